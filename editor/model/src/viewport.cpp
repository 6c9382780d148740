#include "antumbra/editor/viewport.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/gtc/constants.hpp>

namespace antumbra::editor {
namespace {

constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};
constexpr float kMaxPitch = 1.5533430f;  // 89 degrees
constexpr float kMinDistance = 0.05f;

float aspect_of(glm::ivec2 image) {
  return static_cast<float>(std::max(image.x, 1)) / static_cast<float>(std::max(image.y, 1));
}

glm::vec3 direction_of(float yaw, float pitch) {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

// A closed world-space loop to image polylines, cut where it passes behind the near plane.
void add_loop(const scene::Camera& camera, glm::ivec2 image, const std::vector<glm::vec3>& loop,
              std::vector<std::vector<glm::vec2>>& out) {
  const glm::vec3 forward = camera.forward();
  const float cut = camera.near * 1.01f;
  std::vector<glm::vec2> run;
  const auto flush = [&] {
    if (run.size() >= 2) out.push_back(run);
    run.clear();
  };
  const auto add = [&](glm::vec3 p) {
    if (const auto pixel = project(camera, image, p)) run.push_back(*pixel);
  };
  for (std::size_t i = 0; i + 1 < loop.size(); ++i) {
    const glm::vec3 a = loop[i];
    const glm::vec3 b = loop[i + 1];
    const float da = glm::dot(a - camera.position, forward);
    const float db = glm::dot(b - camera.position, forward);
    if (da >= cut && db >= cut) {
      if (run.empty()) add(a);
      add(b);
    } else if (da >= cut || db >= cut) {
      const glm::vec3 crossing = a + (b - a) * ((cut - da) / (db - da));
      if (da >= cut) {
        if (run.empty()) add(a);
        add(crossing);
        flush();
      } else {
        add(crossing);
        add(b);
      }
    } else {
      flush();
    }
  }
  flush();
}

}  // namespace

float focal_pixels(const scene::Camera& camera, glm::ivec2 image) {
  return 0.5f * static_cast<float>(image.y) / std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
}

PixelRect letterbox(glm::ivec2 image, glm::ivec2 target) {
  const double scale = std::min(static_cast<double>(target.x) / std::max(image.x, 1),
                                static_cast<double>(target.y) / std::max(image.y, 1));
  PixelRect rect;
  rect.width = std::max(1, static_cast<int>(image.x * scale));
  rect.height = std::max(1, static_cast<int>(image.y * scale));
  rect.x = (target.x - rect.width) / 2;
  rect.y = (target.y - rect.height) / 2;
  return rect;
}

glm::vec2 to_image(const PixelRect& rect, glm::ivec2 image, glm::vec2 target_pixel) {
  return (target_pixel - glm::vec2(rect.x, rect.y)) * glm::vec2(image) /
         glm::vec2(rect.width, rect.height);
}

glm::vec2 to_target(const PixelRect& rect, glm::ivec2 image, glm::vec2 image_pixel) {
  return glm::vec2(rect.x, rect.y) +
         image_pixel * glm::vec2(rect.width, rect.height) / glm::vec2(image);
}

Ray ray_through(const scene::Camera& camera, glm::ivec2 image, glm::vec2 pixel) {
  const glm::vec2 ndc = pixel / glm::vec2(image) * 2.0f - 1.0f;
  const glm::mat4 inverse = glm::inverse(camera.view_projection(aspect_of(image)));
  const glm::vec4 far_point = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  Ray ray;
  ray.origin = camera.position;
  ray.direction = glm::normalize(glm::vec3(far_point) / far_point.w - camera.position);
  return ray;
}

std::optional<glm::vec2> project(const scene::Camera& camera, glm::ivec2 image, glm::vec3 point,
                                 float* view_depth) {
  const glm::vec4 clip = camera.view_projection(aspect_of(image)) * glm::vec4(point, 1.0f);
  // For this projection clip.w is the distance along the view direction.
  if (view_depth != nullptr) *view_depth = clip.w;
  if (clip.w < camera.near) return std::nullopt;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return (ndc + 1.0f) * 0.5f * glm::vec2(image);
}

int pick_light(const std::vector<scene::PointLight>& lights, const scene::Camera& camera,
               glm::ivec2 image, glm::vec2 pixel, float min_radius_px) {
  const float focal = focal_pixels(camera, image);
  // Inside a light's own sphere: the nearest such light is in front. Only inside the
  // enlarged marker of small lights: the marker whose centre is closest on screen, so
  // that neighbouring markers that overlap split the space between them.
  int in_sphere = -1;
  float in_sphere_depth = std::numeric_limits<float>::max();
  int in_marker = -1;
  float in_marker_distance = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const auto& light = lights[i];
    if (light.type == scene::LightType::directional) continue;
    float depth = 0.0f;
    const auto centre = project(camera, image, light.position, &depth);
    if (!centre) continue;
    const float distance = glm::distance(*centre, pixel);
    const float sphere_radius = light.size * focal / depth;
    if (distance <= sphere_radius && depth < in_sphere_depth) {
      in_sphere = static_cast<int>(i);
      in_sphere_depth = depth;
    }
    if (distance <= std::max(min_radius_px, sphere_radius) && distance < in_marker_distance) {
      in_marker = static_cast<int>(i);
      in_marker_distance = distance;
    }
  }
  return in_sphere >= 0 ? in_sphere : in_marker;
}

std::optional<glm::vec3> intersect_plane(const Ray& ray, glm::vec3 plane_point,
                                         glm::vec3 plane_normal, float max_distance) {
  const float denominator = glm::dot(plane_normal, ray.direction);
  if (std::abs(denominator) < 1e-6f) return std::nullopt;
  const float t = glm::dot(plane_normal, plane_point - ray.origin) / denominator;
  if (!(t > 0.0f) || t > max_distance) return std::nullopt;
  return ray.origin + ray.direction * t;
}

std::string_view to_string(DragPlane plane) {
  switch (plane) {
    case DragPlane::horizontal:
      return "horizontal";
    case DragPlane::vertical:
      return "vertical";
    case DragPlane::facing:
      return "facing";
  }
  return "?";
}

namespace {

glm::vec3 normal_of(DragPlane plane, const scene::Camera& camera, glm::vec3 grab_direction) {
  if (plane == DragPlane::horizontal) return kWorldUp;
  if (plane == DragPlane::facing) return -grab_direction;
  const glm::vec3 forward = camera.forward();
  const glm::vec2 flat(forward.x, forward.z);
  // Straight down the view has no horizontal direction: the upright plane is then
  // edge-on whichever way it faces, and the drag moves on.
  return glm::length(flat) > 1e-6f ? glm::normalize(glm::vec3(flat.x, 0.0f, flat.y))
                                   : glm::vec3(0.0f, 0.0f, 1.0f);
}

// The planes to try, best first: the one asked for, the other upright one, then facing.
std::vector<DragPlane> plane_order(DragPlane requested) {
  if (requested == DragPlane::vertical) {
    return {DragPlane::vertical, DragPlane::horizontal, DragPlane::facing};
  }
  if (requested == DragPlane::facing) return {DragPlane::facing};
  return {DragPlane::horizontal, DragPlane::vertical, DragPlane::facing};
}

}  // namespace

LightDrag::LightDrag(glm::vec3 light_position, const scene::Camera& camera, glm::ivec2 image,
                     glm::vec2 grab_pixel, DragPlane requested, float max_move)
    : camera_(camera),
      image_(image),
      start_(light_position),
      requested_(requested),
      plane_(requested),
      max_move_(std::max(max_move, 0.0f)) {
  const Ray grab = ray_through(camera, image, grab_pixel);
  for (const DragPlane candidate : plane_order(requested)) {
    const glm::vec3 normal = normal_of(candidate, camera, grab.direction);
    const auto hit = intersect_plane(grab, start_, normal, std::numeric_limits<float>::max());
    const bool edge_on = std::abs(glm::dot(grab.direction, normal)) < kGrazingSine;
    if ((edge_on || !hit) && candidate != DragPlane::facing) continue;
    plane_ = candidate;
    normal_ = normal;
    // The facing plane always meets its own grab ray; the fallback keeps the light put.
    offset_ = hit ? start_ - *hit : glm::vec3(0.0f);
    return;
  }
}

std::optional<glm::vec3> LightDrag::update(glm::vec2 pixel) const {
  const Ray ray = ray_through(camera_, image_, pixel);
  const auto hit = intersect_plane(ray, start_, normal_, camera_.far);
  if (!hit) return std::nullopt;
  glm::vec3 position = *hit + offset_;
  if (glm::distance(position, start_) > max_move_) return std::nullopt;
  if (plane_ == DragPlane::horizontal) position.y = start_.y;  // exactly, not within float noise
  return position;
}

std::string LightDrag::describe() const {
  char text[160];
  switch (plane_) {
    case DragPlane::horizontal:
      std::snprintf(text, sizeof text, "horizontal plane y = %.2f m", start_.y);
      break;
    case DragPlane::vertical:
      std::snprintf(text, sizeof text, "upright plane facing the camera");
      break;
    case DragPlane::facing:
      std::snprintf(text, sizeof text, "plane facing the cursor's ray");
      break;
  }
  std::string out = std::string("dragging on the ") + text;
  if (switched()) {
    out += " (the " + std::string(to_string(requested_)) + " plane is seen edge-on from here)";
  }
  return out;
}

float drag_limit(const scene::Scene& scene) {
  scene::Aabb box = scene.bounds;
  for (const auto& light : scene.lights) {
    if (light.type == scene::LightType::directional) continue;
    box.expand(light.position);
  }
  const float diagonal = box.empty() ? 0.0f : glm::length(box.extent());
  return std::min(std::max(diagonal, 1.0f), std::max(scene.camera.far, 1.0f));
}

std::vector<std::vector<glm::vec2>> sphere_outline(const scene::Camera& camera, glm::ivec2 image,
                                                   glm::vec3 centre, float radius, int segments) {
  std::vector<std::vector<glm::vec2>> out;
  if (!(radius > 0.0f) || !std::isfinite(radius) || segments < 3) return out;
  const auto loop = [&](glm::vec3 middle, glm::vec3 a, glm::vec3 b, float r) {
    std::vector<glm::vec3> points;
    points.reserve(static_cast<std::size_t>(segments) + 1);
    for (int i = 0; i <= segments; ++i) {
      const float angle =
          2.0f * glm::pi<float>() * static_cast<float>(i % segments) / static_cast<float>(segments);
      points.push_back(middle + r * (std::cos(angle) * a + std::sin(angle) * b));
    }
    add_loop(camera, image, points, out);
  };
  const glm::vec3 to_centre = centre - camera.position;
  const float d = glm::length(to_centre);
  if (d > radius * 1.0001f) {
    // The silhouette: the circle where the view cone touches the sphere.
    const glm::vec3 u = to_centre / d;
    const glm::vec3 helper = std::abs(u.y) < 0.9f ? kWorldUp : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 a = glm::normalize(glm::cross(u, helper));
    const glm::vec3 b = glm::cross(u, a);
    loop(centre - u * (radius * radius / d), a, b, radius * std::sqrt(d * d - radius * radius) / d);
  }
  loop(centre, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, radius);
  return out;
}

ViewportCamera::ViewportCamera(const scene::Camera& start) {
  reset(start);
}

void ViewportCamera::reset(const scene::Camera& start) {
  camera_ = start;
  camera_.up = kWorldUp;
  const glm::vec3 offset = start.target - start.position;
  distance_ = std::max(glm::length(offset), kMinDistance);
  const glm::vec3 f =
      glm::length(offset) > 0.0f ? offset / glm::length(offset) : glm::vec3(0.0f, 0.0f, -1.0f);
  // Straight down (or up) the view has no horizontal direction: the file's `up` says
  // which way the top of the image faces.
  const glm::vec3 heading = std::abs(f.y) > 0.999f ? start.up * (f.y < 0.0f ? 1.0f : -1.0f) : f;
  yaw_ = std::atan2(heading.x, -heading.z);
  pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  apply();
}

void ViewportCamera::apply() {
  camera_.target = camera_.position + direction_of(yaw_, pitch_) * distance_;
}

void ViewportCamera::look(glm::vec2 delta_pixels) {
  yaw_ += delta_pixels.x * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ - delta_pixels.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
  apply();
}

void ViewportCamera::move(glm::vec3 axes, float metres) {
  const glm::vec3 forward = direction_of(yaw_, pitch_);
  const glm::vec3 right = glm::normalize(glm::cross(forward, kWorldUp));
  const glm::vec3 step = right * axes.x + kWorldUp * axes.y + forward * axes.z;
  if (glm::length(step) <= 0.0f) return;
  camera_.position += glm::normalize(step) * metres;
  apply();
}

void ViewportCamera::orbit(glm::vec2 delta_pixels) {
  const glm::vec3 pivot = camera_.target;
  yaw_ += delta_pixels.x * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ - delta_pixels.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
  camera_.position = pivot - direction_of(yaw_, pitch_) * distance_;
  apply();
}

void ViewportCamera::dolly(float steps) {
  const glm::vec3 pivot = camera_.target;
  distance_ =
      std::clamp(distance_ * std::pow(0.85f, steps), kMinDistance, std::max(camera_.far, 1.0f));
  camera_.position = pivot - direction_of(yaw_, pitch_) * distance_;
  apply();
}

void ViewportCamera::set_pivot(glm::vec3 pivot) {
  const glm::vec3 offset = pivot - camera_.position;
  const float d = glm::length(offset);
  if (d < kMinDistance) return;  // standing on it: no direction to turn to
  const glm::vec3 f = offset / d;
  yaw_ = std::atan2(f.x, -f.z);
  pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  distance_ = d;
  apply();
}

}  // namespace antumbra::editor
