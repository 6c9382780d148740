#include "dirty_pages.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pages.h"

namespace antumbra::passes {

std::uint32_t PageRect::pages() const {
  if (empty()) return 0u;
  const glm::uvec2 side = last - first + 1u;
  return side.x * side.y;
}

void PageRect::mark(std::uint32_t pages_x, std::vector<std::uint32_t>& bits) const {
  for (std::uint32_t y = first.y; y <= last.y && !empty(); ++y) {
    for (std::uint32_t x = first.x; x <= last.x; ++x) {
      const std::uint32_t k = y * pages_x + x;
      if (k / 32u < bits.size()) bits[k / 32u] |= 1u << (k % 32u);
    }
  }
}

PageRect box_pages(const glm::mat4& view_proj, std::uint32_t size, const scene::Aabb& box) {
  if (box.empty() || size == 0u) return {};
  const std::uint32_t pages = (size + shared::kPageSize - 1u) >> shared::kPageShift;
  const PageRect whole{glm::uvec2(0u), glm::uvec2(pages - 1u)};
  glm::vec2 low(std::numeric_limits<float>::max());
  glm::vec2 high(std::numeric_limits<float>::lowest());
  float nearest = std::numeric_limits<float>::max();
  std::uint32_t behind = 0;
  for (std::uint32_t i = 0; i < 8u; ++i) {
    const glm::vec3 corner{(i & 1u) != 0u ? box.max.x : box.min.x,
                           (i & 2u) != 0u ? box.max.y : box.min.y,
                           (i & 4u) != 0u ? box.max.z : box.min.z};
    const glm::vec4 clip = view_proj * glm::vec4(corner, 1.0f);
    if (!(clip.w > 1e-6f)) {
      ++behind;
      continue;
    }
    const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    low = glm::min(low, uv);
    high = glm::max(high, uv);
    nearest = std::min(nearest, clip.z / clip.w);
  }
  // Wholly behind the light's plane: nothing the face sees. Across it: its projection is
  // unbounded.
  if (behind == 8u) return {};
  if (behind > 0u) return whole;
  // Beside the face, or wholly beyond its far plane: no texel of it.
  if (high.x < 0.0f || high.y < 0.0f || low.x > 1.0f || low.y > 1.0f || nearest > 1.0f) return {};
  // Texels whose centres the projection may reach, one more each side.
  const float last_texel = static_cast<float>(size - 1u);
  const glm::vec2 first_texel = glm::clamp(glm::floor(low * static_cast<float>(size)) - 1.0f,
                                           glm::vec2(0.0f), glm::vec2(last_texel));
  const glm::vec2 end_texel = glm::clamp(glm::floor(high * static_cast<float>(size)) + 1.0f,
                                         glm::vec2(0.0f), glm::vec2(last_texel));
  return {glm::uvec2(first_texel) >> shared::kPageShift,
          glm::uvec2(end_texel) >> shared::kPageShift};
}

}  // namespace antumbra::passes
