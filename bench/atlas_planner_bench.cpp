// The shadow atlas planner's CPU time per frame (passes/point_shadow_atlas/atlas_planner.hpp;
// docs/technique.md, "Page pool"): the atrium's 16 lights on a page pool whose graph holds
// `records` face records (96 as the test graphs, 6144 as page-pool.json, 24576 for 4096
// lights), every light moving. The records no light owns should cost next to nothing.
#include <cstdint>
#include <string>

#include <benchmark/benchmark.h>

#include "antumbra/scene/scene_file.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

namespace {

using antumbra::passes::AtlasPlanner;
using antumbra::passes::AtlasSettings;

antumbra::scene::Scene atrium() {
  auto loaded = antumbra::scene::load_scene_file(std::string(ANTUMBRA_SOURCE_DIR) +
                                                 "/data/scenes/atrium.json");
  if (!loaded.ok()) return {};
  return std::move(loaded.value());
}

void BM_PlanPagedFrame(benchmark::State& state) {
  antumbra::scene::Scene scene = atrium();
  if (scene.lights.empty()) {
    state.SkipWithError("data/scenes/atrium.json did not load");
    return;
  }
  AtlasSettings settings;
  settings.layers = 32;
  settings.face_size = 1024;
  settings.records = static_cast<std::uint32_t>(state.range(0));
  settings.gpu_decides = true;
  settings.page_pool = true;
  const glm::mat4 camera = scene.camera.view_projection(16.0f / 9.0f);
  AtlasPlanner planner;
  std::uint32_t frame = 0;
  for (auto _ : state) {
    for (auto& light : scene.lights) light.position.x += (frame % 2 == 0 ? 0.01f : -0.01f);
    benchmark::DoNotOptimize(&planner.plan(scene, camera, 1, frame++, settings));
  }
  state.counters["records"] = static_cast<double>(settings.records);
}
BENCHMARK(BM_PlanPagedFrame)->Arg(96)->Arg(6144)->Arg(24576)->Unit(benchmark::kMicrosecond);

}  // namespace
