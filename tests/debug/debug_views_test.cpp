// The debug views of data/graphs/debug-views.json, each selected as the output (as
// `render --output layerView` does) on the atrium at 160x90: they render without
// validation errors and show what they claim to.

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/layering/layer_assignment.hpp"
#include "debug_views/debug_palette.hpp"
#include "register_builtin_passes.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr const char* kGraph = "data/graphs/debug-views.json";
const std::vector<std::string> kViews = {"layerView", "penumbraView", "atlasView"};

std::uint32_t rgb_at(const Image8& image, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (std::size_t{y} * image.width + x) * image.channels;
  return (std::uint32_t{image.bytes[i]} << 16) | (std::uint32_t{image.bytes[i + 1]} << 8) |
         image.bytes[i + 2];
}

void set_param(fg::GraphDesc& graph, const std::string& pass, const std::string& name,
               base::Json value) {
  const int index = graph.find_pass(pass);
  ASSERT_GE(index, 0) << pass;
  graph.passes[static_cast<std::size_t>(index)].params[name] = std::move(value);
}

// What light-layering assigns to the scene's shadow casters (world spheres), on the CPU.
int layers_used(const scene::Scene& scene, int max_layers) {
  std::vector<layering::LightSphere> spheres;
  for (const auto& light : scene.lights) {
    if (!light.casts_shadows) continue;
    spheres.push_back(
        {std::hash<std::string>{}(light.name), light.name, light.position, light.range, false});
  }
  layering::LayeringOptions options;
  options.max_layers = max_layers;
  layering::Layering layering;
  return layering.update_world_sphere(spheres, options).layers_used;
}

}  // namespace

class DebugViewsTest : public RenderTest {
 protected:
  // debug-views.json with `output` as its output, after `edit`; renders 2 frames.
  runtime::RenderSession* render_view(const std::string& output,
                                      const std::function<void(fg::GraphDesc&)>& edit = {}) {
    runtime::RenderSession* session = open_session(kSmall);
    if (session == nullptr) return nullptr;
    fg::GraphDesc graph = load_graph_file(source_dir() / kGraph);
    graph.output = output;
    if (edit) edit(graph);
    load_graph_ok(*session, graph);
    if (::testing::Test::HasFatalFailure()) return nullptr;
    // Only the selected view runs; the other views and the lighting chain are culled.
    const auto& culled = session->executor().plan().culled_passes;
    for (const auto& view : kViews) {
      const bool is_culled = std::find(culled.begin(), culled.end(), view) != culled.end();
      EXPECT_EQ(is_culled, view != output) << view;
    }
    session->set_scene(default_scene());
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    return session;
  }
};

#define RENDER_VIEW(var, ...)                                \
  runtime::RenderSession* var = render_view(__VA_ARGS__);    \
  if ((var) == nullptr) {                                    \
    if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_; \
    FAIL() << "graph did not load";                          \
  }

TEST_F(DebugViewsTest, DefaultOutputCullsEveryView) {
  const auto registry = passes::builtin_pass_registry();
  const auto result = fg::compile_file((source_dir() / kGraph).string(), registry.reflection());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  EXPECT_EQ(result.diagnostics().warning_count(), 0u) << result.diagnostics().to_text();
  const auto& culled = result.value().culled_passes;
  for (const auto& view : kViews) {
    EXPECT_NE(std::find(culled.begin(), culled.end(), view), culled.end()) << view;
  }
}

TEST_F(DebugViewsTest, LayerViewShowsOneColourPerLayerUsed) {
  RENDER_VIEW(session, "layerView",
              [](fg::GraphDesc& graph) { set_param(graph, "layerView", "weighting", "dominant"); });
  const Image8 view = to_image8(read_output(*session));
  const std::set<std::uint32_t> palette(passes::kLayerPalette.begin(), passes::kLayerPalette.end());
  std::set<std::uint32_t> seen;
  std::size_t stripes = 0;
  for (std::uint32_t y = 0; y < view.height; ++y) {
    for (std::uint32_t x = 0; x < view.width; ++x) {
      const std::uint32_t rgb = rgb_at(view, x, y);
      if (palette.count(rgb) != 0) seen.insert(rgb);
      if (rgb == passes::kSharedStripeA) ++stripes;
    }
  }
  const int expected = layers_used(default_scene(), 4);
  EXPECT_GE(expected, 2) << "the atrium's lights overlap: more than one layer";
  EXPECT_EQ(static_cast<int>(seen.size()), expected);
  EXPECT_EQ(stripes, 0u) << "no two lights share a layer under the cap";
}

TEST_F(DebugViewsTest, LayerViewStripesLightsSharingALayer) {
  // One layer for overlapping lights: the cap forces them to share it.
  RENDER_VIEW(session, "layerView",
              [](fg::GraphDesc& graph) { set_param(graph, "layers", "maxLayers", 1); });
  const Image8 view = to_image8(read_output(*session));
  std::size_t red = 0;
  std::size_t white = 0;
  for (std::uint32_t y = 0; y < view.height; ++y) {
    for (std::uint32_t x = 0; x < view.width; ++x) {
      const std::uint32_t rgb = rgb_at(view, x, y);
      red += rgb == passes::kSharedStripeA ? 1 : 0;
      white += rgb == passes::kSharedStripeB ? 1 : 0;
    }
  }
  EXPECT_GT(red, 0u);
  EXPECT_GT(white, 0u);
}

TEST_F(DebugViewsTest, PenumbraViewIsColouredExactlyWhereThePenumbraIsNonZero) {
  RENDER_VIEW(session, "penumbraView");
  const auto view = read_output(*session);
  // Nothing runs after the view, so the penumbra's memory still holds this frame's.
  const auto penumbra = read_resource(*session, "penumbra");
  ASSERT_EQ(penumbra.channels, 4u);
  std::size_t nonzero = 0;
  std::size_t mismatched = 0;
  for (std::uint32_t y = 0; y < view.height; ++y) {
    for (std::uint32_t x = 0; x < view.width; ++x) {
      const std::uint32_t sx = x * penumbra.width / view.width;
      const std::uint32_t sy = y * penumbra.height / view.height;
      float widest = 0.0f;
      for (std::uint32_t c = 0; c < 4; ++c) widest = std::max(widest, penumbra.at(sx, sy, c));
      const float shown = view.at(x, y, 0) + view.at(x, y, 1) + view.at(x, y, 2);
      nonzero += widest > 0.0f ? 1 : 0;
      mismatched += (widest > 0.0f) != (shown > 0.0f) ? 1 : 0;
    }
  }
  EXPECT_GT(nonzero, view.width * view.height / 100) << "the atrium has penumbrae";
  EXPECT_EQ(mismatched, 0u);
  EXPECT_FALSE(is_blank(view));
}

TEST_F(DebugViewsTest, AtlasViewShowsShadowFaces) {
  RENDER_VIEW(session, "atlasView");
  const auto view = read_output(*session);
  EXPECT_FALSE(is_blank(view));
  const TexelStats stats = texel_stats(view);
  EXPECT_EQ(stats.non_finite, 0u);
  EXPECT_GT(stats.max, 0.5f) << "faces hold geometry near their light";
}
