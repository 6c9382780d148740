// Penumbra width against similar triangles, per technique. A sphere light of radius R
// hangs L above a floor, directly above the straight edge of a 0.2 m slab centred at height h:
// the floor's penumbra runs across the edge with width W = 2 R h / (L - h). Where a
// disk light slides past an edge, visibility rises from 10 % to 90 % over 0.687 W (a
// disk's area profile); a box filter's ramp spans 0.8 W of its width.
//
// Visibility is the shadowed frame over the unshadowed one (one light, no ambient), on
// the floor along the line under the light, located by unprojecting the depth buffer
// from an oblique camera. Two slab heights (W and 3 W) separate techniques whose
// penumbra follows the geometry (reference, PCSS, VSSM, SDF) from fixed filters (PCF, the
// moment maps), whose width stays put, and hard shadows, which have none.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "antumbra/scene/scene_file.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr VkExtent2D kWidthView{320, 180};
constexpr float kLightHeight = 4.0f;
constexpr float kLightRadius = 0.25f;
constexpr std::uint32_t kWidthFace = 256;  // atlas faces: PCSS's 23 taps then reach 0.7 m

float analytic_width(float slab) {
  return 2.0f * kLightRadius * slab / (kLightHeight - slab);
}

// `lower` > 0 adds a second slab at that height under the first, reaching 0.3 m past its
// edge: the floor under both edges lies in the upper slab's inner penumbra yet in the
// lower slab's umbra.
// `spot`: the light is a spot pointing straight down (a 60-degree cone), one face
// instead of six.
std::string scene_text(float slab, float lower = 0.0f, bool spot = false) {
  char second[200] = "";
  if (lower > 0.0f) {
    std::snprintf(second, sizeof second,
                  R"(,
    {"name": "lower", "primitive": "box", "size": [4.3, 0.2, 6], "position": [-1.85, %.3f, 0], "material": "grey"})",
                  lower);
  }
  char text[1800];
  std::snprintf(
      text, sizeof text,
      R"({"version": 1, "name": "penumbra-width",
  "camera": {"position": [3.5, 5.0, 0.4], "target": [0, 0, 0], "fovY": 50, "near": 0.1, "far": 40},
  "ambient": [0, 0, 0],
  "materials": {"grey": {"albedo": [0.6, 0.6, 0.6], "roughness": 1.0}},
  "objects": [
    {"name": "floor", "primitive": "box", "size": [8, 0.2, 8], "position": [0, -0.1, 0], "material": "grey"},
    {"name": "slab", "primitive": "box", "size": [4, 0.2, 6], "position": [-2, %.3f, 0], "material": "grey"}%s
  ],
  "lights": [{"name": "lamp", "position": [0, %.3f, 0], "color": [1, 1, 1], "intensity": 20,
              "range": 12, "size": %.3f%s}]})",
      slab, second, kLightHeight, kLightRadius,
      spot ? R"(, "type": "spot", "direction": [0, -1, 0], "angle": 60, "innerAngle": 55)" : "");
  return text;
}

struct Profile {
  std::vector<float> sum;
  std::vector<int> count;
  float start = -1.2f;
  float bin = 0.01f;
};

class PenumbraWidthTest : public RenderTest {
 protected:
  struct Frame {
    gpu::HostImage hdr;
    gpu::HostImage depth;
  };

  using Edit = std::function<void(fg::GraphDesc&)>;
  // Applied to every scene the test renders (after parsing).
  std::function<void(scene::Scene&)> scene_edit_;

  std::optional<Frame> render(const std::string& graph_file, const std::string& scene_json,
                              const Edit& edit = {}) {
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / graph_file);
    for (auto& r : graph.resources) {
      if (r.name == "atlas" || r.name == "moments" || r.name == "penumbraMap" ||
          r.name == "peeled") {
        r.size = fg::SizeSpec{false, 1.0, 1.0, kWidthFace, kWidthFace};
      }
    }
    if (edit) edit(graph);
    for (auto& p : graph.passes) {
      if (p.type == "shadow-pcss") p.params["kernel"] = "23";
    }
    runtime::RenderSession* session = open_session(kWidthView);
    EXPECT_NE(session, nullptr) << skip_reason_;
    if (session == nullptr) return std::nullopt;
    load_graph_ok(*session, graph);
    auto scene = scene::parse_scene_text(scene_json, "penumbra-width.json");
    EXPECT_TRUE(scene.ok()) << describe(scene.diagnostics());
    if (!scene.ok()) return std::nullopt;
    if (scene_edit_) scene_edit_(scene.value());
    session->set_scene(std::move(scene.value()));
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    return Frame{read_resource(*session, "hdr"), read_resource(*session, "depth")};
  }

  // Visibility along z = 0 on the floor, binned by x (every scene has the same camera).
  static Profile profile(const Frame& shadowed, const Frame& unshadowed) {
    const auto scene = scene::parse_scene_text(scene_text(kLightHeight / 2), "penumbra-width.json");
    const float aspect =
        static_cast<float>(kWidthView.width) / static_cast<float>(kWidthView.height);
    const glm::mat4 inverse = glm::inverse(scene.value().camera.view_projection(aspect));
    Profile p;
    p.sum.assign(240, 0.0f);
    p.count.assign(240, 0);
    for (std::uint32_t y = 0; y < kWidthView.height; ++y) {
      for (std::uint32_t x = 0; x < kWidthView.width; ++x) {
        const float d = shadowed.depth.at(x, y, 0);
        if (d >= 1.0f) continue;
        const glm::vec2 ndc{
            (static_cast<float>(x) + 0.5f) / static_cast<float>(kWidthView.width) * 2.0f - 1.0f,
            (static_cast<float>(y) + 0.5f) / static_cast<float>(kWidthView.height) * 2.0f - 1.0f};
        glm::vec4 w = inverse * glm::vec4(ndc, d, 1.0f);
        w /= w.w;
        if (std::abs(w.y) > 0.01f || std::abs(w.z) > 0.08f) continue;  // the floor, near z = 0
        const float lit = unshadowed.hdr.at(x, y, 0);
        if (lit <= 1e-4f) continue;
        const int b = static_cast<int>(std::floor((w.x - p.start) / p.bin));
        if (b < 0 || b >= static_cast<int>(p.sum.size())) continue;
        p.sum[static_cast<std::size_t>(b)] += shadowed.hdr.at(x, y, 0) / lit;
        ++p.count[static_cast<std::size_t>(b)];
      }
    }
    return p;
  }

  // The 10 % to 90 % span of the profile: the last bin below 0.1 and the first above 0.9
  // after it (x grows into the light).
  static float rise_width(const Profile& p) {
    float low = NAN;
    float high = NAN;
    for (std::size_t b = 0; b < p.sum.size(); ++b) {
      if (p.count[b] == 0) continue;
      const float v = p.sum[b] / static_cast<float>(p.count[b]);
      const float x = p.start + (static_cast<float>(b) + 0.5f) * p.bin;
      if (v < 0.1f) low = x;
      if (v > 0.9f && std::isnan(high) && !std::isnan(low)) high = x;
      if (v < 0.1f) high = NAN;
    }
    return high - low;
  }

  // Where the umbra ends: the last bin darker than 0.02 before the profile first rises
  // above 0.9.
  static float umbra_end(const Profile& p) {
    float end = NAN;
    for (std::size_t b = 0; b < p.sum.size(); ++b) {
      if (p.count[b] == 0) continue;
      const float v = p.sum[b] / static_cast<float>(p.count[b]);
      if (v > 0.9f && !std::isnan(end)) break;
      if (v < 0.02f) end = p.start + (static_cast<float>(b) + 0.5f) * p.bin;
    }
    return end;
  }

  // The largest visibility over [from, to].
  static float brightest(const Profile& p, float from, float to) {
    float v = 0.0f;
    for (std::size_t b = 0; b < p.sum.size(); ++b) {
      const float x = p.start + (static_cast<float>(b) + 0.5f) * p.bin;
      if (p.count[b] > 0 && x >= from && x <= to) {
        v = std::max(v, p.sum[b] / static_cast<float>(p.count[b]));
      }
    }
    return v;
  }

  // Mean absolute difference of two profiles over [-0.6, 0.6] m.
  static float mean_difference(const Profile& a, const Profile& b) {
    float sum = 0.0f;
    int n = 0;
    for (std::size_t i = 0; i < a.sum.size(); ++i) {
      const float x = a.start + (static_cast<float>(i) + 0.5f) * a.bin;
      if (a.count[i] == 0 || b.count[i] == 0 || std::abs(x) > 0.6f) continue;
      sum += std::abs(a.sum[i] / static_cast<float>(a.count[i]) -
                      b.sum[i] / static_cast<float>(b.count[i]));
      ++n;
    }
    return n > 0 ? sum / static_cast<float>(n) : NAN;
  }

  // penumbra-wedges.json peeling `depth` layers (without `peeled` below 3).
  static Edit peeling(int depth) {
    return [depth](fg::GraphDesc& graph) {
      for (auto& pass : graph.passes) {
        if (pass.type == "penumbra-wedges") pass.params["peelingDepth"] = depth;
        if (depth >= 3) continue;
        auto& list = pass.type == "penumbra-wedges" ? pass.outputs : pass.inputs;
        std::erase_if(list, [](const fg::PortBindingDesc& b) { return b.port == "peeled"; });
      }
      std::erase_if(graph.resources,
                    [depth](const fg::ResourceDesc& r) { return depth < 3 && r.name == "peeled"; });
    };
  }

  // The darkest bin of the profile (0 in a full umbra).
  static float darkest(const Profile& p) {
    float v = 1.0f;
    for (std::size_t b = 0; b < p.sum.size(); ++b) {
      if (p.count[b] > 0) v = std::min(v, p.sum[b] / static_cast<float>(p.count[b]));
    }
    return v;
  }

  // The visibility profile of `graph` (edited) on `scene_json`.
  std::optional<Profile> visibility(const std::string& graph, const std::string& scene_json,
                                    const Edit& edit = {}) {
    const auto shadowed = render(graph, scene_json, edit);
    const auto unshadowed = render("lighting.json", scene_json);
    if (!shadowed || !unshadowed) return std::nullopt;
    return profile(*shadowed, *unshadowed);
  }

  float measure(const std::string& graph, float slab, float* umbra = nullptr) {
    const auto found = visibility(graph, scene_text(slab));
    if (!found) return NAN;
    const Profile& p = *found;
    if (umbra != nullptr) *umbra = darkest(p);
    const float width = rise_width(p);
    std::printf("%-20s slab %.1f m: 10-90 width %.3f m (disk 0.687 W = %.3f, box 0.8 W = %.3f)\n",
                graph.c_str(), slab, width, 0.687f * analytic_width(slab),
                0.8f * analytic_width(slab));
    return width;
  }
};

constexpr float kLow = 1.0f;   // W = 0.167 m
constexpr float kHigh = 2.0f;  // W = 0.5 m

// The measurement itself: the area-light reference follows the disk profile.
TEST_F(PenumbraWidthTest, ReferenceFollowsSimilarTriangles) {
  for (const float slab : {kLow, kHigh}) {
    const float expected = 0.687f * analytic_width(slab);
    EXPECT_NEAR(measure("reference.json", slab), expected, 0.2f * expected + 0.02f);
  }
}

// Penumbra estimators (docs/technique.md 3): a box filter of the physical width, so
// 0.8 W, within 30 % (the blocker estimate averages the slab with the floor) plus two
// texels at the receiver.
TEST_F(PenumbraWidthTest, EstimatorsFollowSimilarTriangles) {
  for (const char* graph : {"pcss.json", "vssm.json", "sdf.json", "penumbra-wedges.json"}) {
    SCOPED_TRACE(graph);
    float widths[2] = {NAN, NAN};
    for (const float slab : {kLow, kHigh}) {
      // The SDF's cone estimate needs the occluder thicker than the cone is wide where
      // the ray crosses it (SdfLeaksThroughOccludersThinnerThanItsCone).
      if (std::string(graph) == "sdf.json" && slab == kHigh) continue;
      const float expected = 0.8f * analytic_width(slab);
      const float texel = 2.0f * kLightHeight / kWidthFace;
      widths[slab == kLow ? 0 : 1] = measure(graph, slab);
      EXPECT_NEAR(widths[slab == kLow ? 0 : 1], expected, 0.3f * expected + 2.0f * texel);
    }
    // W triples between the slabs: a fixed filter of the right average width fails here.
    if (std::string(graph) != "sdf.json") {
      EXPECT_GT(widths[1], 2.0f * widths[0]);
    }
  }
}

// The SDF's documented artefact (docs/technique.md 3): a ray through an occluder sees
// at most half its thickness as negative distance, so an occluder thinner than the
// light's cone where the ray crosses it (here 0.2 m against a cone 0.25 m wide at the
// higher slab) never darkens fully; at the lower slab (a 0.125 m cone) it does.
TEST_F(PenumbraWidthTest, SdfLeaksThroughOccludersThinnerThanItsCone) {
  float low = 1.0f;
  float high = 1.0f;
  measure("sdf.json", kLow, &low);
  measure("sdf.json", kHigh, &high);
  std::printf("sdf darkest visibility: %.3f (cone 0.125 m), %.3f (cone 0.25 m)\n", low, high);
  EXPECT_LT(low, 0.05f);
  EXPECT_GT(high, 0.05f);
  EXPECT_LT(high, 0.3f);
}

// Fixed filters: the width does not follow the geometry (tripling W changes it by far
// less), and hard shadows stay within a few texels.
TEST_F(PenumbraWidthTest, FixedFiltersDoNotFollowTheGeometry) {
  const float texel = 2.0f * kLightHeight / kWidthFace;
  EXPECT_LT(measure("hard.json", kHigh), 3.0f * texel);
  for (const char* graph : {"pcf.json", "evsm4.json"}) {
    SCOPED_TRACE(graph);
    const float low = measure(graph, kLow);
    const float high = measure(graph, kHigh);
    EXPECT_LT(high, 1.6f * low) << "W triples between the two slabs";
  }
}

// Penumbra wedges (docs/technique.md 2): inner
// wedges move the umbra's edge inside the hard shadow, where the area light puts it.
// Drawing only outer wedges (peelingDepth 1: the single-layer methods the seed improves
// on) lets the umbra reach the hard edge, W / 2 = 0.25 m too far.
TEST_F(PenumbraWidthTest, WedgesDoNotOverestimateTheUmbra) {
  const std::string scene = scene_text(kHigh);
  const auto reference = visibility("reference.json", scene);
  const auto wedges = visibility("penumbra-wedges.json", scene);
  const auto single = visibility("penumbra-wedges.json", scene, peeling(1));
  ASSERT_TRUE(reference && wedges && single);
  const float texel = 2.0f * kLightHeight / kWidthFace;
  const float expected = umbra_end(*reference);
  std::printf(
      "umbra ends at %.3f m (reference), %.3f (3 layers), %.3f (outer wedges only); "
      "mean |difference| to the reference %.4f and %.4f\n",
      static_cast<double>(expected), static_cast<double>(umbra_end(*wedges)),
      static_cast<double>(umbra_end(*single)),
      static_cast<double>(mean_difference(*wedges, *reference)),
      static_cast<double>(mean_difference(*single, *reference)));
  EXPECT_LT(expected, -0.1f);  // the disk's umbra starts W / 2 inside the hard edge
  EXPECT_NEAR(umbra_end(*wedges), expected, 0.05f + texel);
  EXPECT_GT(umbra_end(*single) - expected, 0.15f);
  EXPECT_LT(mean_difference(*wedges, *reference), 0.04f);
  EXPECT_GT(mean_difference(*single, *reference), 1.5f * mean_difference(*wedges, *reference));
}

// A mesh whose winding flips between neighbouring triangles (exporters write such
// meshes): every other triangle of the slab's top is wound backwards. The edge between
// them is no silhouette (the surface is flat): no wedge may light the umbra under the
// slab, and the profile matches the straight mesh's.
TEST_F(PenumbraWidthTest, FlippedWindingMakesNoSilhouettes) {
  // A narrower slab (x from -0.8 to 0): the diagonal of its top, where the flipped and
  // the straight triangles meet, then projects across the measured line (x = -0.84).
  std::string scene = scene_text(kHigh);
  const std::string wide = R"("size": [4, 0.2, 6], "position": [-2, 2.000, 0])";
  const auto at = scene.find(wide);
  ASSERT_NE(at, std::string::npos);
  scene.replace(at, wide.size(), R"("size": [0.8, 0.2, 6], "position": [-0.4, 2.000, 0])");
  const auto straight = visibility("penumbra-wedges.json", scene);
  int flipped = 0;
  scene_edit_ = [&flipped](scene::Scene& s) {
    for (auto& mesh : s.meshes) {
      if (mesh.name != "slab") continue;
      bool flip = false;
      for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        if (mesh.vertices[mesh.indices[t]].normal.y < 0.9f) continue;  // the top only
        if (flip) {
          std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
          ++flipped;
        }
        flip = !flip;
      }
    }
  };
  const auto mixed = visibility("penumbra-wedges.json", scene);
  scene_edit_ = nullptr;
  ASSERT_TRUE(straight && mixed);
  ASSERT_GT(flipped, 0);
  std::printf(
      "flipped %d top triangles: brightest under the slab %.3f (straight %.3f), "
      "10-90 width %.3f (straight %.3f)\n",
      flipped, static_cast<double>(brightest(*mixed, -1.2f, -0.3f)),
      static_cast<double>(brightest(*straight, -1.2f, -0.3f)),
      static_cast<double>(rise_width(*mixed)), static_cast<double>(rise_width(*straight)));
  EXPECT_LT(brightest(*mixed, -1.2f, -0.3f), 0.02f);
  EXPECT_LT(mean_difference(*mixed, *straight), 0.01f);
}

// The same under a spot light: its one face carries the silhouettes and the wedges.
TEST_F(PenumbraWidthTest, WedgesFollowSimilarTrianglesUnderASpotLight) {
  const std::string scene = scene_text(kHigh, 0.0f, true);
  const auto reference = visibility("reference.json", scene);
  const auto wedges = visibility("penumbra-wedges.json", scene);
  ASSERT_TRUE(reference && wedges);
  // The spot's face spans 2 tan(60 degrees) across: texels 1.7x the cube faces'.
  const float texel = 2.0f * std::tan(glm::radians(60.0f)) * kLightHeight / kWidthFace;
  const float expected = 0.8f * analytic_width(kHigh);
  std::printf(
      "spot light: 10-90 width %.3f m (reference %.3f, 0.8 W = %.3f); umbra ends at "
      "%.3f (reference %.3f)\n",
      static_cast<double>(rise_width(*wedges)), static_cast<double>(rise_width(*reference)),
      static_cast<double>(expected), static_cast<double>(umbra_end(*wedges)),
      static_cast<double>(umbra_end(*reference)));
  EXPECT_NEAR(rise_width(*wedges), expected, 0.3f * expected + 2.0f * texel);
  EXPECT_NEAR(umbra_end(*wedges), umbra_end(*reference), 0.05f + texel);
  EXPECT_LT(mean_difference(*wedges, *reference), 0.04f);
}

// Case 6 of the seed's figure 7: the floor under both slabs' edges lies in the upper
// slab's inner wedge, but a second occluder (the lower slab) hides it fully. Only the
// third depth layer tells it from the inner penumbra (case 5); with two layers the inner
// ramp lights it.
TEST_F(PenumbraWidthTest, ThirdLayerKeepsTheUmbraUnderASecondOccluder) {
  const std::string scene = scene_text(kHigh, kLow);
  const auto reference = visibility("reference.json", scene);
  const auto three = visibility("penumbra-wedges.json", scene);
  const auto two = visibility("penumbra-wedges.json", scene, peeling(2));
  ASSERT_TRUE(reference && three && two);
  const float from = -0.2f;
  const float to = -0.03f;
  std::printf("brightest under both slabs: %.3f (reference), %.3f (3 layers), %.3f (2)\n",
              static_cast<double>(brightest(*reference, from, to)),
              static_cast<double>(brightest(*three, from, to)),
              static_cast<double>(brightest(*two, from, to)));
  EXPECT_LT(brightest(*reference, from, to), 0.02f);
  EXPECT_LT(brightest(*three, from, to), 0.02f);
  EXPECT_GT(brightest(*two, from, to), 0.1f);
}

}  // namespace
