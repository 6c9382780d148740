// point-shadow-atlas on a device (lavapipe in CI): the atrium atlas with validation and
// synchronization validation on, an analytic depth check, static caching, per-light
// invalidation, the per-face fallback and CPU/GLSL agreement of the sampling include.
// The executor is driven directly (not through RenderSession) so that a test can move a
// light without re-uploading the geometry.

#include "atlas_gpu_fixture.hpp"

#include <algorithm>
#include <cmath>

#include "common/light_faces.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

TEST_F(AtlasGpuTest, RendersAtriumAndFloorDepthIsAnalytic) {
  load();
  const Counts c = frame();
  EXPECT_TRUE(c.layered) << "lavapipe supports shaderOutputLayer";
  EXPECT_EQ(c.total, 96u);
  EXPECT_GT(c.culled, 0u);
  EXPECT_EQ(c.rendered, c.total - c.culled);
  const auto texels = read_layer(6 * kLight + 3);  // -Y face
  ASSERT_FLOAT_EQ(scene_.lights[kLight].position.y, kLightHeight);
  // The floor is perpendicular to the -Y axis, so every floor texel linearises to h.
  EXPECT_NEAR(centre_linear_depth(texels, scene_.lights[kLight]), kLightHeight, 0.02f);
  EXPECT_NEAR(sf::linearise(texels[std::size_t{40} * kFace + 200], 0.05f, 3.8f), kLightHeight,
              0.02f);
  std::printf("atrium faces: %u total, %u culled, %u rendered, %u cached\n", c.total, c.culled,
              c.rendered, c.cached);
}

TEST_F(AtlasGpuTest, CachedSecondFrameRendersNothingAndKeepsContents) {
  load();
  const Counts first = frame();
  const auto before = read_layer(6 * kLight + 3);
  const Counts second = frame();
  EXPECT_EQ(second.rendered, 0u);
  EXPECT_EQ(second.cached, first.rendered);
  const Counts third = frame();  // the other frame-in-flight slot as well
  EXPECT_EQ(third.rendered, 0u);
  EXPECT_EQ(read_layer(6 * kLight + 3), before);
}

TEST_F(AtlasGpuTest, MovingOneLightRerendersExactlyItsVisibleFaces) {
  load();
  frame();
  const auto other_before = read_layer(6 * 1 + 3);
  scene_.lights[kLight].position.y -= 0.5f;
  const auto frustum = sf::camera_frustum(scene_.camera.view_projection(160.0f / 90.0f));
  const auto mask =
      sf::visible_faces(frustum, scene_.lights[kLight].position, scene_.lights[kLight].range);
  const Counts c = frame();
  EXPECT_EQ(c.rendered, static_cast<std::uint32_t>(__builtin_popcount(mask)));
  EXPECT_NEAR(centre_linear_depth(read_layer(6 * kLight + 3), scene_.lights[kLight]),
              kLightHeight - 0.5f, 0.02f);
  EXPECT_EQ(read_layer(6 * 1 + 3), other_before);
}

TEST_F(AtlasGpuTest, PerFaceFallbackMatchesLayeredDraw) {
  load(base::Json{{"layeredDraw", false}});
  const Counts c = frame();
  EXPECT_FALSE(c.layered);
  EXPECT_GT(c.rendered, 0u);
  const auto fallback = read_layer(6 * kLight + 3);
  EXPECT_NEAR(centre_linear_depth(fallback, scene_.lights[kLight]), kLightHeight, 0.02f);
  load();
  frame();
  const auto layered = read_layer(6 * kLight + 3);
  EXPECT_EQ(layered, fallback);
}

namespace {

// tests/data/shadows/atlas.json as parsed, for the compiler checks below to change.
base::Result<fg::GraphDesc> atlas_graph() {
  auto document = base::load_json_file((source_dir() / "tests/data/shadows/atlas.json").string());
  if (!document.ok()) return document.diagnostics();
  return fg::parse_graph(document.value());
}

}  // namespace

// A compiler check (validate reports it without a device), located at the binding.
TEST_F(AtlasGpuTest, TooSmallShadowDataIsACompilerError) {
  auto graph = atlas_graph();
  ASSERT_TRUE(graph.ok());
  for (auto& r : graph.value().resources) {
    if (r.name == "shadowData") r.buffer_size = 1024;
  }
  fg::CompileOptions options;
  options.viewport = {kViewport.width, kViewport.height};
  options.footprint = executor_->footprint_fn();
  auto plan = fg::compile(graph.value(), registry_->reflection(), options);
  ASSERT_FALSE(plan.ok());
  const base::Diagnostic* d = plan.diagnostics().find("SHD001");
  ASSERT_NE(d, nullptr) << plan.diagnostics().to_text();
  EXPECT_NE(d->message.find("269840"), std::string::npos) << d->message;
  EXPECT_EQ(d->pointer.rfind("/passes/", 0), 0u) << d->pointer;
  EXPECT_GT(d->line, 0);
}

// The compute rasteriser's page lists name a face's 128^2 pages in 15 bits (pages.h): an
// atlas with larger faces is refused at the atlas binding, with the limit.
TEST_F(AtlasGpuTest, ComputeAtlasFacesPastThePageListsAreACompilerError) {
  auto graph = atlas_graph();
  ASSERT_TRUE(graph.ok());
  const auto compile_with = [&](std::uint32_t side) {
    for (auto& r : graph.value().resources) {
      if (r.name == "atlas" || r.name == "shadowColour") {
        r.size = {false, 1.0, 1.0, side, side};
        r.layers = 6;
      }
      if (r.name == "atlas") r.format = fg::Format::r32f;
      if (r.name == "shadowData") r.buffer_size = passes::shadow_data_bytes(6);
    }
    for (auto& p : graph.value().passes) {
      if (p.type == "point-shadow-atlas") p.params["rasterizer"] = "compute";
    }
    fg::CompileOptions options;
    options.viewport = {kViewport.width, kViewport.height};
    return fg::compile(graph.value(), registry_->reflection(), options);
  };
  const auto large = compile_with(23296);
  ASSERT_FALSE(large.ok());
  const base::Diagnostic* d = large.diagnostics().find("SHD007");
  ASSERT_NE(d, nullptr) << large.diagnostics().to_text();
  EXPECT_NE(d->message.find("23168"), std::string::npos) << d->message;
  EXPECT_EQ(compile_with(16384).diagnostics().find("SHD007"), nullptr);
}

// A face record names its layer in 11 bits (shadow_data.h): more layers are refused at the
// atlas binding, with the limit, before anything is allocated.
TEST_F(AtlasGpuTest, MoreLayersThanAFaceCanNameIsACompilerError) {
  auto graph = atlas_graph();
  ASSERT_TRUE(graph.ok());
  for (auto& r : graph.value().resources) {
    if (r.name == "atlas" || r.name == "shadowColour") {
      r.layers = 2049;
      r.size = {false, 1.0, 1.0, 16, 16};
    }
    if (r.name == "shadowData") r.buffer_size = passes::shadow_data_bytes(2049);
  }
  fg::CompileOptions options;
  options.viewport = {kViewport.width, kViewport.height};
  auto plan = fg::compile(graph.value(), registry_->reflection(), options);
  ASSERT_FALSE(plan.ok());
  const base::Diagnostic* d = plan.diagnostics().find("SHD006");
  ASSERT_NE(d, nullptr) << plan.diagnostics().to_text();
  EXPECT_NE(d->message.find("2049 layers"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("2048"), std::string::npos) << d->message;
  EXPECT_EQ(d->pointer.rfind("/passes/", 0), 0u) << d->pointer;
  for (auto& r : graph.value().resources) {
    if (r.name == "atlas" || r.name == "shadowColour") r.layers = 2048;
  }
  EXPECT_EQ(
      fg::compile(graph.value(), registry_->reflection(), options).diagnostics().find("SHD006"),
      nullptr);
}

TEST_F(AtlasGpuTest, SamplingIncludeAgreesWithCpuFaceMath) {
  // One light, its six faces, and points all round it.
  const glm::vec3 light(1.0f, 2.0f, -1.5f);
  const float range = 4.0f;
  const std::size_t data_bytes = passes::shadow_data_bytes(6);
  std::vector<std::byte> data(data_bytes);
  passes::ShadowLight l;
  l.position_range = glm::vec4(light, range);
  l.params = glm::vec4(0.1f, 0.05f, 0.0f, 0.0f);
  std::memcpy(data.data() + passes::kShadowLightsOffset, &l, sizeof l);
  for (std::uint32_t f = 0; f < 6; ++f) {
    passes::ShadowFace face;
    face.view_proj = sf::face_view_proj(light, f, 0.05f, range);
    face.info = {0u, passes::encode_face_info(f, {.layer = f}), 1u, 0u};
    std::memcpy(data.data() + passes::kShadowFacesOffset + f * sizeof face, &face, sizeof face);
  }
  std::vector<glm::vec4> points;
  for (int i = 0; i < 512; ++i) {
    const float a = 0.37f * static_cast<float>(i);
    const float b = 0.11f * static_cast<float>(i);
    const glm::vec3 d(std::cos(a) * std::cos(b), std::sin(b * 1.7f), std::sin(a) * std::cos(b));
    points.emplace_back(light + d * (0.2f + 3.5f * static_cast<float>(i % 17) / 17.0f), 1.0f);
  }
  const std::vector<glm::vec4> out = run_sampling_check(data, points);
  ASSERT_EQ(out.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 p(points[i]);
    const std::uint32_t face = sf::cube_face(p - light);
    const auto s = sf::project(sf::face_view_proj(light, face, 0.05f, range), p);
    ASSERT_EQ(static_cast<std::uint32_t>(out[i].x), face) << i;
    if (s.linear <= 0.05f) {  // nearer than the near plane: no coordinate (reads as lit)
      EXPECT_EQ(out[i].w, -1.0f) << i;
      continue;
    }
    EXPECT_NEAR(out[i].y, s.uv.x, 1e-4f) << i;
    EXPECT_NEAR(out[i].z, s.uv.y, 1e-4f) << i;
    EXPECT_NEAR(out[i].w, s.depth, 1e-4f) << i;
  }
}

namespace {

// A sun's cascades as the planner fits them for the atrium camera.
TEST_F(AtlasGpuTest, CascadePickAgreesWithCpuMirror) {
  scene::Scene sun_scene = scene_;
  sun_scene.lights.resize(1);
  sun_scene.lights[0].type = scene::LightType::directional;
  sun_scene.lights[0].direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.2f));
  passes::AtlasPlanner planner;
  passes::AtlasSettings settings;
  settings.layers = 4;
  settings.face_size = 1024;
  settings.sun_max_distance = 30.0f;
  settings.camera_near = sun_scene.camera.near;
  settings.camera_far = sun_scene.camera.far;
  const glm::mat4 view_proj = sun_scene.camera.view_projection(16.0f / 9.0f);
  const passes::AtlasFrame& frame = planner.plan(sun_scene, view_proj, 1, 0, settings);
  ASSERT_EQ(std::floor(frame.lights[0].projection.w), 4.0f);
  std::vector<std::byte> data(passes::shadow_data_bytes(4));
  std::memcpy(data.data() + passes::kShadowLightsOffset, frame.lights.data(),
              sizeof(passes::ShadowLight));
  std::memcpy(data.data() + passes::kShadowFacesOffset, frame.faces.data(),
              4 * sizeof(passes::ShadowFace));
  // Points through the camera frustum out past the last cascade.
  std::vector<glm::vec4> points;
  const glm::mat4 inverse = glm::inverse(view_proj);
  for (int i = 0; i < 1024; ++i) {
    const float x = -1.0f + 2.0f * static_cast<float>(i % 32) / 31.0f;
    const float row = std::floor(static_cast<float>(i) / 32.0f);
    const float d = 0.2f * std::pow(300.0f, row / 31.0f);  // 0.2..60 m
    const float z = sun_scene.camera.far * (d - sun_scene.camera.near) /
                    (d * (sun_scene.camera.far - sun_scene.camera.near));
    const glm::vec4 h = inverse * glm::vec4(x, 0.37f * x, std::clamp(z, 0.0f, 1.0f), 1.0f);
    points.emplace_back(glm::vec3(h) / h.w, 1.0f);
  }
  const std::vector<glm::vec4> out = run_sampling_check(data, points);
  ASSERT_EQ(out.size(), points.size());
  std::vector<glm::mat4> cascades;
  for (std::uint32_t c = 0; c < 4; ++c) cascades.push_back(frame.faces[c].view_proj);
  const float band = frame.lights[0].projection.w - 4.0f;
  int seen[5] = {};
  int blended = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto pick = passes::light_faces::pick_cascade(cascades, band, glm::vec3(points[i]));
    // Points right at a band's edge may round either way: allow a tiny blend mismatch.
    ASSERT_EQ(static_cast<int>(out[i].x), pick.index) << i;
    EXPECT_EQ(static_cast<int>(out[i].y), pick.next) << i;
    EXPECT_NEAR(out[i].z, pick.blend, 1e-3f) << i;
    ++seen[pick.index + 1];
    blended += pick.next >= 0 ? 1 : 0;
  }
  for (int c = 0; c < 4; ++c) EXPECT_GT(seen[c + 1], 0) << "cascade " << c << " never picked";
  EXPECT_GT(seen[0], 0) << "points beyond the last cascade";
  EXPECT_GT(blended, 0) << "blend bands";
}

}  // namespace
