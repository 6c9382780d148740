// Cut casters (docs/technique.md, "Materials"): a quad with a checkerboard alpha texture
// (alphaMode MASK) casts a checkerboard shadow, and a one-sided quad casts only when the
// light sees its front, in the hardware and the compute shadow rasterisers alike, and in
// the shadow reference that judges them.
//
// A small point light at (-6, 4, 0) shines on a 2 m quad at height 1; its shadow falls on
// the floor beside it, enlarged 4/3 around the light, where a camera on the far side sees
// it without the quad in the way. Visibility is the frame over the same frame without the
// quad (no ambient), sampled at the centres of the 4 x 4 cells' shadows.

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "../support/gltf_builder.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr VkExtent2D kView{320, 180};
constexpr int kCells = 4;
const glm::vec3 kLight{-6.0f, 4.0f, 0.0f};
constexpr float kQuadHeight = 1.0f;
// The sun variant: travelling from the lamp's place towards the origin (orthographic maps,
// whose projection does not mirror, unlike the cube faces).
const glm::vec3 kSun = glm::normalize(-kLight);

// faded: alphaMode MASK with a base-colour factor alpha of 0.25, cut away everywhere.
enum class Caster { none, checker, one_sided_up, one_sided_down, two_sided_down, faded };

// Writes the quad's glTF into `dir` and returns the scene's JSON.
std::string scene_text(const std::filesystem::path& dir, Caster caster, float light_size,
                       bool sun) {
  nlohmann::json doc = antumbra::testing::quad_gltf(2.0f, 0.0f);
  if (caster == Caster::checker) {
    antumbra::testing::write_file(
        dir / "checker.png",
        antumbra::testing::png_bytes(kCells * 16, kCells * 16,
                                     antumbra::testing::checkerboard_rgba(kCells, 16)));
    doc["materials"] =
        nlohmann::json::array({{{"name", "checker"},
                                {"alphaMode", "MASK"},
                                {"doubleSided", true},
                                {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    doc["textures"] = nlohmann::json::array({{{"source", 0}, {"sampler", 0}}});
    doc["samplers"] = nlohmann::json::array({{{"magFilter", 9728}}});
    doc["images"] = nlohmann::json::array({{{"uri", "checker.png"}}});
  } else if (caster == Caster::faded) {
    doc["materials"] = nlohmann::json::array(
        {{{"name", "faded"},
          {"alphaMode", "MASK"},
          {"doubleSided", true},
          {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 1.0, 1.0, 0.25}}}}}});
  } else {
    doc["materials"] = nlohmann::json::array(
        {{{"name", "card"}, {"doubleSided", caster == Caster::two_sided_down}}});
  }
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const bool down = caster == Caster::one_sided_down || caster == Caster::two_sided_down;
  nlohmann::json scene = {
      {"version", 1},
      {"camera", {{"position", {7.0, 4.5, 0.0}}, {"target", {1.5, 0.0, 0.0}}, {"fovY", 55}}},
      {"ambient", {0, 0, 0}},
      {"objects", nlohmann::json::array({{{"name", "floor"},
                                          {"primitive", "box"},
                                          {"size", {14, 0.2, 14}},
                                          {"position", {0, -0.1, 0}}}})},
      {"lights", nlohmann::json::array({{{"name", "lamp"},
                                         {"position", {kLight.x, kLight.y, kLight.z}},
                                         {"intensity", 60},
                                         {"range", 30},
                                         {"size", light_size}}})}};
  if (sun) {
    scene["lights"] = nlohmann::json::array({{{"name", "sun"},
                                              {"type", "directional"},
                                              {"direction", {kSun.x, kSun.y, kSun.z}},
                                              {"intensity", 3},
                                              {"size", 0.05}}});
  }
  if (caster != Caster::none) {
    // Rotated half a turn about x, the quad faces down (its uv mirrored in z).
    scene["objects"].push_back({{"gltf", "quad.gltf"},  // beside scene.json
                                {"position", {0.0, kQuadHeight, 0.0}},
                                {"rotation", {down ? 180.0 : 0.0, 0.0, 0.0}}});
  }
  return scene.dump();
}

class AlphaMaskTest : public RenderTest {
 protected:
  struct Frame {
    gpu::HostImage hdr;
    scene::Scene scene;
    base::Json clusters;  // the compute rasteriser's clusters by path (note SHD010)
  };

  std::optional<Frame> render(Caster caster, const std::string& rasterizer,
                              float light_size = 0.01f, bool sun = false) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("antumbra_alpha_mask_" + rasterizer + std::to_string(static_cast<int>(caster)) + "_" +
         std::to_string(static_cast<int>(light_size * 100.0f)) + (sun ? "_sun" : ""));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    // "reference": the shadow-reference graph, a few samples of the small light (it is
    // nearly a point, so they agree); "rays": the same with visibility "rays" (traced
    // through the BVH, no maps); else the atlas graph with that rasteriser.
    // "wedges": the penumbra-wedges graph (its hardware atlas, peeling and wedges);
    // "sdf": the scene-sdf graph.
    const bool rays = rasterizer == "rays";
    const bool reference = rasterizer == "reference" || rays;
    const bool wedges = rasterizer == "wedges";
    const bool sdf = rasterizer == "sdf";
    const char* file = reference ? "reference.json"
                       : wedges  ? "penumbra-wedges.json"
                       : sdf     ? "sdf.json"
                                 : "hard.json";
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / file);
    for (auto& r : graph.resources) {
      if (r.name == "atlas") r.size = fg::SizeSpec{false, 1.0, 1.0, 512, 512};
    }
    for (auto& p : graph.passes) {
      if (p.type == "point-shadow-atlas" && !wedges && !sdf) p.params["rasterizer"] = rasterizer;
      if (p.type == "shadow-reference") {
        p.params["samples"] = 16;
        p.params["faceSize"] = 512;
        p.params["visibility"] = rays ? "rays" : "shadowMaps";  // reference.json: rays
      }
    }
    runtime::RenderSession* session = open_session(kView);
    EXPECT_NE(session, nullptr) << skip_reason_;
    if (session == nullptr) return std::nullopt;
    load_graph_ok(*session, graph);
    auto scene = scene::parse_scene_text(scene_text(dir, caster, light_size, sun),
                                         (dir / "scene.json").string());
    EXPECT_TRUE(scene.ok()) << describe(scene.diagnostics());
    if (!scene.ok()) return std::nullopt;
    Frame frame{{}, scene.value()};
    session->set_scene(std::move(scene.value()));
    session->render(1, nullptr);
    expect_no_validation_errors(*session);
    frame.hdr = read_resource(*session, "hdr");
    for (const auto& m : session->last_report().messages()) {
      if (m.code == "SHD010" && m.details.contains("clusters"))
        frame.clusters = m.details["clusters"];
    }
    return frame;
  }

  // Visibility at the shadow of quad point (u, v) (quad uv, before any rotation).
  static float visibility(const Frame& shadowed, const Frame& lit, float u, float v, bool down,
                          bool sun = false) {
    const glm::vec3 quad{-1.0f + 2.0f * u, kQuadHeight, (-1.0f + 2.0f * v) * (down ? -1.0f : 1.0f)};
    const glm::vec3 floor = sun ? quad + kSun * (kQuadHeight / -kSun.y)
                                : kLight + (quad - kLight) * (kLight.y / (kLight.y - kQuadHeight));
    const float aspect = static_cast<float>(kView.width) / static_cast<float>(kView.height);
    const glm::vec4 clip = shadowed.scene.camera.view_projection(aspect) * glm::vec4(floor, 1.0f);
    const float px = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(kView.width);
    const float py = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(kView.height);
    float sum = 0.0f;
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const auto x = static_cast<std::uint32_t>(px) + static_cast<std::uint32_t>(dx);
        const auto y = static_cast<std::uint32_t>(py) + static_cast<std::uint32_t>(dy);
        if (x >= kView.width || y >= kView.height) continue;
        const float reference = lit.hdr.at(x, y, 0);
        if (reference <= 1e-4f) continue;
        sum += shadowed.hdr.at(x, y, 0) / reference;
        ++n;
      }
    }
    return n > 0 ? sum / static_cast<float>(n) : NAN;
  }

  void expect_checkerboard(const std::string& rasterizer) {
    const auto lit = render(Caster::none, rasterizer);
    const auto checker = render(Caster::checker, rasterizer);
    ASSERT_TRUE(lit && checker);
    int right = 0;
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const float u = (static_cast<float>(i) + 0.5f) / kCells;
        const float v = (static_cast<float>(j) + 0.5f) / kCells;
        const float seen = visibility(*checker, *lit, u, v, false);
        const bool opaque = (i + j) % 2 == 0;
        std::printf("[ %s ] cell (%d, %d) %s: visibility %.3f\n", rasterizer.c_str(), i, j,
                    opaque ? "opaque" : "cut", seen);
        if (opaque ? seen < 0.1f : seen > 0.9f) ++right;
      }
    }
    // Every cell: solid cells shadow, cut-away ones let the light through.
    EXPECT_EQ(right, kCells * kCells);
  }

  void expect_one_sided(const std::string& rasterizer, bool sun = false) {
    const auto lit = render(Caster::none, rasterizer, 0.01f, sun);
    ASSERT_TRUE(lit);
    const float centre = 0.5f;
    for (const Caster c : {Caster::one_sided_up, Caster::one_sided_down, Caster::two_sided_down}) {
      const auto frame = render(c, rasterizer, 0.01f, sun);
      ASSERT_TRUE(frame);
      const bool down = c != Caster::one_sided_up;
      const float seen = visibility(*frame, *lit, centre, centre, down, sun);
      std::printf("[ %s%s ] caster %d: visibility %.3f under the quad\n", rasterizer.c_str(),
                  sun ? " sun" : "", static_cast<int>(c), seen);
      // Only the one-sided quad facing away from the light lets it through.
      if (c == Caster::one_sided_down) {
        EXPECT_GT(seen, 0.9f) << rasterizer;
      } else {
        EXPECT_LT(seen, 0.1f) << rasterizer << " caster " << static_cast<int>(c);
      }
    }
  }

  // Penumbra wedges grow from silhouette edges (docs/technique.md, "Draw classes"): a
  // one-sided quad facing away from the light casts nothing, so its border is no
  // silhouette, and the borders of an alpha-tested quad are not either (its shadow stays
  // the atlas's hard one). With a light large enough for wedges several pixels wide, the
  // floor where those borders project stays lit: the midpoints of the facing-away quad's
  // sides and of the checkerboard's cut border cells.
  void expect_no_wedges_from_non_casting_borders() {
    constexpr float kSize = 0.3f;
    const auto lit = render(Caster::none, "wedges", kSize);
    const auto away = render(Caster::one_sided_down, "wedges", kSize);
    const auto checker = render(Caster::checker, "wedges", kSize);
    ASSERT_TRUE(lit && away && checker);
    for (const glm::vec2 uv : {glm::vec2(0.0f, 0.5f), glm::vec2(1.0f, 0.5f), glm::vec2(0.5f, 0.0f),
                               glm::vec2(0.5f, 1.0f)}) {
      const float seen = visibility(*away, *lit, uv.x, uv.y, true);
      std::printf("[ wedges ] one-sided away, border (%.2f, %.2f): visibility %.3f\n", uv.x, uv.y,
                  seen);
      EXPECT_GT(seen, 0.9f) << uv.x << ", " << uv.y;
    }
    // Cut border cells: (1, 0), (3, 0) at v = 0 and (0, 3), (2, 3) at v = 1.
    for (const glm::vec2 uv : {glm::vec2(0.375f, 0.0f), glm::vec2(0.875f, 0.0f),
                               glm::vec2(0.125f, 1.0f), glm::vec2(0.625f, 1.0f)}) {
      const float seen = visibility(*checker, *lit, uv.x, uv.y, false);
      std::printf("[ wedges ] checker, cut border (%.3f, %.2f): visibility %.3f\n", uv.x, uv.y,
                  seen);
      EXPECT_GT(seen, 0.9f) << uv.x << ", " << uv.y;
    }
  }
};

TEST_F(AlphaMaskTest, CheckerboardAlphaCastsACheckerboardShadowHardware) {
  expect_checkerboard("hardware");
}

TEST_F(AlphaMaskTest, CheckerboardAlphaCastsACheckerboardShadowCompute) {
  expect_checkerboard("compute");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontHardware) {
  expect_one_sided("hardware");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontCompute) {
  expect_one_sided("compute");
}

TEST_F(AlphaMaskTest, CheckerboardAlphaCastsACheckerboardShadowReference) {
  expect_checkerboard("reference");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontReference) {
  expect_one_sided("reference");
}

// The sun's orthographic maps do not mirror: gl_FrontFacing needs no flip there.
TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontUnderTheSunReference) {
  expect_one_sided("reference", true);
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontUnderTheSunHardware) {
  expect_one_sided("hardware", true);
}

// The ray-traced reference decides cut and one-sided casters per hit, as the rasterisers
// do per texel (reference_trace.comp).
TEST_F(AlphaMaskTest, CheckerboardAlphaCastsACheckerboardShadowRays) {
  expect_checkerboard("rays");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontRays) {
  expect_one_sided("rays");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontUnderTheSunRays) {
  expect_one_sided("rays", true);
}

TEST_F(AlphaMaskTest, CheckerboardAlphaCastsACheckerboardShadowWedges) {
  expect_checkerboard("wedges");
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontWedges) {
  expect_one_sided("wedges");
}

// The SDF bake keeps or drops an alpha-tested triangle by its alpha at the centroid
// (docs/technique.md, "Draw classes"): a quad cut away by its factor casts nothing, the
// atlas agreeing. The checkerboard's two triangles both have their centroids (thirds of
// the quad) in cut cells, so the field drops the whole quad, solid cells too (printed,
// not asserted: an approximation by design).
TEST_F(AlphaMaskTest, SdfDropsTrianglesCutAtTheirCentroid) {
  const auto lit = render(Caster::none, "sdf");
  const auto faded = render(Caster::faded, "sdf");
  const auto checker = render(Caster::checker, "sdf");
  const auto atlas_lit = render(Caster::none, "hardware");
  const auto atlas_faded = render(Caster::faded, "hardware");
  ASSERT_TRUE(lit && faded && checker && atlas_lit && atlas_faded);
  const float seen = visibility(*faded, *lit, 0.5f, 0.5f, false);
  const float atlas = visibility(*atlas_faded, *atlas_lit, 0.5f, 0.5f, false);
  std::printf("[ sdf ] faded quad: visibility %.3f under it (atlas %.3f)\n", seen, atlas);
  EXPECT_GT(seen, 0.9f);
  EXPECT_GT(atlas, 0.9f);
  // A cut cell, then a solid one.
  for (const glm::vec2 uv : {glm::vec2(0.375f, 0.125f), glm::vec2(0.125f, 0.125f)}) {
    std::printf("[ sdf ] checker cell at (%.3f, %.3f): visibility %.3f\n", uv.x, uv.y,
                visibility(*checker, *lit, uv.x, uv.y, false));
  }
}

// Cut clusters take the compute rasteriser's CUT variant, the rest the one without any
// texture work (docs/technique.md, "Compute shadow rasteriser"): the quad of a cut or a
// one-sided material is on the cut path, the floor on the solid one, and the untextured
// scene has no cut cluster at all.
TEST_F(AlphaMaskTest, ComputeRasterizerPutsOnlyCutClustersOnTheCutPath) {
  const auto lit = render(Caster::none, "compute");
  const auto checker = render(Caster::checker, "compute");
  const auto one_sided = render(Caster::one_sided_up, "compute");
  const auto two_sided = render(Caster::two_sided_down, "compute");
  ASSERT_TRUE(lit && checker && one_sided && two_sided);
  for (const auto* f : {&*lit, &*checker, &*one_sided, &*two_sided}) {
    ASSERT_TRUE(f->clusters.is_object()) << "no cluster counts in SHD010";
    std::printf("clusters: %s\n", f->clusters.dump().c_str());
    EXPECT_EQ(f->clusters["solid"].get<int>() + f->clusters["cut"].get<int>() +
                  f->clusters["translucent"].get<int>(),
              f->clusters["total"].get<int>());
  }
  const int floor = lit->clusters["total"].get<int>();
  EXPECT_GT(floor, 0);
  EXPECT_EQ(lit->clusters["cut"].get<int>(), 0);
  EXPECT_EQ(two_sided->clusters["cut"].get<int>(), 0);
  EXPECT_EQ(two_sided->clusters["solid"].get<int>(), floor + 1);  // the quad: one cluster
  EXPECT_FALSE(lit->clusters["cutPipelineBuilt"].get<bool>());
  EXPECT_FALSE(two_sided->clusters["cutPipelineBuilt"].get<bool>());
  for (const auto* f : {&*checker, &*one_sided}) {
    EXPECT_EQ(f->clusters["cut"].get<int>(), 1);
    EXPECT_EQ(f->clusters["solid"].get<int>(), floor);
    EXPECT_TRUE(f->clusters["cutPipelineBuilt"].get<bool>());
  }
}

TEST_F(AlphaMaskTest, OneSidedCastersCastOnlyFromTheirFrontUnderTheSunCompute) {
  expect_one_sided("compute", true);
}

TEST_F(AlphaMaskTest, NonCastingBordersGrowNoWedges) {
  expect_no_wedges_from_non_casting_borders();
}

}  // namespace
