#pragma once
// The pages of a face a moved dynamic mesh may have drawn into (docs/technique.md,
// "Static and dynamic casters", per-page invalidation): the rectangle of pages its
// bounds cover in the face, which the GPU's face decision redraws instead of the whole
// face (face_decision_interface.h, FaceRequest::dirty). Vulkan-free, unit-tested.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::passes {

// A rectangle of pages, inclusive; empty while first > last.
struct PageRect {
  glm::uvec2 first{1u};
  glm::uvec2 last{0u};

  [[nodiscard]] bool empty() const { return first.x > last.x || first.y > last.y; }
  [[nodiscard]] std::uint32_t pages() const;
  // Sets its pages' bits in `bits` (bit k: page k of a face `pages_x` pages wide, row-major;
  // as many uints as that face's pages take).
  void mark(std::uint32_t pages_x, std::vector<std::uint32_t>& bits) const;
  bool operator==(const PageRect&) const = default;
};

// The pages of a `size`-texel face (world -> face clip `view_proj`, shadow_faces.hpp's
// conventions) whose texels a caster inside `box` may cover: the rectangle around the
// box's eight corners as the face sees them, a texel wider on each side (the
// rasterisers' inclusive edges and rounding). Every page when the box lies across the
// light's plane (no bounded projection); none when it is behind that plane, beside the
// face or beyond its far plane.
PageRect box_pages(const glm::mat4& view_proj, std::uint32_t size, const scene::Aabb& box);

}  // namespace antumbra::passes
