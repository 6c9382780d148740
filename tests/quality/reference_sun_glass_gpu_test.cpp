// The shadow reference covers every light the technique shadows (lavapipe, validation
// and synchronization validation on, like every GPU test here):
//  - the directional sun, averaged over directions spread on its disc: on an analytic
//    scene its penumbra width matches the angular radius;
//  - translucent casters tint instead of blocking: under a glass pane the reference's
//    colour is the pane's transmittance, white beside it, and the layered technique's
//    coloured shadow there agrees with it.
// Visibility is measured per channel as (reference radiance) / (unshadowed radiance of
// deferred.json), so it is the light's coloured visibility where one light shines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/primitives.hpp"
#include "quality_test_support.hpp"
#include "render_test_support.hpp"

namespace antumbra::quality_testing {
namespace {

using render_testing::RenderTest;

constexpr double kSunPi = 3.14159265358979323846;

class ReferenceSunGlassGpu : public RenderTest {
 protected:
  // visibility: the reference's parameter ("shadowMaps", or "rays": traced through the BVH).
  void check_sun_penumbra(runtime::RenderSession* session, const char* visibility);

  // The glass scene's reference (hdr and penumbra count) and unshadowed frames, the
  // reference's bands checked (check_reference_glass, defined below).
  struct GlassFrames {
    app::FloatImage shadowed;
    app::FloatImage unshadowed;
    double metres_per_pixel = 0.0;
  };
  template <typename Setup, typename Check>
  GlassFrames render_glass(runtime::RenderSession& session, const Setup& setup,
                           const char* visibility, const Check& check) {
    GlassFrames f;
    auto reference = graph_for_hdr(graph_path("reference"), {"penumbraCount"});
    set_param(reference, "shadow-reference", "visibility", visibility);
    if (std::string(visibility) == "shadowMaps") {
      set_param(reference, "shadow-reference", "faceSize", 512);
    }
    load_graph_ok(session, reference);
    session.render(1, nullptr);
    f.shadowed = read_float_image(session, "hdr");
    const auto count = read_float_image(session, "penumbraCount");
    EXPECT_TRUE(session.last_report().messages().empty());
    load_graph_ok(session, graph_for_hdr(graph_path("deferred")));
    session.render(1, nullptr);
    f.unshadowed = read_float_image(session, "hdr");
    f.metres_per_pixel = metres_per_pixel(session, setup.camera_height, setup.fov_y_degrees);
    check(f.shadowed, f.unshadowed, count, f.metres_per_pixel);
    return f;
  }

  // Renders `graph` (its hdr) and the unshadowed deferred frame of the session's scene.
  struct Frames {
    app::FloatImage shadowed;
    app::FloatImage unshadowed;
  };
  Frames render_pair(runtime::RenderSession& session, const fg::GraphDesc& graph) {
    Frames f;
    load_graph_ok(session, graph);
    session.render(1, nullptr);
    f.shadowed = read_float_image(session, "hdr");
    for (const auto& m : session.last_report().messages()) {
      ADD_FAILURE() << m.pass << " reported " << m.code << ": " << m.message;
    }
    load_graph_ok(session, graph_for_hdr(graph_path("deferred")));
    session.render(1, nullptr);
    f.unshadowed = read_float_image(session, "hdr");
    return f;
  }

  static double metres_per_pixel(const runtime::RenderSession& session, float camera_height,
                                 float fov_y_degrees) {
    const VkExtent2D e = session.viewport();
    const double aspect = double(e.width) / double(e.height);
    return 2.0 * camera_height * std::tan(fov_y_degrees * 0.5 * kSunPi / 180.0) * aspect /
           double(e.width);
  }
};

// Per-channel visibility averaged over the middle rows, between world x0 and x1 (the
// camera looks straight down at x = centre_x; image x grows with world x).
glm::dvec3 mean_visibility(const app::FloatImage& shadowed, const app::FloatImage& unshadowed,
                           double centre_x, double metres_per_pixel, double x0, double x1,
                           glm::dvec3* worst_low = nullptr, glm::dvec3* worst_high = nullptr) {
  glm::dvec3 sum(0.0);
  glm::dvec3 lo(1e9);
  glm::dvec3 hi(-1e9);
  std::size_t count = 0;
  const double half = 0.5 * shadowed.width;
  for (std::uint32_t y = shadowed.height / 2 - 4; y <= shadowed.height / 2 + 4; ++y) {
    for (std::uint32_t x = 0; x < shadowed.width; ++x) {
      const double wx = centre_x + (double(x) + 0.5 - half) * metres_per_pixel;
      if (wx < x0 || wx > x1) continue;
      glm::dvec3 v(0.0);
      for (int c = 0; c < 3; ++c) {
        const double lit = unshadowed.at(x, y, static_cast<std::uint32_t>(c));
        v[c] = lit > 0.0 ? shadowed.at(x, y, static_cast<std::uint32_t>(c)) / lit : 0.0;
      }
      sum += v;
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
      ++count;
    }
  }
  if (worst_low != nullptr) *worst_low = lo;
  if (worst_high != nullptr) *worst_high = hi;
  return count > 0 ? sum / double(count) : glm::dvec3(-1.0);
}

// The analytic scene (quality_test_support.hpp) lit by the sun straight down instead of
// the point light: the occluder's edge x = 1 at height 2 over the plane, the camera 1.5 m
// above the plane looking down at the edge. A sun disc of angular radius a makes a
// penumbra of full width 2 (d_receiver - d_blocker) tan(a) (the light size of the
// technique, w_light = tan(a), is the disc's radius; the width spans its diameter).
void ReferenceSunGlassGpu::check_sun_penumbra(runtime::RenderSession* session,
                                              const char* visibility) {
  const AnalyticSetup setup;
  const float angular_radius = 5.0f;  // degrees
  scene::Scene s = analytic_scene(setup);
  s.lights[0].type = scene::LightType::directional;
  s.lights[0].name = "sun";
  s.lights[0].direction = {0.0f, -1.0f, 0.0f};
  s.lights[0].size = angular_radius;
  s.lights[0].intensity = 3.0f;
  session->set_scene(s);
  auto reference = graph_for_hdr(graph_path("reference"));
  set_param(reference, "shadow-reference", "faceSize", 512);
  set_param(reference, "shadow-reference", "visibility", visibility);
  const auto frames = render_pair(*session, reference);

  const auto row = visibility_row(frames.shadowed, frames.unshadowed);
  const double low = *std::min_element(row.begin(), row.end());
  const double high = *std::max_element(row.begin(), row.end());
  EXPECT_LT(low, 0.02) << "umbra expected under the occluder";
  EXPECT_GT(high, 0.98) << "full sun expected beside it";
  const double pixels = transition_width(row, low, high);
  ASSERT_GT(pixels, 0.0);
  const double mpp = metres_per_pixel(*session, setup.camera_height, setup.fov_y_degrees);
  const double measured = pixels * mpp / kDiskTenNinety;
  const double expected =
      2.0 * double(setup.blocker) * std::tan(double(angular_radius) * kSunPi / 180.0);
  std::printf(
      "sun penumbra, %s (angular radius %.1f deg): 10-90%% width %.2f px = %.4f m -> full "
      "width %.4f m, 2 (d_r - d_b) tan(a) = %.4f m (ratio %.3f)\n",
      visibility, angular_radius, pixels, pixels * mpp, measured, expected, measured / expected);
  RecordProperty(std::string("sun_penumbra_ratio_") + visibility,
                 std::to_string(measured / expected));
  EXPECT_NEAR(measured / expected, 1.0, 0.05);
}

TEST_F(ReferenceSunGlassGpu, SunPenumbraWidthMatchesAngularRadius) {
  OPEN_SESSION(session, kGolden);
  check_sun_penumbra(session, "shadowMaps");
}

TEST_F(ReferenceSunGlassGpu, SunPenumbraWidthMatchesAngularRadiusRays) {
  OPEN_SESSION(session, kGolden);
  check_sun_penumbra(session, "rays");
}

// A 1 m glass pane (a thin box, like the atrium's panes) 1 m over a plane, under one
// light, the camera between pane and plane looking down at the pane's shadow edge.
struct GlassSetup {
  bool sun = false;            // the sun straight down, else a point light at (0, 3, 0)
  float pane_height = 1.0f;    // centre of the 2 cm thick pane
  float light_height = 3.0f;   // point light
  float camera_height = 0.8f;  // below the pane: the camera sees the floor only
  float fov_y_degrees = 60.0f;
  glm::vec4 transmittance{1.0f, 0.2f, 0.2f, 0.5f};
  // The shadow edge on the floor (the pane spans |x| <= 0.5).
  [[nodiscard]] float edge_x() const {
    return sun ? 0.5f : 0.5f * light_height / (light_height - pane_height);
  }
  // What the technique's colour convention makes of one pane: mix(1, rgb, a).
  [[nodiscard]] glm::dvec3 tint() const {
    return glm::mix(glm::dvec3(1.0), glm::dvec3(transmittance), double(transmittance.a));
  }
};

scene::Scene glass_scene(const GlassSetup& setup) {
  scene::Scene s;
  s.name = "glass-pane";
  scene::Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.8f);
  grey.roughness = 1.0f;
  s.materials.push_back(grey);
  scene::Material glass;
  glass.name = "glass";
  glass.albedo = glm::vec3(setup.transmittance);
  glass.roughness = 0.05f;
  glass.translucent = true;
  glass.transmittance = setup.transmittance;
  s.materials.push_back(glass);

  scene::Mesh plane = scene::make_plane({40.0f, 40.0f});
  plane.name = "floor";
  plane.update_bounds();
  s.meshes.push_back(std::move(plane));
  scene::Mesh pane = scene::make_box({1.0f, 0.02f, 1.0f});
  pane.name = "pane";
  pane.material = 1;
  pane.transform = glm::translate(glm::mat4(1.0f), {0.0f, setup.pane_height, 0.0f});
  pane.update_bounds();
  s.meshes.push_back(std::move(pane));

  scene::PointLight light;
  if (setup.sun) {
    light.name = "sun";
    light.type = scene::LightType::directional;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.size = 2.0f;  // degrees: a 7 cm penumbra 1 m under the pane
    light.intensity = 3.0f;
  } else {
    light.name = "key";
    light.position = {0.0f, setup.light_height, 0.0f};
    light.intensity = 20.0f;
    light.range = 12.0f;
    light.size = 0.1f;  // a 10 cm penumbra: (3 - 2) * 0.2 / 2
  }
  s.lights.push_back(light);

  const float x = setup.edge_x();
  s.camera.position = {x, setup.camera_height, 0.0f};
  s.camera.target = {x, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_degrees = setup.fov_y_degrees;
  s.camera.near = 0.05f;
  s.camera.far = 20.0f;
  s.ambient = glm::vec3(0.0f);
  s.bounds = s.compute_bounds();
  return s;
}

// Tolerances of the glass tests (visibility per channel, 0..1):
constexpr double kTintTolerance = 0.02;     // reference mean under the pane vs mix(1, rgb, a)
constexpr double kTintSpread = 0.03;        // any reference pixel there vs that tint
constexpr double kWhiteTolerance = 0.02;    // reference beside the pane's shadow vs white
constexpr double kLayeredTolerance = 0.06;  // layered technique's mean vs the reference's
// Regions: well inside / outside the shadow edge, clear of the penumbra (point light:
// 10 cm, sun: 7 cm wide) and of the frame's border.
constexpr double kInner = 0.15;  // metres from the edge
constexpr double kOuter = 0.45;

void check_reference_glass(ReferenceSunGlassGpu& test, const GlassSetup& setup,
                           const app::FloatImage& shadowed, const app::FloatImage& unshadowed,
                           const app::FloatImage& count, double mpp) {
  const double edge = setup.edge_x();
  glm::dvec3 lo;
  glm::dvec3 hi;
  const glm::dvec3 under =
      mean_visibility(shadowed, unshadowed, edge, mpp, edge - kOuter, edge - kInner, &lo, &hi);
  const glm::dvec3 beside =
      mean_visibility(shadowed, unshadowed, edge, mpp, edge + kInner, edge + kOuter);
  const glm::dvec3 tint = setup.tint();
  const char* light = setup.sun ? "sun" : "point";
  std::printf(
      "reference under the pane (%s): (%.4f %.4f %.4f) [min (%.4f %.4f %.4f) max (%.4f %.4f "
      "%.4f)], expected (%.4f %.4f %.4f); beside: (%.4f %.4f %.4f)\n",
      light, under.r, under.g, under.b, lo.r, lo.g, lo.b, hi.r, hi.g, hi.b, tint.r, tint.g, tint.b,
      beside.r, beside.g, beside.b);
  test.RecordProperty(std::string("glass_reference_under_g_") + light, std::to_string(under.g));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(under[c], tint[c], kTintTolerance) << light << " channel " << c;
    EXPECT_NEAR(lo[c], tint[c], kTintSpread) << light << " channel " << c;
    EXPECT_NEAR(hi[c], tint[c], kTintSpread) << light << " channel " << c;
    EXPECT_NEAR(beside[c], 1.0, kWhiteTolerance) << light << " channel " << c;
  }
  // The pane's flat coloured shadow is no penumbra; its edge is.
  const std::uint32_t y = count.height / 2;
  const double half = 0.5 * count.width;
  std::size_t under_penumbra = 0;
  std::size_t edge_penumbra = 0;
  for (std::uint32_t x = 0; x < count.width; ++x) {
    const double wx = edge + (double(x) + 0.5 - half) * mpp;
    const float v = count.at(x, y, 0);
    if (wx > edge - kOuter && wx < edge - kInner && v >= 1.0f) ++under_penumbra;
    if (std::abs(wx - edge) < 0.02 && v >= 1.0f) ++edge_penumbra;
  }
  EXPECT_EQ(under_penumbra, 0u) << light;
  EXPECT_GT(edge_penumbra, 0u) << light;
}

TEST_F(ReferenceSunGlassGpu, GlassPaneTintsTheReferenceAndTheLayeredTechniqueAgrees) {
  OPEN_SESSION(session, kGolden);
  const bool layered = std::filesystem::exists(graph_path("layered-ssss"));
  for (const bool sun : {false, true}) {
    GlassSetup setup;
    setup.sun = sun;
    session->set_scene(glass_scene(setup));
    const auto check = [&](const auto& shadowed, const auto& unshadowed, const auto& count,
                           double mpp) {
      check_reference_glass(*this, setup, shadowed, unshadowed, count, mpp);
    };
    const GlassFrames frames = render_glass(*session, setup, "shadowMaps", check);
    const auto& shadowed = frames.shadowed;
    const auto& unshadowed = frames.unshadowed;
    const double mpp = frames.metres_per_pixel;
    if (sun || !layered) continue;

    // The layered technique (default graph) on the same frame: its coloured shadow under
    // the pane and its light beside it agree with the reference's.
    load_graph_ok(*session, graph_for_hdr(graph_path("layered-ssss")));
    session->render(2, nullptr);
    const auto technique = read_float_image(*session, "hdr");
    const double edge = setup.edge_x();
    const glm::dvec3 ref_under =
        mean_visibility(shadowed, unshadowed, edge, mpp, edge - kOuter, edge - kInner);
    const glm::dvec3 got_under =
        mean_visibility(technique, unshadowed, edge, mpp, edge - kOuter, edge - kInner);
    const glm::dvec3 got_beside =
        mean_visibility(technique, unshadowed, edge, mpp, edge + kInner, edge + kOuter);
    std::printf(
        "layered-ssss under the pane: (%.4f %.4f %.4f) vs reference (%.4f %.4f %.4f); beside: "
        "(%.4f %.4f %.4f)\n",
        got_under.r, got_under.g, got_under.b, ref_under.r, ref_under.g, ref_under.b, got_beside.r,
        got_beside.g, got_beside.b);
    RecordProperty("glass_layered_under_g", std::to_string(got_under.g));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got_under[c], ref_under[c], kLayeredTolerance) << "channel " << c;
      EXPECT_NEAR(got_beside[c], 1.0, kLayeredTolerance) << "channel " << c;
    }
  }
}

// The ray-traced reference (visibility "rays") tints through the pane as the map-based
// one does: panes turned towards the light multiply their transmittance in, and a pane
// does not tint its own lit surface (check_reference_glass's bands and penumbra counts).
TEST_F(ReferenceSunGlassGpu, GlassPaneTintsTheRayTracedReference) {
  OPEN_SESSION(session, kGolden);
  for (const bool sun : {false, true}) {
    GlassSetup setup;
    setup.sun = sun;
    session->set_scene(glass_scene(setup));
    render_glass(*session, setup, "rays",
                 [&](const auto& shadowed, const auto& unshadowed, const auto& count, double mpp) {
                   check_reference_glass(*this, setup, shadowed, unshadowed, count, mpp);
                 });
  }
}

}  // namespace
}  // namespace antumbra::quality_testing
