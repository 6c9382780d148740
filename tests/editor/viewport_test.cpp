// The viewport's geometry: letterboxing, rays and projection, picking, dragging on a
// plane, range-sphere outlines and the fly/orbit camera.

#include "antumbra/editor/viewport.hpp"
#include "antumbra/scene/scene_file.hpp"

#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace antumbra::editor {
namespace {

constexpr glm::ivec2 kImage{320, 180};

scene::Camera looking_down_minus_z() {
  scene::Camera camera;
  camera.position = {0.0f, 2.0f, 10.0f};
  camera.target = {0.0f, 2.0f, 0.0f};
  return camera;
}

scene::PointLight point_light(const char* name, glm::vec3 position, float size = 0.2f) {
  scene::PointLight light;
  light.name = name;
  light.position = position;
  light.size = size;
  return light;
}

float distance_to_ray(const Ray& ray, glm::vec3 point) {
  const glm::vec3 v = point - ray.origin;
  return glm::length(v - ray.direction * glm::dot(v, ray.direction));
}

void expect_near(glm::vec3 a, glm::vec3 b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

constexpr float kNoLimit = 1e9f;

// A dragged light (grabbed at its centre) is where the cursor points.
void expect_under_cursor(const scene::Camera& camera, glm::vec3 light, glm::vec2 cursor) {
  const auto on_screen = project(camera, kImage, light);
  ASSERT_TRUE(on_screen.has_value());
  EXPECT_LT(glm::distance(*on_screen, cursor), 0.05f);
}

TEST(Viewport, LetterboxKeepsTheAspectAndMapsBothWays) {
  const PixelRect wide = letterbox({1920, 1080}, {1000, 1000});
  EXPECT_EQ(wide.width, 1000);
  EXPECT_EQ(wide.height, 562);
  EXPECT_EQ(wide.x, 0);
  EXPECT_EQ(wide.y, 219);
  const PixelRect tall = letterbox({100, 100}, {400, 200});
  EXPECT_EQ(tall.x, 100);
  EXPECT_EQ(tall.width, 200);
  EXPECT_FALSE(tall.contains({50.0f, 100.0f}));
  EXPECT_TRUE(tall.contains({150.0f, 100.0f}));
  const glm::vec2 image_point = to_image(tall, {100, 100}, {200.0f, 50.0f});
  EXPECT_FLOAT_EQ(image_point.x, 50.0f);
  EXPECT_FLOAT_EQ(image_point.y, 25.0f);
  const glm::vec2 back = to_target(tall, {100, 100}, image_point);
  EXPECT_FLOAT_EQ(back.x, 200.0f);
  EXPECT_FLOAT_EQ(back.y, 50.0f);
  const PixelRect degenerate = letterbox({100, 100}, {0, 0});
  EXPECT_EQ(degenerate.width, 1);
  EXPECT_EQ(degenerate.height, 1);
}

TEST(Viewport, RaysAndProjectionAreInverse) {
  const scene::Camera camera = looking_down_minus_z();
  const Ray centre = ray_through(camera, kImage, glm::vec2(kImage) * 0.5f);
  expect_near(centre.direction, {0.0f, 0.0f, -1.0f}, 1e-5f);
  // The top of the image is up in the world (Vulkan's flipped y), the left is -x.
  EXPECT_GT(ray_through(camera, kImage, {160.0f, 0.0f}).direction.y, 0.0f);
  EXPECT_LT(ray_through(camera, kImage, {0.0f, 90.0f}).direction.x, 0.0f);
  for (const glm::vec2 pixel :
       {glm::vec2(3.0f, 7.0f), glm::vec2(301.5f, 44.0f), glm::vec2(160.0f, 179.0f)}) {
    const Ray ray = ray_through(camera, kImage, pixel);
    float depth = 0.0f;
    const auto projected = project(camera, kImage, ray.origin + ray.direction * 7.0f, &depth);
    ASSERT_TRUE(projected.has_value());
    EXPECT_NEAR(projected->x, pixel.x, 1e-3f);
    EXPECT_NEAR(projected->y, pixel.y, 1e-3f);
    EXPECT_GT(depth, 0.0f);
  }
  EXPECT_FALSE(project(camera, kImage, {0.0f, 2.0f, 12.0f}).has_value());  // behind
}

TEST(Viewport, PickingTakesTheNearestLightUnderTheCursor) {
  const scene::Camera camera = looking_down_minus_z();
  std::vector<scene::PointLight> lights = {point_light("far", {0.0f, 2.0f, -5.0f}),
                                           point_light("near", {0.0f, 2.0f, 0.0f}),
                                           point_light("side", {3.0f, 2.0f, 0.0f})};
  scene::PointLight sun = point_light("sun", {0.0f, 2.0f, 5.0f});
  sun.type = scene::LightType::directional;
  lights.push_back(sun);  // in front of both, but a sun has no position
  const glm::vec2 middle = glm::vec2(kImage) * 0.5f;
  EXPECT_EQ(pick_light(lights, camera, kImage, middle), 1);
  const glm::vec2 side = *project(camera, kImage, lights[2].position);
  EXPECT_EQ(pick_light(lights, camera, kImage, side + glm::vec2(9.0f, 0.0f)), 2);
  EXPECT_EQ(pick_light(lights, camera, kImage, side + glm::vec2(11.0f, 0.0f)), -1);
  EXPECT_EQ(pick_light(lights, camera, kImage, {5.0f, 5.0f}), -1);
  // A big light is hit over its projected sphere, not just the minimum marker.
  lights[2].size = 1.0f;  // 10 m away: radius 0.1 * focal = ~15.6 px at 180 px, 60 degrees
  EXPECT_EQ(pick_light(lights, camera, kImage, side + glm::vec2(14.0f, 0.0f)), 2);
  EXPECT_EQ(pick_light(lights, camera, kImage, side + glm::vec2(17.0f, 0.0f)), -1);
}

TEST(Viewport, OverlappingMarkersSplitTheSpaceBetweenThem) {
  const scene::Camera camera = looking_down_minus_z();
  // Two small lights 12 px apart at 180 px high: their 10 px markers overlap.
  const std::vector<scene::PointLight> lights = {point_light("left", {0.0f, 2.0f, 0.0f}, 0.01f),
                                                 point_light("right", {0.77f, 2.0f, 0.0f}, 0.01f)};
  const glm::vec2 left = *project(camera, kImage, lights[0].position);
  const glm::vec2 right = *project(camera, kImage, lights[1].position);
  ASSERT_LT(glm::distance(left, right), 20.0f);
  EXPECT_EQ(pick_light(lights, camera, kImage, left + (right - left) * 0.4f), 0);
  EXPECT_EQ(pick_light(lights, camera, kImage, left + (right - left) * 0.6f), 1);
}

TEST(Viewport, PlanesRefuseParallelAndFarHits) {
  const Ray along_floor{{0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
  EXPECT_FALSE(intersect_plane(along_floor, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 100.0f));
  const Ray up{{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  EXPECT_FALSE(intersect_plane(up, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 100.0f));  // behind
  const Ray grazing{{0.0f, 1.0f, 0.0f}, glm::normalize(glm::vec3(1.0f, -0.001f, 0.0f))};
  EXPECT_FALSE(intersect_plane(grazing, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 100.0f));
  const auto hit = intersect_plane(grazing, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 2000.0f);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->y, 0.0f, 1e-3f);
}

TEST(Viewport, AHorizontalDragKeepsTheLightUnderTheCursorAtItsHeight) {
  scene::Camera camera;
  camera.position = {0.0f, 6.0f, 8.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  const glm::vec3 light{1.0f, 1.5f, -1.0f};
  const glm::vec2 grab_pixel = *project(camera, kImage, light) + glm::vec2(2.0f, -1.0f);
  const LightDrag drag(light, camera, kImage, grab_pixel, DragPlane::horizontal, kNoLimit);
  ASSERT_FALSE(drag.switched());
  // Not moving the cursor does not move the light, even though the grab was off-centre.
  expect_near(*drag.update(grab_pixel), light, 1e-4f);
  const glm::vec2 target_pixel = grab_pixel + glm::vec2(40.0f, 25.0f);
  const auto moved = drag.update(target_pixel);
  ASSERT_TRUE(moved.has_value());
  EXPECT_EQ(moved->y, light.y);
  EXPECT_GT(moved->x, light.x);  // right on screen
  EXPECT_GT(moved->z, light.z);  // down on screen: towards the camera
  // The grabbed point (light + fixed offset) is under the cursor.
  const auto grabbed = intersect_plane(ray_through(camera, kImage, target_pixel), light,
                                       {0.0f, 1.0f, 0.0f}, 1000.0f);
  ASSERT_TRUE(grabbed.has_value());
  const auto offset_at_grab = light - *intersect_plane(ray_through(camera, kImage, grab_pixel),
                                                       light, {0.0f, 1.0f, 0.0f}, 1000.0f);
  expect_near(*moved - *grabbed, offset_at_grab, 1e-4f);
}

TEST(Viewport, AVerticalDragChangesHeightFacingTheCamera) {
  const scene::Camera camera = looking_down_minus_z();
  const glm::vec3 light{0.0f, 2.5f, 0.0f};
  const glm::vec2 at = *project(camera, kImage, light);
  const LightDrag drag(light, camera, kImage, at, DragPlane::vertical, kNoLimit);
  ASSERT_FALSE(drag.switched());
  const auto moved = drag.update(at + glm::vec2(0.0f, -30.0f));
  ASSERT_TRUE(moved.has_value());
  EXPECT_GT(moved->y, light.y);
  EXPECT_NEAR(moved->z, light.z, 1e-4f);  // stays on the plane facing the camera
  EXPECT_NEAR(moved->x, light.x, 1e-4f);
  expect_under_cursor(camera, *moved, at + glm::vec2(0.0f, -30.0f));
  // Looking steeply down (the navigation camera stops at 89 degrees) the upright plane
  // is edge-on: the drag moves to the horizontal plane and still follows the cursor.
  for (const float pitch_pixels : {1000.0f, 300.0f}) {  // to the 89 degree clamp; ~86 degrees
    scene::Camera level;
    level.position = {0.0f, 10.0f, 0.0f};
    level.target = {0.0f, 10.0f, -1.0f};
    ViewportCamera view(level);
    view.look({0.0f, pitch_pixels});  // mouse down: look down
    ASSERT_LT(view.camera().forward().y, -0.98f);
    const glm::vec3 below{0.0f, 0.0f, 0.0f};
    const glm::vec2 grab = *project(view.camera(), kImage, below);
    const LightDrag steep(below, view.camera(), kImage, grab, DragPlane::vertical, kNoLimit);
    if (pitch_pixels > 500.0f) {
      EXPECT_TRUE(steep.switched());
      EXPECT_EQ(steep.plane(), DragPlane::horizontal);
      EXPECT_NE(steep.describe().find("edge-on"), std::string::npos) << steep.describe();
    }
    expect_near(*steep.update(grab), below, 1e-4f);
    const glm::vec2 cursor = grab + glm::vec2(20.0f, -20.0f);
    expect_under_cursor(view.camera(), *steep.update(cursor), cursor);
  }
  // A file camera straight down, its `up` saying where the top of the image is.
  scene::Camera down;
  down.position = {0.0f, 10.0f, 0.0f};
  down.target = {0.0f, 0.0f, 0.0f};
  down.up = {0.0f, 0.0f, -1.0f};
  const glm::vec2 centre = glm::vec2(kImage) * 0.5f;
  const LightDrag from_above({0.0f, 0.0f, 0.0f}, down, kImage, centre, DragPlane::horizontal,
                             kNoLimit);
  EXPECT_FALSE(from_above.switched());
  const glm::vec3 up_on_screen = *from_above.update(centre + glm::vec2(0.0f, -20.0f));
  EXPECT_LT(up_on_screen.z, 0.0f) << "the top of the image faces -Z";
  EXPECT_TRUE(std::isfinite(up_on_screen.x));
}

TEST(Viewport, AStraightDownFileCameraKeepsItsHeading) {
  scene::Camera down;
  down.position = {0.0f, 10.0f, 0.0f};
  down.target = {0.0f, 0.0f, 0.0f};
  down.up = {1.0f, 0.0f, 0.0f};  // the top of the image faces +X
  const ViewportCamera view(down);
  const glm::vec3 forward = view.camera().forward();
  EXPECT_LT(forward.y, -0.99f);
  EXPECT_GT(forward.x, 0.0f) << "tilted towards the image's top, not an arbitrary side";
  EXPECT_NEAR(forward.z, 0.0f, 1e-5f);
}

TEST(Viewport, AHorizontalDragSlightlyAboveTheEyeFollowsTheCursorRay) {
  // A grazing plane that is not edge-on: the ray still decides, however far a pixel moves
  // the light; the old screen-space mapping put the light metres from the cursor here.
  const scene::Camera camera = looking_down_minus_z();  // eye at y = 2
  const glm::vec3 light{1.0f, 2.3f, -6.0f};
  const glm::vec2 at = *project(camera, kImage, light);
  const LightDrag drag(light, camera, kImage, at, DragPlane::horizontal, kNoLimit);
  EXPECT_FALSE(drag.switched());
  expect_near(*drag.update(at), light, 1e-4f);
  for (const glm::vec3 target : {glm::vec3(-2.0f, 2.3f, -1.0f), glm::vec3(3.0f, 2.3f, 4.0f),
                                 glm::vec3(0.5f, 2.3f, -20.0f)}) {
    const glm::vec2 cursor = *project(camera, kImage, target);
    const auto moved = drag.update(cursor);
    ASSERT_TRUE(moved.has_value());
    EXPECT_LT(glm::distance(*moved, target), 0.01f) << target.x << " " << target.z;
  }
  // Below the plane's horizon the ray never meets it: the light stays where it was put.
  EXPECT_FALSE(drag.update(at + glm::vec2(0.0f, 30.0f)).has_value());
}

TEST(Viewport, AnEdgeOnPlaneIsSwappedForOneThatIsNot) {
  // The light at eye height: its horizontal plane contains the eye.
  const scene::Camera camera = looking_down_minus_z();
  for (const float height : {2.0f, 2.04f, 1.97f}) {
    const glm::vec3 light{1.0f, height, -6.0f};
    const glm::vec2 at = *project(camera, kImage, light);
    const LightDrag drag(light, camera, kImage, at, DragPlane::horizontal, kNoLimit);
    EXPECT_TRUE(drag.switched()) << height;
    EXPECT_EQ(drag.plane(), DragPlane::vertical);
    EXPECT_NE(drag.describe().find("upright"), std::string::npos) << drag.describe();
    expect_near(*drag.update(at), light, 1e-4f);
    for (const glm::vec2 step : {glm::vec2(25.0f, 0.0f), glm::vec2(-10.0f, 30.0f)}) {
      const auto moved = drag.update(at + step);
      ASSERT_TRUE(moved.has_value());
      expect_under_cursor(camera, *moved, at + step);
      EXPECT_NEAR(moved->z, light.z, 1e-3f);  // on the upright plane through the light
    }
  }
}

TEST(Viewport, ADragNeverMovesALightFurtherThanItsLimits) {
  const scene::Camera camera = looking_down_minus_z();  // eye at y = 2, far 100
  const glm::vec3 light{0.0f, 2.5f, 0.0f};
  const glm::vec2 at = *project(camera, kImage, light);
  const LightDrag drag(light, camera, kImage, at, DragPlane::horizontal, 12.0f);
  EXPECT_FALSE(drag.switched());
  // Towards the plane's horizon the hit runs away: within the limit it follows, beyond it
  // the light stays.
  float last_distance = 0.0f;
  int followed = 0;
  for (float dy = 0.0f; dy < 90.0f; dy += 0.5f) {
    const auto moved = drag.update(at + glm::vec2(0.0f, dy));
    if (!moved) continue;
    ++followed;
    last_distance = glm::distance(*moved, light);
    EXPECT_LE(last_distance, 12.0f + 1e-3f);
  }
  EXPECT_GT(followed, 3);
  EXPECT_GT(last_distance, 6.0f);
  const LightDrag unlimited(light, camera, kImage, at, DragPlane::horizontal, 1e9f);
  for (float dy = 0.0f; dy < 90.0f; dy += 0.5f) {
    if (const auto moved = unlimited.update(at + glm::vec2(0.0f, dy))) {
      EXPECT_LE(glm::distance(camera.position, *moved), camera.far + 1e-2f);
    }
  }
}

TEST(Viewport, TheDragLimitIsTheSceneExtent) {
  scene::Scene scene;
  scene.camera.far = 100.0f;
  scene.bounds.expand(glm::vec3(-15.0f, 0.0f, -7.0f));
  scene.bounds.expand(glm::vec3(15.0f, 8.0f, 7.0f));
  EXPECT_NEAR(drag_limit(scene), glm::length(glm::vec3(30.0f, 8.0f, 14.0f)), 1e-3f);
  scene.lights.push_back(point_light("far", {40.0f, 2.0f, 0.0f}));
  EXPECT_NEAR(drag_limit(scene), glm::length(glm::vec3(55.0f, 8.0f, 14.0f)), 1e-3f);
  scene.camera.far = 20.0f;
  EXPECT_NEAR(drag_limit(scene), 20.0f, 1e-3f);
  EXPECT_NEAR(drag_limit(scene::Scene{}), 1.0f, 1e-6f);
}

// The default scene as a new user opens it: every light dragged from the scene's camera
// to points over the floor at its height lands under the cursor, within 5 cm.
TEST(Viewport, EveryAtriumLightLandsOverTheFloorWhereItIsDropped) {
  const auto loaded = scene::load_scene_file(ANTUMBRA_SOURCE_DIR "/data/scenes/atrium.json");
  ASSERT_TRUE(loaded.ok());
  const scene::Scene& atrium = loaded.value();
  const glm::ivec2 image{1280, 720};
  const ViewportCamera view(atrium.camera);
  const scene::Camera& camera = view.camera();
  const float limit = drag_limit(atrium);
  const auto on_image = [&](const std::optional<glm::vec2>& p) {
    return p && p->x >= 0.0f && p->y >= 0.0f && p->x <= static_cast<float>(image.x) &&
           p->y <= static_cast<float>(image.y);
  };
  int drags = 0;
  for (const auto& light : atrium.lights) {
    if (light.type == scene::LightType::directional) continue;
    const auto at = project(camera, image, light.position);
    if (!on_image(at)) continue;
    for (float x = -13.0f; x <= 13.0f; x += 3.25f) {
      for (float z = -6.0f; z <= 6.0f; z += 2.0f) {
        const glm::vec3 target{x, light.position.y, z};
        const auto cursor = project(camera, image, target);
        if (!on_image(cursor)) continue;
        const LightDrag drag(light.position, camera, image, *at, DragPlane::horizontal, limit);
        ASSERT_FALSE(drag.switched()) << light.name;
        // The cursor's path in steps, as a hand moves it: every step follows the ray.
        std::optional<glm::vec3> moved;
        for (int i = 1; i <= 8; ++i) {
          moved = drag.update(*at + (*cursor - *at) * (static_cast<float>(i) / 8.0f));
        }
        ASSERT_TRUE(moved.has_value()) << light.name << " to " << x << ", " << z;
        EXPECT_LT(glm::distance(*moved, target), 0.05f) << light.name << " to " << x << ", " << z;
        ++drags;
      }
    }
  }
  EXPECT_GT(drags, 200);
}

// The atrium's camera raised to the lights' height (2.3 m): every horizontal drag is
// edge-on, moves to the upright plane, and the light still ends under the cursor.
TEST(Viewport, AtriumDragsAtTheLightsHeightStayUnderTheCursor) {
  const auto loaded = scene::load_scene_file(ANTUMBRA_SOURCE_DIR "/data/scenes/atrium.json");
  ASSERT_TRUE(loaded.ok());
  const glm::ivec2 image{1280, 720};
  ViewportCamera view(loaded.value().camera);
  view.move({0.0f, 1.0f, 0.0f}, 2.3f - view.camera().position.y);
  const scene::Camera& camera = view.camera();
  ASSERT_NEAR(camera.position.y, 2.3f, 1e-4f);
  int drags = 0;
  for (const auto& light : loaded.value().lights) {
    if (light.type == scene::LightType::directional || light.position.y != 2.3f) continue;
    const auto at = project(camera, image, light.position);
    if (!at || at->x < 0.0f || at->x > 1280.0f || at->y < 0.0f || at->y > 720.0f) continue;
    const LightDrag drag(light.position, camera, image, *at, DragPlane::horizontal,
                         drag_limit(loaded.value()));
    EXPECT_TRUE(drag.switched()) << light.name;
    for (const glm::vec2 step : {glm::vec2(40.0f, 0.0f), glm::vec2(-25.0f, -60.0f)}) {
      const auto moved = drag.update(*at + step);
      ASSERT_TRUE(moved.has_value()) << light.name;
      const auto on_screen = project(camera, image, *moved);
      ASSERT_TRUE(on_screen.has_value());
      EXPECT_LT(glm::distance(*on_screen, *at + step), 0.05f) << light.name;
      EXPECT_LT(glm::distance(*moved, light.position), drag_limit(loaded.value()));
    }
    ++drags;
  }
  EXPECT_GT(drags, 3);
}

TEST(Viewport, TheRangeSilhouetteIsTangentToTheSphere) {
  scene::Camera camera;
  camera.position = {0.0f, 4.0f, 12.0f};
  camera.target = {0.0f, 1.0f, 0.0f};
  const glm::vec3 centre{1.0f, 1.0f, -2.0f};
  const float radius = 3.0f;
  const auto outline = sphere_outline(camera, kImage, centre, radius, 48);
  ASSERT_EQ(outline.size(), 2u);  // silhouette + horizontal great circle, both whole
  ASSERT_EQ(outline[0].size(), 49u);
  for (const glm::vec2 pixel : outline[0]) {
    EXPECT_NEAR(distance_to_ray(ray_through(camera, kImage, pixel), centre), radius, 1e-2f);
  }
  for (const glm::vec2 pixel : outline[1]) {  // the equator: its rays cross y = centre.y
    const Ray ray = ray_through(camera, kImage, pixel);
    const auto hit = intersect_plane(ray, centre, {0.0f, 1.0f, 0.0f}, 1000.0f);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(glm::distance(*hit, centre), radius, 1e-2f);
  }
}

TEST(Viewport, AnOutlineAroundTheCameraIsCutAtTheNearPlane) {
  const scene::Camera camera = looking_down_minus_z();
  const auto outline = sphere_outline(camera, kImage, camera.position, 5.0f, 64);
  ASSERT_EQ(outline.size(), 1u);  // no silhouette from inside; half the equator is behind
  EXPECT_LT(outline[0].size(), 40u);
  for (const glm::vec2 pixel : outline[0]) {
    EXPECT_TRUE(std::isfinite(pixel.x) && std::isfinite(pixel.y));
  }
  EXPECT_TRUE(sphere_outline(camera, kImage, {0.0f, 0.0f, 0.0f}, 0.0f).empty());
  EXPECT_TRUE(sphere_outline(camera, kImage, {0.0f, 0.0f, 0.0f}, INFINITY).empty());
}

TEST(Viewport, FlyingLooksAndMovesInCameraAxes) {
  ViewportCamera view(looking_down_minus_z());
  expect_near(view.camera().position, {0.0f, 2.0f, 10.0f}, 1e-5f);
  expect_near(view.camera().target, {0.0f, 2.0f, 0.0f}, 1e-4f);
  view.move({0.0f, 0.0f, 1.0f}, 2.0f);  // W
  expect_near(view.camera().position, {0.0f, 2.0f, 8.0f}, 1e-5f);
  view.move({1.0f, 0.0f, 0.0f}, 1.0f);  // D
  expect_near(view.camera().position, {1.0f, 2.0f, 8.0f}, 1e-5f);
  view.move({0.0f, 1.0f, 0.0f}, 0.5f);  // E
  expect_near(view.camera().position, {1.0f, 2.5f, 8.0f}, 1e-5f);
  const glm::vec3 before = view.camera().forward();
  view.look({100.0f, 0.0f});  // mouse right: turn right
  EXPECT_GT(view.camera().forward().x, 0.0f);
  expect_near(view.camera().position, {1.0f, 2.5f, 8.0f}, 1e-5f);
  view.look({-100.0f, 0.0f});
  expect_near(view.camera().forward(), before, 1e-5f);
  view.look({0.0f, -1e6f});  // far past straight up: clamped, never flipped
  EXPECT_GT(view.camera().forward().y, 0.99f);
  EXPECT_LT(view.camera().forward().y, 1.0f);
  EXPECT_TRUE(std::isfinite(view.camera().view()[0][0]));
}

TEST(Viewport, OrbitingKeepsThePivotAndItsDistance) {
  ViewportCamera view(looking_down_minus_z());
  const glm::vec3 light{2.0f, 1.0f, -1.0f};
  view.set_pivot(light);
  expect_near(view.camera().position, {0.0f, 2.0f, 10.0f}, 1e-5f);  // turned, not moved
  expect_near(view.pivot(), light, 1e-4f);
  const float distance = glm::distance(view.camera().position, light);
  view.orbit({150.0f, 40.0f});
  expect_near(view.pivot(), light, 1e-4f);
  EXPECT_NEAR(glm::distance(view.camera().position, light), distance, 1e-3f);
  view.dolly(1.0f);
  EXPECT_NEAR(glm::distance(view.camera().position, light), distance * 0.85f, 1e-3f);
  view.dolly(100.0f);
  EXPECT_NEAR(view.distance(), 0.05f, 1e-6f);  // never through the pivot
  view.dolly(-10000.0f);
  EXPECT_LE(view.distance(), view.camera().far);  // never to infinity
  EXPECT_TRUE(std::isfinite(view.camera().position.x));
  view.reset(looking_down_minus_z());
  expect_near(view.camera().target, {0.0f, 2.0f, 0.0f}, 1e-4f);
}

}  // namespace
}  // namespace antumbra::editor
