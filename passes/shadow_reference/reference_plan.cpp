#include "reference_plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/light_faces.hpp"
#include "common/shadow_faces.hpp"

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

std::vector<glm::vec2> fibonacci_disc(std::uint32_t count) {
  std::vector<glm::vec2> points;
  points.reserve(count);
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (std::uint32_t i = 0; i < count; ++i) {
    const double r = std::sqrt((static_cast<double>(i) + 0.5) / static_cast<double>(count));
    const double phi = golden * static_cast<double>(i);
    points.emplace_back(static_cast<float>(r * std::cos(phi)),
                        static_cast<float>(r * std::sin(phi)));
  }
  return points;
}

std::vector<glm::vec3> sun_directions(const glm::vec3& direction, float angular_radius_degrees,
                                      std::uint32_t count) {
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  light_faces::perpendicular_basis(f, s, t);
  const float spread = std::tan(glm::radians(std::clamp(angular_radius_degrees, 0.0f, 45.0f)));
  std::vector<glm::vec3> out;
  out.reserve(count);
  for (const glm::vec2& d : fibonacci_disc(count)) {
    out.push_back(glm::normalize(f + spread * (d.x * s + d.y * t)));
  }
  return out;
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

namespace {

using Polygon = std::vector<glm::vec3>;

// Sutherland-Hodgman: the part of `polygon` where dot(n, p) + d >= 0.
Polygon clip(const Polygon& polygon, const glm::vec3& n, float d) {
  Polygon out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec3& a = polygon[i];
    const glm::vec3& b = polygon[(i + 1) % polygon.size()];
    const float da = glm::dot(n, a) + d;
    const float db = glm::dot(n, b) + d;
    if (da >= 0.0f) out.push_back(a);
    if ((da >= 0.0f) != (db >= 0.0f)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

std::array<glm::vec3, 8> box_corners(const scene::Aabb& box) {
  std::array<glm::vec3, 8> corners;
  for (std::size_t k = 0; k < 8; ++k) {
    corners[k] = {(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                  (k & 4) ? box.max.z : box.min.z};
  }
  return corners;
}

}  // namespace

std::vector<glm::vec3> visible_region(const glm::mat4& camera_view_proj,
                                      const scene::Aabb& bounds) {
  std::vector<glm::vec3> out;
  if (bounds.empty()) return out;
  const auto frustum = shadow_faces::camera_frustum(camera_view_proj);
  const auto& c = frustum.corners;  // index = 4 z + 2 y + x (near/far, bottom/top, left/right)
  const std::array<std::array<int, 4>, 6> faces{
      {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}}};
  for (const auto& face : faces) {
    Polygon polygon{c[face[0]], c[face[1]], c[face[2]], c[face[3]]};
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
      glm::vec3 n(0.0f);
      n[axis] = 1.0f;
      polygon = clip(polygon, n, -bounds.min[axis]);
      if (!polygon.empty()) polygon = clip(polygon, -n, bounds.max[axis]);
    }
    out.insert(out.end(), polygon.begin(), polygon.end());
  }
  for (const glm::vec3& corner : box_corners(bounds)) {
    bool inside = true;
    for (const auto& plane : frustum.planes) inside = inside && plane.distance(corner) >= 0.0f;
    if (inside) out.push_back(corner);
  }
  return out;
}

SunFit fit_sun(const glm::vec3& direction, std::span<const glm::vec3> receivers,
               const scene::Aabb& caster_bounds, float face_size, float margin_texels) {
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  light_faces::perpendicular_basis(f, s, t);
  glm::vec2 lo(std::numeric_limits<float>::max());
  glm::vec2 hi(std::numeric_limits<float>::lowest());
  float far = std::numeric_limits<float>::lowest();
  float near = std::numeric_limits<float>::max();
  auto add_receiver = [&](const glm::vec3& p) {
    const glm::vec2 st(glm::dot(s, p), glm::dot(t, p));
    lo = glm::min(lo, st);
    hi = glm::max(hi, st);
    far = std::max(far, glm::dot(f, p));
    near = std::min(near, glm::dot(f, p));
  };
  for (const glm::vec3& p : receivers) add_receiver(p);
  if (receivers.empty()) {
    if (caster_bounds.empty()) return {};
    for (const glm::vec3& p : box_corners(caster_bounds)) add_receiver(p);
  }
  if (!caster_bounds.empty()) {
    for (const glm::vec3& p : box_corners(caster_bounds)) near = std::min(near, glm::dot(f, p));
  }
  const glm::vec2 centre = 0.5f * (lo + hi);
  float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y);
  half = std::max(half * (1.0f + 2.0f * margin_texels / std::max(face_size, 1.0f)), 0.0f) + 1e-3f;
  const float pad = 0.05f + 0.01f * (far - near);  // casters on the bound stay inside
  near -= pad;
  far += pad;
  SunFit fit;
  fit.half_width = half;
  fit.depth = far - near;
  const glm::vec4 rx(s / half, -centre.x / half);
  const glm::vec4 ry(t / half, -centre.y / half);
  const glm::vec4 rz(f / fit.depth, -near / fit.depth);
  const glm::vec4 rw(0.0f, 0.0f, 0.0f, 1.0f);
  for (int col = 0; col < 4; ++col) {
    fit.view_proj[col] = glm::vec4(rx[col], ry[col], rz[col], rw[col]);
  }
  return fit;
}

namespace {

// Opaque casters block (depth); translucent ones tint (colour), per triangle. Opaque ones
// of one-sided or alpha-tested materials are cut casters (docs/technique.md, "Draw
// classes"): they block only where their front faces the sample and their alpha reaches
// the cutoff, which the cut pipeline decides per fragment.
struct Casters {
  std::vector<std::uint32_t> opaque;
  std::vector<std::uint32_t> cut;
  std::vector<std::uint32_t> translucent;
  scene::Aabb bounds;
};

Casters sort_casters(const scene::Scene& scene, const std::vector<glm::vec3>& positions,
                     const std::vector<std::uint32_t>& indices,
                     std::span<const std::uint32_t> vertex_materials) {
  Casters casters;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t v = indices[t];
    bool tints = false;
    bool cut = false;
    if (v < vertex_materials.size() && vertex_materials[v] < scene.materials.size()) {
      const scene::Material& m = scene.materials[vertex_materials[v]];
      tints = m.translucent;
      cut = m.alpha_tested() || !m.double_sided;
    }
    auto& list = tints ? casters.translucent : (cut ? casters.cut : casters.opaque);
    list.insert(list.end(), {indices[t], indices[t + 1], indices[t + 2]});
    for (std::size_t k = 0; k < 3; ++k) casters.bounds.expand(positions[indices[t + k]]);
  }
  return casters;
}

void add_list(ReferencePlan& plan, const std::vector<std::uint32_t>& tris, std::uint32_t& first,
              std::uint32_t& count) {
  first = static_cast<std::uint32_t>(plan.indices.size());
  count = static_cast<std::uint32_t>(tris.size());
  plan.indices.insert(plan.indices.end(), tris.begin(), tris.end());
}

// What the suns' maps are fitted around: the visible part of the scene, computed once, by
// the first sun that needs it.
struct SunReceivers {
  std::vector<glm::vec3> points;
  bool known = false;
};

// The sun: a disc of angular radius `size` degrees; every sample direction gets its own
// orthographic map around the visible receivers, and every caster may block.
void plan_sun(ReferencePlan& plan, std::uint32_t l, const scene::PointLight& light,
              const Casters& casters, const glm::mat4& camera_view_proj,
              const PlanSettings& settings, SunReceivers& receivers) {
  const std::size_t base = std::size_t{l} * plan.samples;
  const bool shadows = light.casts_shadows && !casters.bounds.empty();
  const auto sun = sun_directions(light.direction, light.size, plan.samples);
  if (shadows && !receivers.known) {
    receivers.points = visible_region(camera_view_proj, casters.bounds);
    receivers.known = true;
  }
  if (shadows && plan.matrices.empty()) {
    plan.matrices.assign(plan.points.size(), glm::mat4(1.0f));
  }
  for (std::uint32_t k = 0; k < plan.samples; ++k) {
    float half_width = -1.0f;
    if (shadows) {
      const SunFit fit =
          fit_sun(sun[k], receivers.points, casters.bounds, static_cast<float>(settings.face_size));
      plan.matrices[base + k] = fit.view_proj;
      half_width = fit.half_width;
    }
    plan.points[base + k].position_far = {sun[k], half_width};
  }
  if (!shadows) return;
  add_list(plan, casters.opaque, plan.index_first[l], plan.index_count[l]);
  add_list(plan, casters.cut, plan.cut_first[l], plan.cut_count[l]);
  add_list(plan, casters.translucent, plan.tint_first[l], plan.tint_count[l]);
}

// A point or spot light: samples on its sphere; faces reach the receivers' whole lit
// sphere from any point of the light.
void plan_local_light(ReferencePlan& plan, std::uint32_t l, const scene::PointLight& light,
                      const Casters& casters, const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& directions) {
  const std::size_t base = std::size_t{l} * plan.samples;
  const float far = light.range + light.size;
  const bool shadows = light.casts_shadows && light.range > 0.0f;
  for (std::uint32_t k = 0; k < plan.samples; ++k) {
    const glm::vec3 p = light.position + directions[k] * light.size;
    plan.points[base + k].position_far = {p, shadows ? far : -1.0f};
  }
  if (!shadows) return;
  add_list(plan, triangles_near(positions, casters.opaque, light.position, far),
           plan.index_first[l], plan.index_count[l]);
  add_list(plan, triangles_near(positions, casters.cut, light.position, far), plan.cut_first[l],
           plan.cut_count[l]);
  add_list(plan, triangles_near(positions, casters.translucent, light.position, far),
           plan.tint_first[l], plan.tint_count[l]);
}

// Consecutive visible faces share one instanced draw.
void add_face_runs(Batch& batch, std::uint32_t sample, std::uint32_t slot, std::uint32_t mask) {
  for (std::uint32_t f = 0; f < shadow_faces::kFaceCount;) {
    if ((mask & (1u << f)) == 0) {
      ++f;
      continue;
    }
    FaceRun run{sample, slot, f, 0};
    while (f < shadow_faces::kFaceCount && (mask & (1u << f)) != 0) {
      ++run.face_count;
      ++f;
    }
    batch.runs.push_back(run);
  }
}

// The lights first .. first + count - 1, drawn together.
Batch make_batch(const ReferencePlan& plan, const scene::Scene& scene,
                 const shadow_faces::Frustum& frustum, const PlanSettings& settings,
                 std::uint32_t first, std::uint32_t count) {
  Batch batch;
  batch.first_light = first;
  batch.light_count = count;
  for (std::uint32_t slot = 0; slot < batch.light_count; ++slot) {
    batch.tinted = batch.tinted || plan.tint_count[first + slot] > 0;
  }
  for (std::uint32_t k = 0; k < plan.samples; ++k) {
    for (std::uint32_t slot = 0; slot < batch.light_count; ++slot) {
      const std::uint32_t l = first + slot;
      if (plan.index_count[l] == 0 && plan.cut_count[l] == 0 && plan.tint_count[l] == 0) continue;
      if (scene.lights[l].type == scene::LightType::directional) {
        batch.runs.push_back({k, slot, 0, 1});  // one map, fitted to the view
        continue;
      }
      const glm::vec4 pf = plan.points[std::size_t{l} * plan.samples + k].position_far;
      const std::uint32_t mask =
          settings.cull_faces ? shadow_faces::visible_faces(frustum, glm::vec3(pf), pf.w) : 0x3Fu;
      add_face_runs(batch, k, slot, mask);
    }
  }
  return batch;
}

}  // namespace

ReferencePlan build_plan(const scene::Scene& scene, const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices,
                         const glm::mat4& camera_view_proj, const PlanSettings& settings,
                         std::span<const std::uint32_t> vertex_materials) {
  ReferencePlan plan;
  plan.samples = std::max<std::uint32_t>(settings.samples, 1);
  plan.lights_per_batch = std::max<std::uint32_t>(settings.lights_per_batch, 1);
  const auto directions = fibonacci_sphere(plan.samples);
  const auto frustum = shadow_faces::camera_frustum(camera_view_proj);
  const auto light_count = static_cast<std::uint32_t>(scene.lights.size());
  const Casters casters = sort_casters(scene, positions, indices, vertex_materials);
  SunReceivers receivers;

  plan.points.resize(std::size_t{light_count} * plan.samples);
  plan.index_first.resize(light_count, 0);
  plan.index_count.resize(light_count, 0);
  plan.cut_first.resize(light_count, 0);
  plan.cut_count.resize(light_count, 0);
  plan.tint_first.resize(light_count, 0);
  plan.tint_count.resize(light_count, 0);
  for (std::uint32_t l = 0; l < light_count; ++l) {
    const auto& light = scene.lights[l];
    if (light.type == scene::LightType::directional) {
      plan_sun(plan, l, light, casters, camera_view_proj, settings, receivers);
    } else {
      plan_local_light(plan, l, light, casters, positions, directions);
    }
  }

  for (std::uint32_t first = 0; first < light_count; first += plan.lights_per_batch) {
    Batch batch = make_batch(plan, scene, frustum, settings, first,
                             std::min(plan.lights_per_batch, light_count - first));
    plan.any_tinted = plan.any_tinted || batch.tinted;
    plan.batches.push_back(std::move(batch));
  }
  return plan;
}

}  // namespace antumbra::passes::reference
