#include "fix_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "antumbra/layering/scene_spheres.hpp"
#include "antumbra/scene/light_bounds.hpp"
#include "shared/limits.h"

namespace antumbra::editor::detail {

bool FitCheck::fits(std::span<const scene::PointLight> lights, int& needed) {
  layering::gather_light_spheres(lights, shared::kMaxShadowLights, spheres_, scene_index_);
  const auto& a =
      layering_.assign(builder_.build_world_sphere(spheres_), spheres_, options_, nullptr);
  needed = a.layers_needed;
  return a.warnings.empty() && a.layers_needed <= cap();
}

float round_down(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return static_cast<float>(std::floor(v * scale) / scale);
}

float round_nearest(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return static_cast<float>(std::round(v * scale) / scale);
}

std::string metres(float v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", static_cast<double>(v));
  std::string text = buffer;
  while (text.size() > 1 && text.back() == '0' && text[text.size() - 2] != '.') text.pop_back();
  return text;
}

std::string in_quotes(const std::string& name) {
  std::string out;
  out.reserve(name.size() + 2);
  out += '\'';
  out += name;
  out += '\'';
  return out;
}

layering::LightSphere sphere_of(const scene::PointLight& light) {
  // What gather_light_spheres makes of a point or spot light, without its lists: the
  // searches call this thousands of times.
  const scene::LightBound bound = scene::light_bounding_sphere(light);
  layering::LightSphere sphere;
  sphere.position = bound.centre;
  sphere.range = bound.radius;
  return sphere;
}

bool overlap(const layering::LightSphere& a, const layering::LightSphere& b) {
  return glm::distance(a.position, b.position) < a.range + b.range;
}

double conflict_threshold(scene::PointLight light, const layering::LightSphere& u) {
  double lo = 0.0;
  double hi = light.range;
  for (int i = 0; i < 48; ++i) {
    const double mid = 0.5 * (lo + hi);
    light.range = static_cast<float>(mid);
    (overlap(sphere_of(light), u) ? hi : lo) = mid;
  }
  return lo;
}

}  // namespace antumbra::editor::detail
