#pragma once
// Named benchmark scenarios: technique x kernel x resolution x light count, laid out
// like the seed's Table 1 (techniques x kernels x 720p/1080p, 16 lights) and Table 2
// (1..16 lights), extended to 64, 256 and 1024 lights, plus the "moving" table (lights
// on deterministic paths, light_motion.hpp), at a scale that shrinks the screen and the
// shadow atlas faces alike (lavapipe). Plain data: tested without a device.

#include <string>
#include <vector>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::app {

struct ParamOverride {
  std::string pass_type;  // applies to every pass of this type
  std::string param;
  base::Json value;
};

struct Scenario {
  std::string name;       // e.g. "table1/pcss-11/1080p"; the scaled height, e.g. "270p"
  std::string table;      // "table1", "table2", "lights", "moving"
  std::string technique;  // e.g. "pcss"
  std::string graph;      // file name under data/graphs/
  int kernel = 0;         // 0 when the technique has none
  unsigned width = 0;     // the rendered size, scale applied
  unsigned height = 0;
  unsigned face = 0;  // shadow atlas face size in texels, scale applied
  int lights = 16;
  std::vector<ParamOverride> overrides;  // per variant (kernel, cache, later the rasteriser)
  bool shadow_cache = false;  // static shadow caching (off: every face re-rendered each frame)
  std::string scene = "atrium.json";  // file name under data/scenes/
  int moving = 0;                     // lights that move each frame: the first ones
  // point-shadow-atlas's rasterizer ("hardware" or "compute"; the moving table has both).
  std::string rasterizer = "hardware";
  // The "penumbra" table: every light's radius in metres (0: the scene's own).
  float light_size = 0.0f;
  // The "pages" table: the atlas is a page pool of this many layers (point-shadow-atlas's
  // pagePool, its tables bound to every reader of the atlas); 0: faces in squares.
  std::uint32_t pool_layers = 0;
};

// The penumbra table's light radii (metres): the seed's claim is that the screen-space
// soft-shadow stage costs the same whatever the penumbra's size.
inline constexpr float kPenumbraLightSizes[] = {0.05f, 0.1f, 0.25f, 0.5f, 1.0f};

// The lights of the moving table and, for 1024, the district scene's 64 moving lights
// (issue 12's target: 1024 lights, 64 moving each frame, >= 1 M triangles).
inline constexpr int kDistrictLights = 1024;
inline constexpr int kDistrictMovingLights = 64;
inline constexpr const char* kDistrictScene = "district.json";
// The "sun" table's scene: a sun and four lamps (docs/technique.md 3, cascades).
inline constexpr const char* kSunScene = "courtyard-sun.json";
inline constexpr int kSunSceneLights = 5;
// The "dynamic" table's scene: the atrium with moving carts and a ball.
inline constexpr const char* kDynamicScene = "atrium-dynamic.json";
// The "many" table's 4096-light scene: 16 x 16 atria (issue 32: every light shadowed).
inline constexpr const char* kCityScene = "city.json";
inline constexpr int kCityLights = 4096;
// The "materials" table's textured scene: the atrium with alpha-tested lattice screens.
inline constexpr const char* kCutoutScene = "atrium-cutouts.json";

// How the district's rows (the moving table's 1024 lights) differ from the others':
// their size is `scale` (builtin_scenarios') times `scale`, `lights` of the district's
// lights are kept (with_light_count lays them out over the same area; fewer than 1024:
// the names say "<lights>l-district") and `moving` of them move. `bench --quick` shrinks
// all three.
struct DistrictRows {
  double scale = 1.0;
  int lights = kDistrictLights;
  int moving = kDistrictMovingLights;
};

// Every built-in scenario, in a stable order, with screen and atlas faces scaled by
// `scale` (names carry the scaled height, so two scales never share a name).
std::vector<Scenario> builtin_scenarios(double scale = 1.0, const DistrictRows& district = {});

// `bench --quick`: the preset for CPU devices (lavapipe), measured to finish the moving
// table (`--scenario moving/`, 48 rows) within 10 minutes on 2 cores (docs/measuring.md:
// 8 min 12 s). 3 timed frames after 1 warm-up frame (the first frame fills the shadow
// cache), a quarter of the size, and the district's rows at half of that with 256 lights,
// 16 of them moving: on lavapipe a hardware row's warm-up frame draws the district's
// 1.3 M triangles into every face of its shadowed lights; with all 1024 lights the table
// took 9 min 51 s.
inline constexpr int kQuickFrames = 3;
inline constexpr int kQuickWarmup = 1;
inline constexpr double kQuickScale = 0.25;
inline constexpr DistrictRows kQuickDistrict{0.5, 256, 16};

// The atlas face for `lights` lights at `scale`: 1024 texels up to 64 lights and 512
// beyond, scaled, rounded to a multiple of 16 (maps derived from the atlas divide it by
// 2, 4, 8 or 16) and at least 16.
unsigned shadow_face_size(int lights, double scale);

// Scenarios whose name contains any of `filters` (all when empty).
std::vector<Scenario> select_scenarios(const std::vector<Scenario>& all,
                                       const std::vector<std::string>& filters);

// Applies the overrides to a parsed graph; returns the names of overrides that matched
// no pass (a scenario typo must not silently measure the default).
std::vector<std::string> apply_overrides(fg::GraphDesc& graph,
                                         const std::vector<ParamOverride>& overrides);

// Sizes the shadow atlas (and its colour twin, min-filtered and moment maps, and shadowData)
// of a graph for `lights` shadow-casting lights: 6 layers per light up to the
// device-independent limit of 2046 layers, faces of `face` texels (a derived map keeps
// its factor of the graph's atlas size), and a face record for every light's faces (past
// 341 lights their faces share layers at smaller sizes: every light casts its shadow).
void fit_shadow_resources(fg::GraphDesc& graph, int lights, unsigned face);

// The atlas format the scenario's rasterizer writes fastest: r32f for "compute" (its
// resolve shader's storage image; a d32f atlas would be filled by copies), as the graph
// says otherwise.
void fit_atlas_format(fg::GraphDesc& graph, const std::string& rasterizer);

// With `pool_layers` > 0: the atlas (and its colour twin) that many layers deep, made a
// page pool whose tables (a `pageTables` buffer for every face record shadowData holds)
// the atlas pass writes and every pass that reads the atlas binds.
void fit_page_pool(fg::GraphDesc& graph, std::uint32_t pool_layers);

// How the moving table's lights move (scene::animate_lights), for `scenario.moving`
// lights; frame 0 is the first warm-up frame of each scenario.
scene::LightMotion bench_motion(const Scenario& scenario);

// The scene with its lights replaced by `count` lights in a deterministic layout that
// covers the same area (16 keeps the scene's own lights). Ranges shrink as the count
// grows so that the lit area per light stays comparable.
// Every light of `scene` with radius `size` (metres); 0 leaves them as they are.
void set_light_size(scene::Scene& scene, float size);

scene::Scene with_light_count(const scene::Scene& base, int count);

}  // namespace antumbra::app
