// The host's scene through calls (docs/integration.md): a scene built with
// scene::SceneBuilder, no file, rendered through the default graph (layered-ssss.json), then
// changed per frame with RenderSession::set_lights and set_mesh_transform.
//
// A floor, a box floating over it, a lamp above one side of it and a small light in a far
// corner. The lamp moves to its mirror image across the plane x = 0: the box's shadow jumps
// to the other side (the image changes there). Far from both shadows the image keeps its
// colour: where neither lamp position reaches (the corner light's pool, the floor behind),
// pixel for pixel; on the plane of symmetry between the shadows, where the lamp shines
// from the same distance and angle before and after, each pixel as its mirror image.
// Pixels are found by projecting known world points with the scene's camera.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_builder.hpp"
#include "common/shadow_faces.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr VkExtent2D kView{160, 90};
constexpr glm::vec3 kBoxCentre{0.0f, 1.2f, 0.0f};
constexpr float kBoxSize = 0.6f;
constexpr glm::vec3 kLampLeft{-1.2f, 3.0f, 0.0f};
constexpr glm::vec3 kLampRight{1.2f, 3.0f, 0.0f};
// The lamp lights the floor within 7.4 m of the point under it; the floor reaches 10 m.
constexpr float kLampRange = 8.0f;
// A second light at the back, where the lamp never reaches, far from the box.
constexpr glm::vec3 kFarLight{-6.0f, 1.5f, -8.0f};
constexpr float kFarRange = 2.5f;
constexpr int kSame = 3;      // 1/255 steps: unchanged within rasterisation noise
constexpr int kChanged = 20;  // the box's umbra against the lit floor

scene::PointLight lamp(const glm::vec3& position) {
  return {
      .name = "lamp", .position = position, .intensity = 15.0f, .range = kLampRange, .size = 0.1f};
}

scene::Camera camera() {
  scene::Camera c;
  c.position = {0.0f, 5.0f, 6.0f};
  c.target = {0.0f, 0.3f, 0.0f};
  c.fov_y_degrees = 50.0f;
  c.near = 0.1f;
  c.far = 40.0f;
  return c;
}

scene::Scene host_scene(const glm::vec3& lamp_at, const glm::vec3& box_at, bool box_dynamic) {
  scene::SceneBuilder builder;
  builder.set_name("host-scene");
  builder.set_camera(camera());
  builder.set_ambient(glm::vec3(0.03f));
  const auto grey =
      builder.add_material({.name = "grey", .albedo = glm::vec3(0.7f), .roughness = 1.0f});
  const scene::Mesh floor = scene::make_plane({20.0f, 20.0f});
  builder.add_mesh("floor", floor.vertices, floor.indices, grey);
  const scene::Mesh box = scene::make_box(glm::vec3(kBoxSize));
  builder.add_mesh("box", box.vertices, box.indices, grey, glm::translate(glm::mat4(1.0f), box_at),
                   box_dynamic);
  builder.add_light(lamp(lamp_at));
  builder.add_light({.name = "far", .position = kFarLight, .intensity = 2.0f, .range = kFarRange});
  return builder.build();
}

// Where the ray from `light` through `p` meets the floor (y = 0).
glm::vec3 on_floor(const glm::vec3& light, const glm::vec3& p) {
  return light + (p - light) * (light.y / (light.y - p.y));
}

glm::ivec2 pixel_of(const glm::vec3& p) {
  const float aspect = static_cast<float>(kView.width) / static_cast<float>(kView.height);
  const glm::vec4 clip = camera().view_projection(aspect) * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;  // y = -1 at the top (camera.hpp)
  return {static_cast<int>((ndc.x * 0.5f + 0.5f) * static_cast<float>(kView.width)),
          static_cast<int>((ndc.y * 0.5f + 0.5f) * static_cast<float>(kView.height))};
}

// Mean of r, g, b over the 3x3 pixels around `at`.
double brightness(const Image8& image, glm::ivec2 at) {
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const std::size_t texel =
          static_cast<std::size_t>(at.y + dy) * image.width + static_cast<std::size_t>(at.x + dx);
      for (std::size_t c = 0; c < 3; ++c) sum += image.bytes[texel * image.channels + c];
    }
  }
  return sum / 27.0;
}

// Largest per-channel difference between the 3x3 pixels of `a` around `at` and those of
// `b` there, or (`mirrored`) at their mirror images across the image's middle column.
int largest_difference(const Image8& a, const Image8& b, glm::ivec2 at, bool mirrored = false) {
  const auto texel = [&](int x, int y) {
    return static_cast<std::size_t>(y) * a.width + static_cast<std::size_t>(x);
  };
  int out = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = at.x + dx;
      const int x_in_b = mirrored ? static_cast<int>(a.width) - 1 - x : x;
      for (std::size_t c = 0; c < 3; ++c) {
        const int va = a.bytes[texel(x, at.y + dy) * a.channels + c];
        const int vb = b.bytes[texel(x_in_b, at.y + dy) * b.channels + c];
        out = std::max(out, std::abs(va - vb));
      }
    }
  }
  return out;
}

struct FaceCounts {
  std::uint32_t rendered = 0;
  std::uint32_t cached = 0;
  std::uint32_t dynamic = 0;
};

// The shadow atlas's counts of the last frame (SHD010).
FaceCounts face_counts(const runtime::RenderSession& session) {
  for (const auto& m : session.last_report().messages()) {
    if (m.code != "SHD010") continue;
    return {m.details["rendered"].get<std::uint32_t>(), m.details["cached"].get<std::uint32_t>(),
            m.details["dynamic"].get<std::uint32_t>()};
  }
  ADD_FAILURE() << "no SHD010 report of the shadow atlas";
  return {};
}

// The faces of `lights` whose frustum a box at `from` or at `to` may reach: those a move
// from one to the other may redraw (the planner's own test, shadow_faces::box_may_touch).
std::uint32_t faces_touched(const std::vector<scene::PointLight>& lights, const glm::vec3& from,
                            const glm::vec3& to) {
  namespace sf = passes::shadow_faces;
  const glm::vec3 half(kBoxSize * 0.5f);
  std::uint32_t count = 0;
  for (const scene::PointLight& light : lights) {
    for (std::uint32_t face = 0; face < sf::kFaceCount; ++face) {
      const glm::mat4 view_proj = sf::face_view_proj(light.position, face, 0.05f, light.range);
      if (sf::box_may_touch(view_proj, {from - half, from + half}) ||
          sf::box_may_touch(view_proj, {to - half, to + half})) {
        ++count;
      }
    }
  }
  return count;
}

class HostSceneTest : public RenderTest {
 protected:
  Image8 render_frames(runtime::RenderSession& session, int frames) {
    session.render(frames, nullptr);
    return to_image8(read_output(session));
  }

  // After a failure: the two images and their difference, for a look.
  void keep_images(const std::string& name, const Image8& expected, const Image8& actual) {
    if (!HasFailure()) return;
    const auto dir = artifact_dir() / name;
    std::filesystem::create_directories(dir);
    write_failure_images(dir, expected, actual);
    std::cout << "images of '" << name << "' in " << dir.string() << "\n";
  }
};

std::string describe_point(const glm::vec3& p, glm::ivec2 at) {
  return "floor point (" + std::to_string(p.x) + ", " + std::to_string(p.z) + ") at pixel " +
         std::to_string(at.x) + "," + std::to_string(at.y);
}

}  // namespace

TEST_F(HostSceneTest, MovedLightMovesTheShadowAndNothingFarFromIt) {
  OPEN_SESSION(session, kView);
  load_graph_ok(*session, load_graph_file(source_dir() / "data/graphs/layered-ssss.json"));
  scene::Scene scene = host_scene(kLampLeft, kBoxCentre, /*box_dynamic=*/false);
  std::vector<scene::PointLight> lights = scene.lights;
  session->set_scene(std::move(scene));
  const Image8 before = render_frames(*session, 3);
  lights[0] = lamp(kLampRight);
  session->set_lights(lights);
  const Image8 after = render_frames(*session, 2);
  // A brighter lamp where it stands keeps its shadow faces (docs/integration.md).
  lights[0].intensity *= 2.0f;
  session->set_lights(lights);
  render_frames(*session, 1);
  EXPECT_EQ(face_counts(*session).rendered, 0u) << "a new intensity redraws no face";
  expect_no_validation_errors(*session);

  // The centres of the box's shadow under each lamp: dark under one, lit under the other.
  const glm::ivec2 left_shadow = pixel_of(on_floor(kLampLeft, kBoxCentre));
  const glm::ivec2 right_shadow = pixel_of(on_floor(kLampRight, kBoxCentre));
  EXPECT_GT(brightness(after, left_shadow) - brightness(before, left_shadow), kChanged)
      << "the lamp's first shadow is lit once it moved, at pixel " << left_shadow.x << ","
      << left_shadow.y;
  EXPECT_GT(brightness(before, right_shadow) - brightness(after, right_shadow), kChanged)
      << "the box shadows the other side, at pixel " << right_shadow.x << "," << right_shadow.y;
  // Beyond the lamp's reach from either place: the far light's pool and the floor behind.
  for (const glm::vec3 p : {glm::vec3(-6, 0, -8), glm::vec3(-5, 0, -8.5f), glm::vec3(0, 0, -8)}) {
    ASSERT_GT(glm::length(p - kLampLeft), kLampRange) << "the lamp reaches " << p.x << "," << p.z;
    ASSERT_GT(glm::length(p - kLampRight), kLampRange);
    EXPECT_LE(largest_difference(before, after, pixel_of(p)), kSame)
        << describe_point(p, pixel_of(p));
  }
  // Between the shadows on the plane of symmetry (the image's middle column), in front of
  // the box: the lamp shines there as before, from the mirror side.
  for (const glm::vec3 p : {glm::vec3(0, 0, 1.5f), glm::vec3(0, 0, 2.5f)}) {
    EXPECT_LE(largest_difference(before, after, pixel_of(p), /*mirrored=*/true), kSame)
        << describe_point(p, pixel_of(p));
  }
  keep_images("lamp-moved", before, after);
}

// A scene file's object motion follows the frames since RenderSession::restart_motion (bench
// calls it per scenario, so a row measures the same frames whatever ran before it): two
// frames into a period of eight the box stands 2.4 m aside and the lamp lights where its
// shadow was; restarted, the next frame is frame 0's image again.
TEST_F(HostSceneTest, RestartedMotionRendersFrameZeroAgain) {
  OPEN_SESSION(session, kView);
  load_graph_ok(*session, load_graph_file(source_dir() / "data/graphs/layered-ssss.json"));
  scene::Scene scene = host_scene(kLampLeft, kBoxCentre, /*box_dynamic=*/true);
  scene::DynamicObject box{.name = "box", .meshes = {1}, .base = {scene.meshes.at(1).transform}};
  ASSERT_TRUE(scene.meshes.at(1).dynamic);
  box.pivot = kBoxCentre;
  box.moves = true;
  box.motion = {.offset = {2.4f, 0.0f, 0.0f}, .period = 8};
  scene.dynamic_objects.push_back(box);
  session->set_scene(std::move(scene));
  session->restart_motion();  // as bench does: whatever frames the session rendered before
  const Image8 first = render_frames(*session, 1);  // motion frame 0
  const Image8 moved = render_frames(*session, 2);  // frame 2: the offset's whole 2.4 m
  session->restart_motion();
  const Image8 again = render_frames(*session, 1);
  expect_no_validation_errors(*session);

  const glm::ivec2 shadow = pixel_of(on_floor(kLampLeft, kBoxCentre));
  EXPECT_GT(brightness(moved, shadow) - brightness(first, shadow), kChanged)
      << "the box left its first shadow, at pixel " << shadow.x << "," << shadow.y << ": "
      << brightness(first, shadow) << " -> " << brightness(moved, shadow);
  int worst = 0;
  for (int y = 1; y + 1 < static_cast<int>(kView.height); y += 3) {
    for (int x = 1; x + 1 < static_cast<int>(kView.width); x += 3) {
      worst = std::max(worst, largest_difference(first, again, {x, y}));
    }
  }
  EXPECT_LE(worst, kSame) << "the restarted motion's first frame is frame 0's image";
  keep_images("motion-restarted", first, again);
}

// The box built dynamic moves with set_mesh_transform: next frame its shadow moved and the
// atlas redrew only faces the box left or entered, fewer than it holds; the image is the
// one of a scene built with the box there.
TEST_F(HostSceneTest, MovedMeshRedrawsOnlyTheFacesItTouches) {
  OPEN_SESSION(session, kView);
  load_graph_ok(*session, load_graph_file(source_dir() / "data/graphs/layered-ssss.json"));
  scene::Scene scene = host_scene(kLampLeft, kBoxCentre, /*box_dynamic=*/true);
  const std::vector<scene::PointLight> lights = scene.lights;
  session->set_scene(std::move(scene));
  const Image8 start = render_frames(*session, 3);
  const FaceCounts still = face_counts(*session);
  EXPECT_EQ(still.rendered, 0u) << "nothing changed: every face comes from the cache";

  const glm::vec3 moved_to = kBoxCentre + glm::vec3(0.6f, 0.0f, 0.8f);
  session->set_mesh_transform(1, glm::translate(glm::mat4(1.0f), moved_to));
  const Image8 moved = render_frames(*session, 1);
  const FaceCounts redrawn = face_counts(*session);
  const std::uint32_t touched = faces_touched(lights, kBoxCentre, moved_to);
  EXPECT_GT(redrawn.rendered, 0u) << "the box's move redrew the faces it crossed";
  EXPECT_EQ(redrawn.dynamic, redrawn.rendered) << "every redraw is the box's";
  EXPECT_LE(redrawn.rendered, touched) << "only faces the box reaches";
  EXPECT_LT(touched, still.cached) << "the box reaches some of the faces in use, not all";
  for (const glm::vec3& at : {kBoxCentre, moved_to}) {
    const glm::ivec2 shadow = pixel_of(on_floor(kLampLeft, at));
    EXPECT_GT(largest_difference(start, moved, shadow), kChanged)
        << "the shadow left and entered " << describe_point(on_floor(kLampLeft, at), shadow);
  }
  const Image8 steady = render_frames(*session, 1);
  EXPECT_EQ(face_counts(*session).rendered, 0u) << "a box that stays put redraws nothing";
  expect_no_validation_errors(*session);
  keep_images("box-moved", start, moved);

  // The same frame from a scene built with the box there (static: the whole atlas drawn).
  session->set_scene(host_scene(kLampLeft, moved_to, /*box_dynamic=*/false));
  const Image8 fresh = render_frames(*session, 2);
  const DiffStats stats = diff_images(fresh, steady, kSame);
  EXPECT_EQ(stats.pixels_over, 0u) << describe(stats);
  keep_images("fresh-against-moved", fresh, steady);
  expect_no_validation_errors(*session);
}

TEST_F(HostSceneTest, SetMeshTransformRefusesStaticMeshesByName) {
  OPEN_SESSION(session, kView);
  try {
    session->set_mesh_transform(0, glm::mat4(1.0f));
    ADD_FAILURE() << "a mesh moved before any scene";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("before set_scene()"), std::string::npos) << e.what();
  }
  session->set_scene(host_scene(kLampLeft, kBoxCentre, /*box_dynamic=*/false));
  try {
    session->set_mesh_transform(1, glm::mat4(1.0f));
    ADD_FAILURE() << "a static mesh moved";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mesh 1 'box'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(session->set_mesh_transform(2, glm::mat4(1.0f)), std::invalid_argument);
}
