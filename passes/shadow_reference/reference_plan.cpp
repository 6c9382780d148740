#include "reference_plan.hpp"

#include <algorithm>
#include <cmath>

#include "point_shadow_atlas/shadow_faces.hpp"

namespace antumbra::passes::reference {

std::vector<glm::vec3> fibonacci_sphere(std::uint32_t count) {
  std::vector<glm::vec3> points;
  points.reserve(count);
  // Golden angle in double so that large counts do not drift between platforms.
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (std::uint32_t i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / static_cast<double>(count);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * static_cast<double>(i);
    points.emplace_back(static_cast<float>(r * std::cos(phi)), static_cast<float>(z),
                        static_cast<float>(r * std::sin(phi)));
  }
  return points;
}

std::vector<std::uint32_t> triangles_near(const std::vector<glm::vec3>& positions,
                                          const std::vector<std::uint32_t>& indices,
                                          const glm::vec3& centre, float radius) {
  std::vector<std::uint32_t> out;
  const float r2 = radius * radius;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = positions[indices[t]];
    const glm::vec3& b = positions[indices[t + 1]];
    const glm::vec3& c = positions[indices[t + 2]];
    const glm::vec3 lo = glm::min(a, glm::min(b, c));
    const glm::vec3 hi = glm::max(a, glm::max(b, c));
    const glm::vec3 d = glm::clamp(centre, lo, hi) - centre;
    if (glm::dot(d, d) <= r2) out.insert(out.end(), {indices[t], indices[t + 1], indices[t + 2]});
  }
  return out;
}

ReferencePlan build_plan(const scene::Scene& scene, const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices,
                         const glm::mat4& camera_view_proj, const PlanSettings& settings) {
  ReferencePlan plan;
  plan.samples = std::max<std::uint32_t>(settings.samples, 1);
  plan.lights_per_batch = std::max<std::uint32_t>(settings.lights_per_batch, 1);
  const auto directions = fibonacci_sphere(plan.samples);
  const auto frustum = shadow_faces::camera_frustum(camera_view_proj);
  const auto light_count = static_cast<std::uint32_t>(scene.lights.size());

  plan.points.resize(std::size_t{light_count} * plan.samples);
  plan.index_first.resize(light_count, 0);
  plan.index_count.resize(light_count, 0);
  for (std::uint32_t l = 0; l < light_count; ++l) {
    const auto& light = scene.lights[l];
    // Faces reach the receivers' whole lit sphere from any point of the light.
    const float far = light.range + light.size;
    // Directional lights have no sphere to sample: unshadowed (the pass reports it).
    const bool shadows =
        light.casts_shadows && light.range > 0.0f && light.type != scene::LightType::directional;
    for (std::uint32_t k = 0; k < plan.samples; ++k) {
      const glm::vec3 p = light.position + directions[k] * light.size;
      plan.points[std::size_t{l} * plan.samples + k].position_far = {p, shadows ? far : -1.0f};
    }
    if (!shadows) continue;
    const auto tris = triangles_near(positions, indices, light.position, far);
    plan.index_first[l] = static_cast<std::uint32_t>(plan.indices.size());
    plan.index_count[l] = static_cast<std::uint32_t>(tris.size());
    plan.indices.insert(plan.indices.end(), tris.begin(), tris.end());
  }

  for (std::uint32_t first = 0; first < light_count; first += plan.lights_per_batch) {
    Batch batch;
    batch.first_light = first;
    batch.light_count = std::min(plan.lights_per_batch, light_count - first);
    for (std::uint32_t k = 0; k < plan.samples; ++k) {
      for (std::uint32_t slot = 0; slot < batch.light_count; ++slot) {
        const std::uint32_t l = first + slot;
        if (plan.index_count[l] == 0) continue;
        const glm::vec4 pf = plan.points[std::size_t{l} * plan.samples + k].position_far;
        const std::uint32_t mask =
            settings.cull_faces ? shadow_faces::visible_faces(frustum, glm::vec3(pf), pf.w) : 0x3Fu;
        // Consecutive visible faces share one instanced draw.
        for (std::uint32_t f = 0; f < shadow_faces::kFaceCount;) {
          if ((mask & (1u << f)) == 0) {
            ++f;
            continue;
          }
          FaceRun run{k, slot, f, 0};
          while (f < shadow_faces::kFaceCount && (mask & (1u << f)) != 0) {
            ++run.face_count;
            ++f;
          }
          batch.runs.push_back(run);
        }
      }
    }
    plan.batches.push_back(std::move(batch));
  }
  return plan;
}

}  // namespace antumbra::passes::reference
