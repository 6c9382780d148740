#pragma once
// Per-light face resolution from the light's footprint on screen (docs/technique.md,
// "Per-light resolution"), Vulkan-free: a light whose range sphere covers r pixels of
// the screen (projected radius) gets faces of about r * scale texels, rounded up to a
// power of two between the minimum and the atlas's face size, so a face texel is about
// one screen pixel at half the light's range. A band of a quarter octave around each
// step keeps the choice from flickering while the camera moves.

#include <cstdint>

#include <glm/glm.hpp>

namespace antumbra::passes {

struct ResolutionSettings {
  float scale = 1.0f;              // texels per projected pixel of the light's radius
  std::uint32_t minimum = 64;      // a power of two
  std::uint32_t maximum = 1024;    // the atlas's face size (any size)
  float viewport_height = 720.0f;  // pixels
  float tan_half_fov = 0.57735f;   // the camera's vertical half angle
  glm::vec3 camera{0.0f};
  float hysteresis = 0.25f;  // octaves
};

// The screen radius in pixels of a sphere (whole screen height when the camera is inside).
float projected_radius(const glm::vec3& centre, float radius, const ResolutionSettings& s);

// The face size for a light wanting `wanted` texels, given last frame's choice
// (`previous`, 0 for none): a power of two in [minimum, maximum], or maximum.
std::uint32_t choose_resolution(float wanted, std::uint32_t previous, const ResolutionSettings& s);

}  // namespace antumbra::passes
