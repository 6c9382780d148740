#pragma once
// What the one-light and the several-light fix searches share (fix_suggestion.cpp,
// multi_light_fix.cpp): the verification by the layering's own colouring, the values an
// artist would type, and the geometry of one light's conflict.

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor::detail {

// Keeps a tested value off the exact touching distance, where rounding decides.
inline constexpr double kMargin = 1e-4;

// Verifies a candidate layout exactly as a fresh frame of the pass would colour it.
class FitCheck {
 public:
  explicit FitCheck(const layering::LayeringOptions& options) : options_(options) {}
  [[nodiscard]] int cap() const { return std::clamp(options_.max_layers, 1, layering::kMaxLayers); }
  [[nodiscard]] const layering::LayeringOptions& options() const { return options_; }
  // A fresh frame's colouring (no history) of these lights fits the cap: nothing
  // overflows and the uncapped colouring needs no more than the cap.
  bool fits(std::span<const scene::PointLight> lights, int& needed);

 private:
  layering::LayeringOptions options_;
  layering::GraphBuilder builder_;
  layering::Layering layering_;
  std::vector<layering::LightSphere> spheres_;
  std::vector<std::uint32_t> scene_index_;
};

// Values an artist would type: rounded to `decimals`, as the parser will read them back.
[[nodiscard]] float round_down(double v, int decimals);
[[nodiscard]] float round_nearest(double v, int decimals);
// "4.2", "4.23", "6.0": two decimals at most, one at least.
[[nodiscard]] std::string metres(float v);
[[nodiscard]] std::string in_quotes(const std::string& name);

// The sphere the pass colours for `light` (the conflict test of the world-sphere graph).
[[nodiscard]] layering::LightSphere sphere_of(const scene::PointLight& light);
[[nodiscard]] bool overlap(const layering::LightSphere& a, const layering::LightSphere& b);
// The range below which `light` stops conflicting with sphere u (bisection: a light's
// sphere only grows with its range, so the conflict is monotone in it).
[[nodiscard]] double conflict_threshold(scene::PointLight light, const layering::LightSphere& u);

// On the ground plane, away from each neighbour of v that `counts` and from all of them
// together: the directions both searches try moving a light in.
template <class Neighbours, class Position, class Counts>
std::vector<glm::vec3> away_on_ground(const Neighbours& neighbours, Position position,
                                      std::uint32_t v, Counts counts) {
  std::vector<glm::vec3> directions;
  glm::vec3 sum(0.0f);
  for (std::uint32_t u : neighbours) {
    if (!counts(u)) continue;
    glm::vec3 d = position(v) - position(u);
    d.y = 0.0f;
    if (glm::length(d) < 1e-6f) continue;
    directions.push_back(glm::normalize(d));
    sum += directions.back();
  }
  if (glm::length(sum) > 1e-6f) directions.push_back(glm::normalize(sum));
  return directions;
}

}  // namespace antumbra::editor::detail
