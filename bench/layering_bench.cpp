// Per-frame CPU cost of light layering: conflict graph + capped, temporally stable
// colouring, for the world-sphere and screen-tile criteria. Budget: 1024 lights <= 0.25 ms
// on one core. Layouts keep a mean degree near 8, i.e. a scene that fits a handful of
// layers; denser layouts are the artist's problem (the cap warns).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/layering/layer_assignment.hpp"

namespace antumbra::layering {
namespace {

constexpr float kMeanDegree = 8.0f;

// Lights in a slab (side x side/4 x side), ranges 0.5..1.5, density for kMeanDegree.
std::vector<LightSphere> world_layout(std::size_t count, std::uint32_t seed = 42) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float volume = static_cast<float>(count) * 4.0f / 3.0f * 3.14159f * 8.0f / kMeanDegree;
  const float side = std::cbrt(4.0f * volume);
  std::vector<LightSphere> lights;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 p(unit(rng) * side, unit(rng) * side * 0.25f, unit(rng) * side);
    lights.push_back({i * 2654435761u, "light" + std::to_string(i), p, 0.5f + unit(rng)});
  }
  return lights;
}

// Footprints on a 1920x1080 screen sized for kMeanDegree with 8 px of blur dilation.
std::vector<ScreenRect> screen_layout(std::size_t count, std::uint32_t seed = 42) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float side =
      std::sqrt(kMeanDegree * 1920.0f * 1080.0f / static_cast<float>(count)) / 2.0f - 2.0f * 16.0f;
  std::vector<ScreenRect> rects;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec2 p(unit(rng) * 1920.0f, unit(rng) * 1080.0f);
    const glm::vec2 s = glm::vec2(std::max(side, 4.0f)) * (0.5f + unit(rng));
    rects.push_back({p - 0.5f * s, p + 0.5f * s});
  }
  return rects;
}

const TileParams kTiles{16, 8.0f, {1920, 1080}};

void BM_WorldSphereFrame(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  Layering layering;
  const LayeringOptions options{Order::dsatur, 16, CapPolicy::least_conflict};
  for (auto _ : state) benchmark::DoNotOptimize(layering.update_world_sphere(lights, options));
  state.counters["edges"] = static_cast<double>(layering.graph().edge_count());
  state.counters["layers"] = layering.update_world_sphere(lights, options).layers_used;
}
BENCHMARK(BM_WorldSphereFrame)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMicrosecond);

void BM_WorldSphereFrameNoHistory(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  GraphBuilder builder;
  Layering layering;
  for (auto _ : state) {
    const ConflictGraph& graph = builder.build_world_sphere(lights);
    benchmark::DoNotOptimize(layering.assign(graph, lights, {Order::dsatur, 16}, nullptr));
  }
}
BENCHMARK(BM_WorldSphereFrameNoHistory)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMicrosecond);

void BM_ScreenTileFrame(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto lights = world_layout(n);
  const auto rects = screen_layout(n);
  Layering layering;
  const LayeringOptions options{Order::dsatur, 16, CapPolicy::least_conflict};
  for (auto _ : state)
    benchmark::DoNotOptimize(layering.update_screen_tile(lights, rects, kTiles, options));
  state.counters["edges"] = static_cast<double>(layering.graph().edge_count());
  state.counters["layers"] =
      layering.update_screen_tile(lights, rects, kTiles, options).layers_used;
}
BENCHMARK(BM_ScreenTileFrame)->Arg(16)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMicrosecond);

// Every light circles its place (radius 0.25, a quarter of a mean range, 32 frames a turn):
// the graph is rebuilt from moved spheres every frame and some edges come and go, so the
// history helps less than with the static layouts above.
constexpr int kMovingFrames = 32;

std::vector<std::vector<LightSphere>> moving_world_frames(std::size_t count) {
  const auto base = world_layout(count);
  std::vector<std::vector<LightSphere>> frames(kMovingFrames, base);
  for (int f = 0; f < kMovingFrames; ++f) {
    for (std::size_t i = 0; i < count; ++i) {
      const float a =
          6.2831853f * (static_cast<float>(f) / kMovingFrames + static_cast<float>(i % 7) / 7.0f);
      frames[f][i].position +=
          0.25f * glm::vec3(std::cos(a), 0.3f * std::sin(2.0f * a), std::sin(a));
    }
  }
  return frames;
}

void BM_WorldSphereFrameMoving(benchmark::State& state) {
  const auto frames = moving_world_frames(static_cast<std::size_t>(state.range(0)));
  Layering layering;
  const LayeringOptions options{Order::dsatur, 16, CapPolicy::least_conflict};
  std::size_t f = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(layering.update_world_sphere(frames[f++ % kMovingFrames], options));
}
BENCHMARK(BM_WorldSphereFrameMoving)->Arg(1024)->Unit(benchmark::kMicrosecond);

// Footprints circling 12 px, 32 frames a turn.
std::vector<std::vector<ScreenRect>> moving_screen_frames(std::size_t count) {
  const auto base = screen_layout(count);
  std::vector<std::vector<ScreenRect>> frames(kMovingFrames, base);
  for (int f = 0; f < kMovingFrames; ++f) {
    for (std::size_t i = 0; i < count; ++i) {
      const float a =
          6.2831853f * (static_cast<float>(f) / kMovingFrames + static_cast<float>(i % 7) / 7.0f);
      const glm::vec2 shift = 12.0f * glm::vec2(std::cos(a), std::sin(a));
      frames[f][i] = {base[i].min + shift, base[i].max + shift};
    }
  }
  return frames;
}

void BM_ScreenTileFrameMoving(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto lights = world_layout(n);
  const auto frames = moving_screen_frames(n);
  Layering layering;
  const LayeringOptions options{Order::dsatur, 16, CapPolicy::least_conflict};
  std::size_t f = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        layering.update_screen_tile(lights, frames[f++ % kMovingFrames], kTiles, options));
  }
}
BENCHMARK(BM_ScreenTileFrameMoving)->Arg(1024)->Unit(benchmark::kMicrosecond);

// Over the cap (needs ~9 layers, cap 4): capped run, fresh retry, uncapped count, warnings.
void BM_WorldSphereFrameOverCap(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  Layering layering;
  const LayeringOptions options{Order::dsatur, 4, static_cast<CapPolicy>(state.range(1))};
  for (auto _ : state) benchmark::DoNotOptimize(layering.update_world_sphere(lights, options));
  state.SetLabel(std::string(to_string(options.policy)));
  state.counters["overflow"] =
      static_cast<double>(layering.update_world_sphere(lights, options).warnings[0].lights.size());
}
BENCHMARK(BM_WorldSphereFrameOverCap)
    ->Args({1024, 0})
    ->Args({1024, 1})
    ->Unit(benchmark::kMicrosecond);

// Stage breakdown at 1024 lights.
void BM_WorldSphereGraphOnly(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  GraphBuilder builder;
  for (auto _ : state) benchmark::DoNotOptimize(builder.build_world_sphere(lights));
}
BENCHMARK(BM_WorldSphereGraphOnly)->Arg(1024)->Unit(benchmark::kMicrosecond);

void BM_WorldSphereGraphBruteForce(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(build_world_sphere_graph_brute_force(lights));
}
BENCHMARK(BM_WorldSphereGraphBruteForce)->Arg(1024)->Unit(benchmark::kMicrosecond);

// The same graphs from moving lights: a new input each iteration, as in a real frame, so
// the branch predictor cannot learn one input's pattern (the static rows above flatter it).
void BM_WorldSphereGraphOnlyMoving(benchmark::State& state) {
  const auto frames = moving_world_frames(static_cast<std::size_t>(state.range(0)));
  GraphBuilder builder;
  std::size_t f = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(builder.build_world_sphere(frames[f++ % kMovingFrames]));
}
BENCHMARK(BM_WorldSphereGraphOnlyMoving)->Arg(1024)->Unit(benchmark::kMicrosecond);

void BM_ScreenTileGraphOnly(benchmark::State& state) {
  const auto rects = screen_layout(static_cast<std::size_t>(state.range(0)));
  GraphBuilder builder;
  for (auto _ : state) benchmark::DoNotOptimize(builder.build_screen_tile(rects, kTiles));
}
BENCHMARK(BM_ScreenTileGraphOnly)->Arg(1024)->Unit(benchmark::kMicrosecond);

void BM_ScreenTileGraphOnlyMoving(benchmark::State& state) {
  const auto frames = moving_screen_frames(static_cast<std::size_t>(state.range(0)));
  GraphBuilder builder;
  std::size_t f = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(builder.build_screen_tile(frames[f++ % kMovingFrames], kTiles));
}
BENCHMARK(BM_ScreenTileGraphOnlyMoving)->Arg(1024)->Unit(benchmark::kMicrosecond);

void BM_Colour(benchmark::State& state) {
  const auto order = static_cast<Order>(state.range(0));
  const auto lights = world_layout(1024);
  const ConflictGraph graph = build_world_sphere_graph(lights);
  Colourer colourer;
  std::vector<int> colours(lights.size());
  for (auto _ : state) {
    std::fill(colours.begin(), colours.end(), kUncoloured);
    benchmark::DoNotOptimize(colourer.colour(graph, order, colours));
  }
  state.SetLabel(std::string(to_string(order)));
  state.counters["layers"] = colour_count(colours);
}
BENCHMARK(BM_Colour)->DenseRange(0, 4)->Unit(benchmark::kMicrosecond);

void BM_ProjectSpheres(benchmark::State& state) {
  const auto lights = world_layout(static_cast<std::size_t>(state.range(0)));
  const glm::mat4 view =
      glm::lookAtRH(glm::vec3(0, 30, -20), glm::vec3(40, 0, 40), glm::vec3(0, 1, 0));
  const glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 500.0f);
  std::vector<ScreenRect> rects(lights.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < lights.size(); ++i)
      rects[i] =
          project_sphere_rect(lights[i].position, lights[i].range, view, proj, kTiles.viewport)
              .value_or(ScreenRect{});
    benchmark::DoNotOptimize(rects.data());
  }
}
BENCHMARK(BM_ProjectSpheres)->Arg(1024)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace antumbra::layering
