// Packed faces on lavapipe, under validation and synchronization validation
// (docs/technique.md, "Packed faces"): 16 lights' 96 faces in an atlas of 6 layers of 256^2
// cannot have a layer each, so the planner gives every light 64^2 faces, 16 to a layer.
// The frame must equal the one rendered from an atlas of 96 layers of 64^2 (one face a
// layer, nothing packed): same face sizes, so the same depth, and every lookup, filter and
// derived map (min-filtered depth, summed-area moments) reading through the faces' places
// instead of their layers' corners. Hardware and compute rasterisers.

#include <algorithm>
#include <string>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

// The atlas and the maps derived from it at `face` texels (a derived map keeps its factor
// of the atlas's size) and `layers` layers; rasteriser `rasterizer` (compute: r32f atlas).
fg::GraphDesc atlas_graph(const std::string& file, std::uint32_t face, std::uint32_t layers,
                          const std::string& rasterizer) {
  auto graph = load_graph_file(source_dir() / "data" / "graphs" / file);
  std::uint32_t atlas_width = 0;
  for (const auto& r : graph.resources) {
    if (r.name == "atlas") atlas_width = r.size.width;
  }
  for (auto& r : graph.resources) {
    const bool shadow_image = r.name == "atlas" || r.name == "shadowColour" ||
                              r.name == "minDepth" || r.name == "moments";
    if (r.kind != fg::ResourceKind::image || !shadow_image) continue;
    const std::uint32_t factor = std::max(atlas_width / std::max(r.size.width, 1u), 1u);
    r.size.width = r.size.height = face / factor;
    r.layers = layers;
    if (r.name == "atlas" && rasterizer == "compute") r.format = fg::Format::r32f;
  }
  for (auto& pass : graph.passes) {
    if (pass.type == "point-shadow-atlas") pass.params["rasterizer"] = rasterizer;
  }
  return graph;
}

struct Case {
  const char* graph;
  const char* rasterizer;
};

class PackedFacesGpu : public RenderTest, public ::testing::WithParamInterface<Case> {
 protected:
  gpu::HostImage render(const fg::GraphDesc& graph, fgvk::FrameReport* report) {
    runtime::RenderSession* session = open_session(kSmall);
    if (session == nullptr) return {};
    session->set_scene(default_scene());
    load_graph_ok(*session, graph);
    session->render(2);
    if (report != nullptr) *report = session->last_report();
    expect_no_validation_errors(*session);
    return read_output(*session);
  }
};

TEST_P(PackedFacesGpu, EqualsOneFaceALayerAtTheSameSize) {
  const Case c = GetParam();
  fgvk::FrameReport packed_report;
  const auto packed = render(atlas_graph(c.graph, 256, 6, c.rasterizer), &packed_report);
  if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_;
  const auto whole = render(atlas_graph(c.graph, 64, 96, c.rasterizer), nullptr);
  ASSERT_FALSE(is_blank(packed));
  // Every light drawn at 64^2, none left out (SHD005 names all 16; no SHD002).
  bool degraded = false;
  for (const auto& m : packed_report.messages()) {
    EXPECT_NE(m.code, "SHD002") << m.message;
    if (m.code == "SHD005") {
      degraded = true;
      EXPECT_EQ(m.details["lights"].size(), 16u) << m.message;
      EXPECT_EQ(m.details["layersUsed"].get<std::uint32_t>(), 6u);
      for (const auto& light : m.details["lights"]) EXPECT_EQ(light["given"], 64) << m.message;
    }
  }
  EXPECT_TRUE(degraded) << "no SHD005 note: the faces were not drawn smaller";
  const Image8 expected = to_image8(whole);
  const Image8 actual = to_image8(packed);
  const DiffStats diff = diff_images(expected, actual, 2);
  if (diff.pixels_over > 0) {
    write_failure_images(
        artifact_dir() / "packed_faces" / (std::string(c.graph) + "-" + c.rasterizer), expected,
        actual);
  }
  EXPECT_EQ(diff.pixels_over, 0u) << describe(diff);
}

INSTANTIATE_TEST_SUITE_P(
    Graphs, PackedFacesGpu,
    ::testing::Values(Case{"layered-ssss.json", "hardware"}, Case{"layered-ssss.json", "compute"},
                      Case{"pcss.json", "hardware"}, Case{"layered-ssss-min.json", "hardware"},
                      Case{"vssm.json", "compute"}),
    [](const ::testing::TestParamInfo<Case>& param) {
      std::string name = std::string(param.param.graph) + "_" + param.param.rasterizer;
      std::replace_if(
          name.begin(), name.end(), [](char ch) { return !std::isalnum(ch); }, '_');
      return name;
    });

}  // namespace
