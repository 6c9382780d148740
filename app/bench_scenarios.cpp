#include "bench_scenarios.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace antumbra::app {
namespace {

struct Technique {
  const char* name;
  const char* graph;
  const char* kernel_pass;   // pass type that takes the kernel, "" for none
  std::vector<int> kernels;  // empty: one scenario without a kernel
};

const std::vector<Technique>& techniques() {
  static const std::vector<Technique> kTechniques = {
      {"lighting-only", "lighting.json", "", {}},
      {"hard", "hard.json", "", {}},
      {"pcf", "pcf.json", "shadow-pcf", {5, 11, 23}},
      {"pcss", "pcss.json", "shadow-pcss", {5, 11, 23}},
      {"ssss-blocker", "layered-ssss-blocker.json", "anisotropic-blur", {5, 11, 23}},
      {"ssss", "layered-ssss.json", "anisotropic-blur", {5, 11, 23}},
      {"ssss-min", "layered-ssss-min.json", "anisotropic-blur", {5, 11, 23}},
      {"vsm", "vsm.json", "", {}},
      {"evsm2", "evsm2.json", "", {}},
      {"evsm4", "evsm4.json", "", {}},
      {"msm", "msm.json", "", {}},
      {"vssm", "vssm.json", "", {}},
      {"sdf", "sdf.json", "", {}},
      {"penumbra-wedges", "penumbra-wedges.json", "", {}},
  };
  return kTechniques;
}

unsigned scaled(unsigned size, double scale) {
  return std::max(16u, static_cast<unsigned>(std::lround(size * scale)));
}

Scenario make(const std::string& table, const Technique& t, int kernel, unsigned height, int lights,
              double scale) {
  Scenario s;
  s.table = table;
  s.technique = t.name;
  s.graph = t.graph;
  s.kernel = kernel;
  s.height = scaled(height, scale);
  s.width = scaled(height * 16 / 9, scale);
  s.face = shadow_face_size(lights, scale);
  s.lights = lights;
  s.name = table + "/" + t.name + (kernel > 0 ? "-" + std::to_string(kernel) : "") + "/" +
           std::to_string(s.height) + "p" +
           (table == "table1" ? "" : "/" + std::to_string(lights) + "l");
  if (kernel > 0) s.overrides.push_back({t.kernel_pass, "kernel", std::to_string(kernel)});
  // Tables 1 and 2 re-render every shadow face every frame, as the seed's dynamic-light
  // measurements did; the many-light table measures the cached steady state. The moving
  // and many tables cache too: what stands still stays cached, a moving light's faces change
  // their matrices and so redraw themselves.
  s.shadow_cache = table == "lights" || table == "moving" || table == "many" || table == "pages" ||
                   table == "materials" || table == "penumbra" || table == "dynamic";
  // No shadow atlas to pin in the unshadowed and the distance-field graphs.
  if (std::string(t.graph) != "lighting.json" && std::string(t.graph) != "sdf.json") {
    s.overrides.push_back({"point-shadow-atlas", "cache", s.shadow_cache});
    // Pinned: "auto" would pick per device and change what a row measures. Compute
    // rows override it.
    s.overrides.push_back({"point-shadow-atlas", "rasterizer", s.rasterizer});
  }
  // The G-buffer pinned likewise; the "/vis" rows set "compute".
  s.overrides.push_back({"gbuffer", "rasterizer", "hardware"});
  return s;
}

const Technique& technique(const std::string& name) {
  const auto& all = techniques();
  return *std::find_if(all.begin(), all.end(), [&](const Technique& t) { return name == t.name; });
}

// Dynamic objects: the atrium's lights stand, carts and a ball move every frame; the
// hardware rasteriser with and without the static cache, and the compute one.
void add_dynamic_table(std::vector<Scenario>& out, double scale) {
  const std::pair<const char*, int> rows[] = {{"hard", 0}, {"pcss", 11}, {"ssss", 11}};
  for (const auto& [name, kernel] : rows) {
    for (const std::string variant : {"hardware", "nocache", "compute"}) {
      Scenario s = make("dynamic", technique(name), kernel, 1080, 16, scale);
      s.scene = kDynamicScene;
      if (variant == "nocache") {
        s.name += "/nocache";
        s.overrides.push_back({"point-shadow-atlas", "staticCache", false});
      } else if (variant == "compute") {
        s.rasterizer = "compute";
        s.name += "/compute";
        s.overrides.push_back({"point-shadow-atlas", "rasterizer", s.rasterizer});
        s.overrides.push_back({"tonemap", "stage", "compute"});
      }
      out.push_back(std::move(s));
    }
  }
}

// The moving rows' rasteriser variants: both shadow rasterisers (the compute rows end in
// "/compute"; they cull faces by receivers), the compute one again with per-light
// resolution ("/compute/screen"), and that again with the compute G-buffer
// ("/compute/screen/vis": no raster pass left).
struct Raster {
  const char* rasterizer;
  const char* resolution;
  bool visibility = false;
};
constexpr Raster kRasters[] = {{"hardware", "fixed"},
                               {"compute", "fixed"},
                               {"compute", "screen"},
                               {"compute", "screen", true}};

void apply_raster(Scenario& s, const Raster& raster) {
  s.rasterizer = raster.rasterizer;
  if (s.rasterizer != "hardware") {
    s.name += "/" + s.rasterizer;
    s.overrides.push_back({"point-shadow-atlas", "rasterizer", s.rasterizer});
    // The rest of the frame off the raster units too: the compute tonemap.
    s.overrides.push_back({"tonemap", "stage", "compute"});
  }
  if (std::string(raster.resolution) != "fixed") {
    s.name += std::string("/") + raster.resolution;
    s.overrides.push_back({"point-shadow-atlas", "resolution", raster.resolution});
  }
  if (raster.visibility) {
    s.name += "/vis";
    for (auto& o : s.overrides) {
      if (o.pass_type == "gbuffer" && o.param == "rasterizer") o.value = "compute";
    }
  }
}

// Moving lights: every light moves in the atrium; 1024 lights are the district's, 64
// of them moving.
void add_moving_table(std::vector<Scenario>& out, double scale, const DistrictRows& rows) {
  struct Variant {
    const char* technique;
    int kernel;
  };
  constexpr Variant kMovingVariants[] = {{"hard", 0}, {"pcss", 11}, {"ssss", 11}};
  for (const int count : {16, 64, 256, kDistrictLights}) {
    const bool district = count == kDistrictLights;
    const int lights = district ? rows.lights : count;
    for (const Variant& v : kMovingVariants) {
      for (const Raster& raster : kRasters) {
        Scenario s = make("moving", technique(v.technique), v.kernel, 1080, lights,
                          district ? scale * rows.scale : scale);
        // A district of fewer lights says so: "256l" alone would read as the atrium's row.
        if (district && lights != kDistrictLights) s.name += "-district";
        s.scene = district ? kDistrictScene : "atrium.json";
        s.moving = district ? std::min(rows.moving, lights) : lights;
        apply_raster(s, raster);
        out.push_back(std::move(s));
      }
    }
  }
}

// Many lights, every one shadowed (packed faces share the atlas's layers): layered SSSS 11
// on the compute rasterisers with per-light resolution, the district with 64 and with all
// of its lights moving and the city (4096 lights) with a quarter moving. `bench --quick`
// keeps the district's share of the lights (DistrictRows) for both scenes.
void add_many_table(std::vector<Scenario>& out, double scale, const DistrictRows& rows) {
  struct Row {
    const char* scene;
    int lights;  // the scene's
    int moving;
  };
  constexpr Row kRows[] = {{kDistrictScene, kDistrictLights, kDistrictMovingLights},
                           {kDistrictScene, kDistrictLights, kDistrictLights},
                           {kCityScene, kCityLights, kCityLights / 4}};
  for (const Row& row : kRows) {
    const int lights = row.lights / kDistrictLights * rows.lights;
    const int moving = std::min(row.moving * rows.lights / kDistrictLights, lights);
    Scenario s = make("many", technique("ssss"), 11, 1080, lights, scale * rows.scale);
    // Appended piecewise, not operator+(const char*, string&&): GCC 12 warns falsely.
    s.name += "-";
    s.name += std::to_string(moving);
    s.name += "m";
    s.scene = row.scene;
    s.moving = moving;
    apply_raster(s, kRasters[3]);  // compute, per-light resolution, compute G-buffer
    out.push_back(std::move(s));
  }
}

// Page pool (docs/technique.md, "Page pool"): the many table's rows and the atrium's 16
// moving lights with the atlas a pool of pages that visible pixels need, far fewer layers
// than the squares take: 32 of 1024^2 for the atrium (128 MiB of depth), 512 of 512^2
// for the district and the city (512 MiB); the atrium also with the min-filtered maps and
// with EVSM4's moment maps, both filtered through the tables.
void add_pages_table(std::vector<Scenario>& out, double scale, const DistrictRows& rows) {
  struct Row {
    const char* scene;
    int lights;  // the scene's
    int moving;
    std::uint32_t pool_layers;
  };
  constexpr Row kRows[] = {{"atrium.json", 16, 16, 32},
                           {kDistrictScene, kDistrictLights, kDistrictMovingLights, 512},
                           {kDistrictScene, kDistrictLights, kDistrictLights, 512},
                           {kCityScene, kCityLights, kCityLights / 4, 512}};
  // The atrium also with the seed's min-filtered maps, EVSM4 and VSSM, through the tables.
  struct Variant {
    const Row* row;
    const char* technique;
  };
  std::vector<Variant> variants;
  for (const Row& row : kRows) variants.push_back({&row, "ssss"});
  variants.insert(variants.begin() + 1, {&kRows[0], "ssss-min"});
  variants.insert(variants.begin() + 2, {&kRows[0], "evsm4"});
  variants.insert(variants.begin() + 3, {&kRows[0], "vssm"});
  for (const auto& [row_of, name] : variants) {
    const Row& row = *row_of;
    const bool many = row.lights >= kDistrictLights;
    const int lights = many ? row.lights / kDistrictLights * rows.lights : row.lights;
    const int moving =
        many ? std::min(row.moving * rows.lights / kDistrictLights, lights) : row.moving;
    const Technique& t = technique(name);
    const int kernel = t.kernels.empty() ? 0 : 11;
    Scenario s = make("pages", t, kernel, 1080, lights, many ? scale * rows.scale : scale);
    s.name += "-";
    s.name += std::to_string(moving);
    s.name += "m";
    s.scene = row.scene;
    s.moving = moving;
    s.pool_layers = row.pool_layers;
    // The pool's layers are cut into whole 128^2 pages (interface/shared/page_tables.h):
    // --quick's faces are rounded up to them.
    s.face = std::max(128u, s.face / 128 * 128);
    apply_raster(s, kRasters[3]);  // compute, per-light resolution, compute G-buffer
    s.name += "/pool";
    s.name += std::to_string(row.pool_layers);
    out.push_back(std::move(s));
  }
}

// Materials: the atrium against the atrium with textured, alpha-tested screens
// (kCutoutScene), layered SSSS 11 under 16 moving lights on every rasteriser variant, so
// that what textures and cut-outs cost is measured beside a scene without them.
void add_materials_table(std::vector<Scenario>& out, double scale) {
  for (const char* scene : {"atrium.json", kCutoutScene}) {
    for (const Raster& raster : kRasters) {
      Scenario s = make("materials", technique("ssss"), 11, 1080, 16, scale);
      s.scene = scene;
      s.moving = 16;
      const std::string file = scene;
      s.name += "/" + file.substr(0, file.rfind('.'));
      apply_raster(s, raster);
      out.push_back(std::move(s));
    }
  }
}

// The sun: the courtyard (a sun and four lamps, shadows from 0.5 to 70 m away) with one
// map against four PSSM cascades, in the filters that read them. Every face is redrawn
// each frame: the cascades follow the camera, so whenever it moves they are redrawn.
void add_sun_table(std::vector<Scenario>& out, double scale) {
  const std::pair<const char*, int> rows[] = {{"hard", 0},  {"pcf", 5},   {"pcss", 11},
                                              {"ssss", 11}, {"evsm4", 0}, {"vssm", 0}};
  for (const auto& [name, kernel] : rows) {
    for (const int cascades : {1, 4}) {
      Scenario s = make("sun", technique(name), kernel, 1080, kSunSceneLights, scale);
      s.scene = kSunScene;
      s.name += "/c" + std::to_string(cascades);
      s.overrides.push_back({"point-shadow-atlas", "sunCascades", cascades});
      s.overrides.push_back({"point-shadow-atlas", "sunDistance", 80.0});
      out.push_back(std::move(s));
    }
  }
}

}  // namespace

unsigned shadow_face_size(int lights, double scale) {
  const double face = (lights <= 64 ? 1024.0 : 512.0) * scale;
  return std::max(16u, static_cast<unsigned>(std::lround(face / 16.0)) * 16u);
}

std::vector<Scenario> builtin_scenarios(double scale, const DistrictRows& district) {
  std::vector<Scenario> out;
  for (const unsigned height : {720u, 1080u}) {
    for (const auto& t : techniques()) {
      if (t.kernels.empty()) {
        out.push_back(make("table1", t, 0, height, 16, scale));
      } else {
        for (const int k : t.kernels) out.push_back(make("table1", t, k, height, 16, scale));
      }
    }
  }
  // Table 2 compares PCSS 5x5 + 11x11 with layered SSSS 11x11 (blocker search and min
  // filter) at 1080p as lights grow.
  for (const int lights : {1, 4, 8, 12, 16, 64, 256, 1024}) {
    const std::string table = lights <= 16 ? "table2" : "lights";
    for (const char* name : {"pcss", "ssss", "ssss-min"}) {
      out.push_back(make(table, technique(name), 11, 1080, lights, scale));
    }
  }
  add_moving_table(out, scale, district);
  add_many_table(out, scale, district);
  add_pages_table(out, scale, district);
  add_materials_table(out, scale);
  add_dynamic_table(out, scale);
  add_sun_table(out, scale);
  // Penumbra size: PCSS and layered SSSS (blocker search, min filter) as the lights grow
  // from 5 cm to 1 m, shadows
  // cached so that the rows time the soft-shadow stage, not the atlas.
  for (const float size : kPenumbraLightSizes) {
    for (const char* name : {"pcss", "ssss", "ssss-min"}) {
      Scenario s = make("penumbra", technique(name), 11, 1080, 16, scale);
      s.light_size = size;
      char radius[32];
      std::snprintf(radius, sizeof radius, "/r%.2fm", static_cast<double>(size));
      s.name += radius;
      out.push_back(std::move(s));
    }
  }
  return out;
}

void set_light_size(scene::Scene& scene, float size) {
  if (size <= 0.0f) return;
  for (auto& light : scene.lights) {
    if (light.type != scene::LightType::directional) light.size = size;
  }
}

scene::LightMotion bench_motion(const Scenario& scenario) {
  scene::LightMotion motion;
  motion.moving = scenario.moving;
  return motion;
}

std::vector<Scenario> select_scenarios(const std::vector<Scenario>& all,
                                       const std::vector<std::string>& filters) {
  if (filters.empty()) return all;
  std::vector<Scenario> out;
  for (const auto& s : all) {
    for (const auto& f : filters) {
      if (s.name.find(f) != std::string::npos) {
        out.push_back(s);
        break;
      }
    }
  }
  return out;
}

std::vector<std::string> apply_overrides(fg::GraphDesc& graph,
                                         const std::vector<ParamOverride>& overrides) {
  std::vector<std::string> unmatched;
  for (const auto& o : overrides) {
    bool matched = false;
    for (auto& pass : graph.passes) {
      if (pass.type != o.pass_type) continue;
      pass.params[o.param] = o.value;
      matched = true;
    }
    if (!matched) unmatched.push_back(o.pass_type + "." + o.param);
  }
  return unmatched;
}

void fit_shadow_resources(fg::GraphDesc& graph, int lights, unsigned face) {
  constexpr int kMaxLayers = 2046;  // Vulkan guarantees 2048 layers
  const int layers = std::clamp(6 * lights, 6, kMaxLayers);
  // A map derived from the atlas (shadow-min-filter's, shadow-moments', penumbra-wedges')
  // keeps its factor of the face size.
  std::uint32_t atlas_width = 0;
  for (const auto& r : graph.resources) {
    if (r.name == "atlas" && !r.size.relative) atlas_width = r.size.width;
  }
  for (auto& r : graph.resources) {
    if (r.kind == fg::ResourceKind::image && r.layers >= 6 &&
        (r.name == "atlas" || r.name == "shadowColour" || r.name == "minDepth" ||
         r.name == "moments" || r.name == "penumbraMap" || r.name == "peeled")) {
      const bool derived = r.name == "minDepth" || r.name == "moments" || r.name == "penumbraMap" ||
                           r.name == "peeled";
      const std::uint32_t factor = derived && atlas_width > 0 && r.size.width > 0
                                       ? std::max(atlas_width / r.size.width, 1u)
                                       : 1u;
      const std::uint32_t size = std::max(face / factor, 1u);
      r.layers = static_cast<std::uint32_t>(layers);
      r.size.relative = false;
      r.size.width = size;
      r.size.height = size;
    }
    if (r.kind == fg::ResourceKind::buffer && r.name == "shadowData") {
      // shadow_data.hpp: header + 4096 lights (ANTUMBRA_MAX_SHADOW_LIGHTS) + a face record for
      // every light's six faces (at least one per layer): faces smaller than a layer share layers,
      // so every light casts its shadow however few layers there are (docs/technique.md, "Packed
      // faces").
      const std::uint64_t records =
          std::max(6 * static_cast<std::uint64_t>(lights), static_cast<std::uint64_t>(layers));
      // Exactly that many: a spare record beyond the layers would make the hardware
      // rasteriser pack faces (and pay for clip distances) where they never share a layer.
      r.buffer_size = 16 + 64 * 4096 + 80 * records;
    }
  }
}

void fit_atlas_format(fg::GraphDesc& graph, const std::string& rasterizer) {
  if (rasterizer != "compute") return;
  for (auto& r : graph.resources) {
    if (r.name == "atlas" && r.kind == fg::ResourceKind::image) r.format = fg::Format::r32f;
  }
  // Receiver culling: the atlas reads the G-buffer's depth (when the graph has one).
  std::string depth;
  for (const auto& pass : graph.passes) {
    for (const auto& out : pass.outputs) {
      if (pass.type == "gbuffer" && out.port == "depth") depth = out.resource;
    }
  }
  if (depth.empty()) return;
  for (auto& pass : graph.passes) {
    const bool bound =
        std::any_of(pass.inputs.begin(), pass.inputs.end(),
                    [](const fg::PortBindingDesc& in) { return in.port == "depth"; });
    if (pass.type == "point-shadow-atlas" && !bound) {
      pass.inputs.push_back({"depth", depth, pass.pointer + "/in/depth"});
    }
  }
}

void fit_page_pool(fg::GraphDesc& graph, std::uint32_t pool_layers) {
  if (pool_layers == 0) return;
  std::uint64_t records = 0;
  std::uint32_t face = 0;
  for (const auto& r : graph.resources) {
    if (r.name == "atlas") face = r.size.width;
    // fit_shadow_resources' layout: header, 4096 lights, 80-byte face records.
    if (r.name == "shadowData") records = (r.buffer_size - 16 - std::uint64_t{64} * 4096) / 80;
  }
  const std::uint64_t pages_side = (face + 127) / 128;  // interface/shared/page_tables.h
  // Layers on top for the records' fallback tiles (pageFallback: 16 tiles to a page,
  // ANTUMBRA_FALLBACK_TILES_PER_PAGE, after the pool's pages), so `pool_layers` stays the
  // pages faces take, as before the tiles.
  const std::uint64_t per_layer = pages_side * pages_side;
  const std::uint64_t fallback = (records + 15) / 16;
  const auto extra = static_cast<std::uint32_t>((fallback + per_layer - 1) / per_layer);
  for (auto& r : graph.resources) {
    // The derived maps keep the pool's layout (shadow-min-filter, shadow-moments over a
    // paged atlas).
    if (r.name == "atlas" || r.name == "shadowColour" || r.name == "minDepth" ||
        r.name == "moments")
      r.layers = pool_layers + extra;
  }
  fg::ResourceDesc tables;
  tables.name = "pageTables";
  tables.kind = fg::ResourceKind::buffer;
  tables.buffer_size = std::max<std::uint64_t>(records * pages_side * pages_side * 4, 16);
  tables.pointer = "/resources/pageTables";
  graph.resources.push_back(tables);
  for (auto& pass : graph.passes) {
    if (pass.type == "point-shadow-atlas") {
      pass.params["pagePool"] = true;
      pass.outputs.push_back({"pageTables", "pageTables", pass.pointer + "/out/pageTables"});
      continue;
    }
    const bool reads_atlas =
        std::any_of(pass.inputs.begin(), pass.inputs.end(),
                    [](const fg::PortBindingDesc& in) { return in.resource == "atlas"; });
    if (reads_atlas) {
      pass.inputs.push_back({"pageTables", "pageTables", pass.pointer + "/in/pageTables"});
    }
  }
}

scene::Scene with_light_count(const scene::Scene& base, int count) {
  scene::Scene s = base;
  if (count == static_cast<int>(base.lights.size()) || base.lights.empty()) return s;
  // Spread the lights over the box the original lights span, on a near-square grid.
  scene::Aabb area;
  float range = 0.0f;
  for (const auto& l : base.lights) {
    area.expand(l.position);
    range = std::max(range, l.range);
  }
  const glm::vec3 lo = area.min;
  const glm::vec3 span = glm::max(area.max - area.min, glm::vec3(1e-3f));
  const int columns = std::max(
      1, static_cast<int>(std::ceil(std::sqrt(static_cast<float>(count) * span.x / span.z))));
  const int rows = std::max(1, (count + columns - 1) / columns);
  // Keep overlap per light roughly constant: spacing shrinks with sqrt(count).
  const float scale = std::sqrt(static_cast<float>(base.lights.size()) / static_cast<float>(count));
  s.lights.clear();
  for (int i = 0; i < count; ++i) {
    const auto& model = base.lights[static_cast<std::size_t>(i) % base.lights.size()];
    scene::PointLight l = model;
    const int c = i % columns;
    const int r = i / columns;
    const float fx = columns > 1 ? static_cast<float>(c) / static_cast<float>(columns - 1) : 0.5f;
    const float fz = rows > 1 ? static_cast<float>(r) / static_cast<float>(rows - 1) : 0.5f;
    l.position = glm::vec3(lo.x + fx * span.x, model.position.y, lo.z + fz * span.z);
    l.range = std::max(0.5f, range * std::min(1.0f, scale * 1.2f));
    l.name = "bench" + std::to_string(i);
    s.lights.push_back(l);
  }
  return s;
}

}  // namespace antumbra::app
