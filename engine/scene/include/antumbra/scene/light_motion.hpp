#pragma once
// Deterministic motion for repeatable benchmarks and tests, as a function of the frame
// index alone (no clock, no randomness), so frame N looks the same in every run and on
// every device: each moving light circles its base position on a small horizontal path
// with a vertical bob; each dynamic object with a motion (scene key "dynamic") swings
// and turns about where it was loaded.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

struct LightMotion {
  // Lights that move: the first `moving` of the list (all when negative). The first ones,
  // because the shadow atlas gives layers in light order: they are the ones with shadows.
  int moving = -1;
  float radius = 0.5f;         // horizontal radius of the path, metres
  float bob = 0.15f;           // vertical amplitude, metres
  std::uint32_t period = 240;  // frames per turn (4 s at 60 Hz)
};

// Where light `index` is at `frame`, relative to its base position; never longer than
// max(radius, bob) in any axis, so a light placed that far from walls stays clear of them.
glm::vec3 light_path_offset(std::size_t index, std::uint64_t frame, const LightMotion& motion);

// `base` with the moving lights at their positions for `frame` (directional lights,
// which have no position, stay as they are).
std::vector<PointLight> animate_lights(const std::vector<PointLight>& base, std::uint64_t frame,
                                       const LightMotion& motion);

// Puts every dynamic object that has a motion where it is at `frame` (transforms and
// bounds of its meshes, and the scene's bounds); true when some mesh moved.
bool animate_objects(Scene& scene, std::uint64_t frame);

}  // namespace antumbra::scene
