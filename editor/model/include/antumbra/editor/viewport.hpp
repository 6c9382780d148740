#pragma once
// The editor viewport's geometry, without a window: where the graph's image lands in the
// window, the navigation camera (fly and orbit), rays through pixels, picking lights,
// dragging a light on a plane and the outline of a light's range sphere. The windowed
// editor feeds it mouse and key input and draws what it returns; tests drive it directly.
//
// Positions are continuous image coordinates of the graph's output: the image spans
// [0, width] x [0, height], origin top-left, y down, as in the Vulkan clip space of
// scene::Camera (NDC y = -1 is the top edge). Pixel (i, j) has its centre at (i+0.5, j+0.5).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/camera.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor {

struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  [[nodiscard]] bool contains(glm::vec2 p) const {
    return p.x >= static_cast<float>(x) && p.y >= static_cast<float>(y) &&
           p.x < static_cast<float>(x + width) && p.y < static_cast<float>(y + height);
  }
};

// The largest rectangle with the image's aspect ratio centred in the target (the
// presenter blits there; input is mapped back through it). Never smaller than 1x1.
PixelRect letterbox(glm::ivec2 image, glm::ivec2 target);
// A target pixel to an image pixel through `rect` (may fall outside the image).
glm::vec2 to_image(const PixelRect& rect, glm::ivec2 image, glm::vec2 target_pixel);
// An image pixel to a target pixel: the inverse of to_image.
glm::vec2 to_target(const PixelRect& rect, glm::ivec2 image, glm::vec2 image_pixel);

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit length
};

// The ray from the camera's position through an image position.
Ray ray_through(const scene::Camera& camera, glm::ivec2 image, glm::vec2 pixel);
// The image position a world point projects to; nullopt when it is not in front of the near
// plane. `view_depth` receives its distance along the view direction.
std::optional<glm::vec2> project(const scene::Camera& camera, glm::ivec2 image, glm::vec3 point,
                                 float* view_depth = nullptr);

// How many image pixels one metre covers at one metre of depth (vertical focal length).
float focal_pixels(const scene::Camera& camera, glm::ivec2 image);

// The light under a pixel. Where the pixel is inside lights' own spheres (radius `size`),
// the nearest of them to the camera; else, within the markers that keep small lights
// clickable (at least `min_radius_px` on screen), the one whose centre is closest.
// Directional lights have no position and are never picked. -1 when none is hit.
int pick_light(const std::vector<scene::PointLight>& lights, const scene::Camera& camera,
               glm::ivec2 image, glm::vec2 pixel, float min_radius_px = 10.0f);

// Where a ray meets a plane; nullopt when it runs parallel to it, meets it behind the
// origin or further than `max_distance` (a drag towards the horizon must not fling the
// light kilometres away).
std::optional<glm::vec3> intersect_plane(const Ray& ray, glm::vec3 plane_point,
                                         glm::vec3 plane_normal, float max_distance);

// Dragging a light in the viewport: the light follows the point where the cursor's ray
// meets its drag plane, so what is under the cursor at the start stays under it (the
// offset between the grabbed point and the light's centre is kept for the whole drag).
// `horizontal`: the plane y = the light's height (the artist's usual layout move);
// `vertical`: the upright plane through the light facing the camera (height changes);
// `facing`: the plane through the light perpendicular to the grab ray, never edge-on.
// A plane seen edge-on from the grab (the eye within about half a degree of it, where a
// pixel of cursor motion would move the light metres) is swapped for one that is not:
// horizontal -> vertical -> facing, and vertical -> horizontal -> facing; plane() and
// describe() say which is used. Nothing is extrapolated: where the cursor's ray misses
// the plane, meets it beyond the far plane or further than `max_move` from where the
// light started (the scene's extent), the light stays where it was last put.
enum class DragPlane { horizontal, vertical, facing };

std::string_view to_string(DragPlane plane);

class LightDrag {
 public:
  // Edge-on planes: below this |sine| of the angle between the grab ray and the plane.
  static constexpr float kGrazingSine = 0.01f;  // about 0.6 degrees

  LightDrag(glm::vec3 light_position, const scene::Camera& camera, glm::ivec2 image,
            glm::vec2 grab_pixel, DragPlane requested, float max_move);
  // The light's new position for a cursor position; nullopt where the cursor's ray
  // misses the plane or the limits (the light stays where it was last put).
  [[nodiscard]] std::optional<glm::vec3> update(glm::vec2 pixel) const;
  // The plane the drag uses, and the one asked for (they differ when it was edge-on).
  [[nodiscard]] DragPlane plane() const { return plane_; }
  [[nodiscard]] DragPlane requested() const { return requested_; }
  [[nodiscard]] bool switched() const { return plane_ != requested_; }
  // Light centre minus the grabbed point: the grabbed point is what lands under the cursor.
  [[nodiscard]] glm::vec3 offset() const { return offset_; }
  // For the status bar: "dragging on the horizontal plane y = 2.30 m", or why another.
  [[nodiscard]] std::string describe() const;

 private:
  scene::Camera camera_;
  glm::ivec2 image_;
  glm::vec3 start_;
  glm::vec3 normal_{0.0f, 1.0f, 0.0f};
  glm::vec3 offset_{0.0f};
  DragPlane requested_;
  DragPlane plane_;
  float max_move_;
};

// How far a drag may move a light in `scene`: the diagonal of its geometry and lights'
// bounds (at least 1 m), and never beyond the camera's far plane.
float drag_limit(const scene::Scene& scene);

// Polylines (image pixels) outlining a sphere as the camera sees it: its silhouette
// (when the camera is outside it) and its horizontal great circle (the footprint an
// artist reads against the floor). Parts behind the near plane are cut away, so a
// polyline may be split in several.
std::vector<std::vector<glm::vec2>> sphere_outline(const scene::Camera& camera, glm::ivec2 image,
                                                   glm::vec3 centre, float radius,
                                                   int segments = 64);

// The navigation camera: fly (look with the mouse, move with keys in camera axes) and
// orbit (turn around a pivot, dolly towards it). World +Y is up; the pitch stays within
// +-89 degrees so the view never flips. Lens settings (fov, near, far) are the scene's.
class ViewportCamera {
 public:
  static constexpr float kRadiansPerPixel = 0.005f;

  explicit ViewportCamera(const scene::Camera& start);
  void reset(const scene::Camera& start);

  [[nodiscard]] const scene::Camera& camera() const { return camera_; }
  [[nodiscard]] glm::vec3 pivot() const { return camera_.target; }
  [[nodiscard]] float distance() const { return distance_; }

  // Fly: turn the view about the camera's position by a mouse delta in pixels.
  void look(glm::vec2 delta_pixels);
  // Fly: move by `metres` along (right, up, forward) weights, e.g. {0, 0, 1} = W.
  void move(glm::vec3 axes, float metres);
  // Orbit: turn the camera about the pivot (the distance to it is kept).
  void orbit(glm::vec2 delta_pixels);
  // Dolly towards (steps > 0) or away from the pivot, by 15 % of the distance per step;
  // never closer than 0.05 m nor further than the far plane.
  void dolly(float steps);
  // Orbit about a new point (a selected light): the camera turns to face it, staying put.
  void set_pivot(glm::vec3 pivot);

 private:
  void apply();  // yaw, pitch, position, distance -> camera_

  scene::Camera camera_;
  float yaw_ = 0.0f;    // radians about +Y; 0 looks down -Z
  float pitch_ = 0.0f;  // radians above the horizon
  float distance_ = 1.0f;
};

}  // namespace antumbra::editor
