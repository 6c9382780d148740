#include "lighting_test_support.hpp"

#include <algorithm>
#include <cmath>

#include "antumbra/scene/primitives.hpp"
#include "common/frame_data.hpp"

namespace antumbra::lighting_testing {

scene::Scene floor_scene() {
  scene::Scene s;
  s.name = "lighting-test";
  s.camera.position = {0.0f, 9.0f, 7.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.near = 0.1f;
  s.camera.far = 100.0f;
  s.ambient = {0.02f, 0.02f, 0.025f};
  scene::Material floor;
  floor.name = "floor";
  floor.albedo = {0.6f, 0.55f, 0.5f};
  floor.roughness = 0.7f;
  s.materials.push_back(floor);
  add_box(s, {0.0f, -0.1f, 0.0f}, {40.0f, 0.2f, 40.0f});
  return s;
}

void add_box(scene::Scene& scene, const glm::vec3& centre, const glm::vec3& size) {
  scene::Mesh mesh = scene::make_box(size);
  mesh.name = "box" + std::to_string(scene.meshes.size());
  mesh.material = 0;
  mesh.transform = glm::mat4(1.0f);
  mesh.transform[3] = glm::vec4(centre, 1.0f);
  mesh.update_bounds();
  scene.meshes.push_back(std::move(mesh));
  scene.bounds = scene.compute_bounds();
}

void add_light(scene::Scene& scene, const glm::vec3& position, const glm::vec3& color,
               float intensity, float range, float size) {
  scene::PointLight light;
  light.name = "light" + std::to_string(scene.lights.size());
  light.position = position;
  light.color = color;
  light.intensity = intensity;
  light.range = range;
  light.size = size;
  scene.lights.push_back(light);
}

glm::vec4 texel(const gpu::HostImage& image, std::uint32_t x, std::uint32_t y) {
  glm::vec4 out(0.0f);
  const std::size_t base = (std::size_t{y} * image.width + x) * image.channels;
  for (std::uint32_t c = 0; c < std::min<std::uint32_t>(image.channels, 4); ++c) {
    out[static_cast<int>(c)] = image.texels[base + c];
  }
  return out;
}

glm::dvec3 reference_radiance(const scene::Scene& scene, VkExtent2D viewport, std::uint32_t x,
                              std::uint32_t y, float depth, const glm::vec4& normal_rough,
                              const glm::vec4& albedo_metal, const LightingParams& params,
                              const glm::vec4& emission_occlusion) {
  const auto frame = passes::build_frame_uniforms(scene, viewport.width, viewport.height, 0);
  const auto lights = passes::build_lights(scene, frame.view);
  const glm::dvec2 uv((x + 0.5) / viewport.width, (y + 0.5) / viewport.height);
  const glm::dvec4 clip(uv * 2.0 - 1.0, depth, 1.0);
  const glm::dvec4 view = glm::dmat4(frame.inv_proj) * clip;
  const glm::dvec3 p = glm::dvec3(view) / view.w;
  const glm::dvec3 n = glm::normalize(glm::dvec3(normal_rough));
  const glm::dvec3 v = glm::normalize(-p);
  const glm::dvec3 albedo(albedo_metal);
  const double shininess = 128.0 + (4.0 - 128.0) * std::clamp<double>(normal_rough.w, 0.0, 1.0);
  // Occlusion darkens the ambient (indirect) term only; emission is added unshadowed.
  glm::dvec3 color =
      glm::dvec3(frame.ambient) * double(params.ambient) * double(emission_occlusion.a) * albedo +
      glm::dvec3(emission_occlusion);
  for (const auto& light : lights) {
    glm::dvec3 l;
    double attenuation = 1.0;
    if (light.direction_type.w > 1.5) {  // directional: constant direction, no falloff
      l = -glm::normalize(glm::dvec3(light.direction_type));
    } else {
      const glm::dvec3 to_light = glm::dvec3(light.position_range) - p;
      const double dist = glm::length(to_light);
      const double range = light.position_range.w;
      if (dist >= range) continue;
      l = to_light / dist;
      const double ratio = dist / range;
      const double window = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
      attenuation = window * window / (dist * dist + 1.0);
      if (light.direction_type.w > 0.5) {  // spot: smoothstep(cos outer, cos inner, cos)
        const double lo = light.cone.x;
        const double hi = std::max(double(light.cone.y), lo + 1e-4);
        const double t =
            std::clamp((glm::dot(-l, glm::dvec3(light.direction_type)) - lo) / (hi - lo), 0.0, 1.0);
        attenuation *= t * t * (3.0 - 2.0 * t);
      }
    }
    const double n_dot_l = std::max(glm::dot(n, l), 0.0);
    if (n_dot_l <= 0.0) continue;
    const glm::dvec3 h = glm::normalize(l + v);
    const double spec = params.specular * std::pow(std::max(glm::dot(n, h), 0.0), shininess) *
                        (shininess + 8.0) / 25.0;
    const glm::dvec3 radiance =
        glm::dvec3(light.color_intensity) * double(light.color_intensity.w) * attenuation;
    color += radiance * n_dot_l * (albedo + glm::dvec3(spec));
  }
  return color * double(params.exposure);
}

glm::ivec2 project_to_pixel(const scene::Scene& scene, VkExtent2D viewport, const glm::vec3& p) {
  const auto frame = passes::build_frame_uniforms(scene, viewport.width, viewport.height, 0);
  const glm::vec4 clip = frame.view_proj * glm::vec4(p, 1.0f);
  const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
  return glm::ivec2(glm::floor(uv * glm::vec2(viewport.width, viewport.height)));
}

std::vector<std::pair<float, float>> floor_light_fraction(const scene::Scene& scene,
                                                          VkExtent2D viewport,
                                                          const gpu::HostImage& hdr,
                                                          const gpu::HostImage& unshadowed,
                                                          float x_max) {
  const float ambient = scene.ambient.r * std::round(scene.materials[0].albedo.r * 255.0f) / 255.0f;
  std::vector<std::pair<float, float>> out;
  glm::ivec2 last(-1);
  for (float x = 0.0f; x <= x_max; x += 0.02f) {
    const glm::ivec2 p = project_to_pixel(scene, viewport, {x, 0.0f, 0.0f});
    if (p == last) continue;
    last = p;
    const float lit = texel(unshadowed, p.x, p.y).r - ambient;
    out.emplace_back(x, (texel(hdr, p.x, p.y).r - ambient) / lit);
  }
  return out;
}

}  // namespace antumbra::lighting_testing
