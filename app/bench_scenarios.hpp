#pragma once
// Named benchmark scenarios: technique x kernel x resolution x light count, laid out
// like the seed's Table 1 (techniques x kernels x 720p/1080p, 16 lights) and Table 2
// (1..16 lights), extended to 64, 256 and 1024 lights. Plain data: tested without a
// device.

#include <string>
#include <vector>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::app {

struct ParamOverride {
  std::string pass_type;  // applies to every pass of this type
  std::string param;
  fg::Json value;
};

struct Scenario {
  std::string name;       // e.g. "table1/pcss-11/1080p"
  std::string table;      // "table1", "table2", "lights"
  std::string technique;  // e.g. "pcss"
  std::string graph;      // file name under data/graphs/
  int kernel = 0;         // 0 when the technique has none
  unsigned width = 0;
  unsigned height = 0;
  int lights = 16;
  std::vector<ParamOverride> overrides;
  bool shadow_cache = false;  // static shadow caching (off: every face re-rendered each frame)
};

// Every built-in scenario, in a stable order.
std::vector<Scenario> builtin_scenarios();

// Scenarios whose name contains any of `filters` (all when empty).
std::vector<Scenario> select_scenarios(const std::vector<Scenario>& all,
                                       const std::vector<std::string>& filters);

// Applies the overrides to a parsed graph; returns the names of overrides that matched
// no pass (a scenario typo must not silently measure the default).
std::vector<std::string> apply_overrides(fg::GraphDesc& graph,
                                         const std::vector<ParamOverride>& overrides);

// Sizes the shadow atlas (and its colour twin and shadowData buffer) of a graph for
// `lights` shadow-casting lights: 6 layers per light up to the device-independent
// limit of 2046 layers, faces of 1024 texels up to 64 lights and 512 beyond.
void fit_shadow_resources(fg::GraphDesc& graph, int lights);

// The scene with its lights replaced by `count` lights in a deterministic layout that
// covers the same area (16 keeps the scene's own lights). Ranges shrink as the count
// grows so that the lit area per light stays comparable.
scene::Scene with_light_count(const scene::Scene& base, int count);

}  // namespace antumbra::app
