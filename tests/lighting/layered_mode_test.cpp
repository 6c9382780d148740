// tiled-lighting's `layered` mode against a synthetic blurred shadow buffer and layer
// table, written by a test-only pass (clears + buffer update) in a registry of its own,
// since the layered-penumbra / anisotropic-blur producers are tested elsewhere. Checks
// the layer -> (array layer L/4, channel L%4) mapping, that the lighting is linear in the
// per-layer visibility, and that a light without a layer stays unshadowed when no atlas
// is bound.

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <memory>
#include <string>

#include "antumbra/fg/param_table.hpp"
#include "common/layer_table.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "executor_harness.hpp"
#include "lighting_test_support.hpp"

using namespace antumbra;
using namespace antumbra::lighting_testing;

namespace {

constexpr std::uint32_t kLayerOfLight0 = 0;  // array layer 0, channel r
constexpr std::uint32_t kLayerOfLight1 = 5;  // array layer 1, channel g
constexpr float kDecoy = 0.7f;               // in every channel no light reads

// "test-layer-fill": visibility `a` for light 0's layer, `b` for light 1's; light 1 has
// no layer when `light1HasLayer` is false.
class LayerFillPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe() {
    fg::PassDesc desc;
    desc.type = "test-layer-fill";
    desc.ports = {
        {.name = passes::port::kShadow,
         .direction = fg::PortDirection::output,
         .access = fg::Access::transfer_dst,
         .stage = fg::Stage::transfer,
         .formats = {fg::Format::rgba16f},
         .min_layers = 2,
         .max_layers = 2},
        {.name = passes::port::kLayerTable,
         .direction = fg::PortDirection::output,
         .kind = fg::ResourceKind::buffer,
         .access = fg::Access::transfer_dst,
         .stage = fg::Stage::transfer},
    };
    desc.params = param_table().descs();
    return desc;
  }
  struct Params {
    float a = 1.0f;
    float b = 1.0f;
    bool light1_has_layer = true;
  };
  static const fg::ParamTable<Params>& param_table() {
    static const auto kTable =
        fg::ParamTable<Params>()
            .add({.name = "a", .type = fg::ParamType::number, .default_value = 1.0}, &Params::a)
            .add({.name = "b", .type = fg::ParamType::number, .default_value = 1.0}, &Params::b)
            .add({.name = "light1HasLayer", .type = fg::ParamType::boolean, .default_value = true},
                 &Params::light1_has_layer);
    return kTable;
  }
  explicit LayerFillPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {}
  void prepare(fgvk::PrepareContext& /*context*/) override {}
  void execute(fgvk::ExecuteContext& context) override {
    const float a = params_.a;
    const float b = params_.b;
    const auto& shadow = context.bindings.required_image(passes::port::kShadow);
    const std::array<VkClearColorValue, 2> values{
        {{{a, kDecoy, kDecoy, kDecoy}}, {{kDecoy, b, kDecoy, kDecoy}}}};
    for (std::uint32_t layer = 0; layer < 2; ++layer) {
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, layer, 1};
      vkCmdClearColorImage(context.cmd, shadow.image, shadow.layout, &values[layer], 1, &range);
    }
    std::vector<std::uint32_t> table(passes::kLayerTableBytes / 4, passes::kNoLayer);
    table[0] = 2;  // light count
    table[1] = 6;  // layers used
    table[4] = kLayerOfLight0;
    table[5] = params_.light1_has_layer ? kLayerOfLight1 : passes::kNoLayer;
    vkCmdUpdateBuffer(context.cmd, context.bindings.buffer(passes::port::kLayerTable)->buffer, 0,
                      passes::kLayerTableBytes, table.data());
  }

 private:
  Params params_;
};

std::unique_ptr<fgvk::Pass> make_fill(const fg::PlanPass& pass) {
  return std::make_unique<LayerFillPass>(pass);
}

std::string layered_graph(float a, float b, bool light1_has_layer) {
  return R"({ "version": 1, "name": "layered", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "shadow": { "kind": "image", "format": "rgba16f", "size": "viewport/2", "layers": 2 },
    "layerTable": { "kind": "buffer", "size": )" +
         std::to_string(passes::kLayerTableBytes) + R"( },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "fill", "type": "test-layer-fill", "params": { "a": )" +
         std::to_string(a) + R"(, "b": )" + std::to_string(b) + R"(, "light1HasLayer": )" +
         (light1_has_layer ? "true" : "false") + R"( },
      "out": { "shadow": "shadow", "layerTable": "layerTable" } },
    { "name": "lighting", "type": "tiled-lighting", "params": { "shadows": "layered" },
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo", "shadow": "shadow",
              "layerTable": "layerTable" },
      "out": { "hdr": "hdr" } } ],
  "output": "hdr" })";
}

class LayeredModeTest : public ExecutorTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    scene::Scene scene = floor_scene();
    add_light(scene, {-2.0f, 1.0f, 0.0f}, {1.0f, 0.8f, 0.6f}, 2.0f, 4.0f);
    add_light(scene, {2.0f, 1.0f, 0.5f}, {0.6f, 0.8f, 1.0f}, 2.0f, 4.0f);
    if (!open(std::move(scene), {{LayerFillPass::describe(), &make_fill}}))
      GTEST_SKIP() << skip_reason_;
  }
  gpu::HostImage render(const std::string& graph_text) {
    return ExecutorTest::render(graph_text, kSmall);
  }
};

// |actual - expected| <= 4e-3 * |expected| + 2e-4 per channel: four rgba16f rounding
// steps of each of the (up to four) images combined, plus near-black slack.
void expect_close(const gpu::HostImage& expected, const gpu::HostImage& actual, const char* what) {
  ASSERT_EQ(expected.texels.size(), actual.texels.size());
  std::size_t over = 0;
  float worst = 0.0f;
  for (std::size_t i = 0; i < expected.texels.size(); ++i) {
    const float d = std::abs(expected.texels[i] - actual.texels[i]);
    worst = std::max(worst, d);
    if (!(d <= 4e-3f * std::abs(expected.texels[i]) + 2e-4f)) ++over;
  }
  EXPECT_EQ(over, 0u) << what << ": worst difference " << worst;
}

}  // namespace

TEST_F(LayeredModeTest, EachLightReadsItsOwnLayer) {
  const auto lit = render(layered_graph(1.0f, 1.0f, true));
  const auto h00 = render(layered_graph(0.0f, 0.0f, true));
  const auto h10 = render(layered_graph(1.0f, 0.0f, true));
  const auto h01 = render(layered_graph(0.0f, 1.0f, true));
  const auto mixed = render(layered_graph(0.25f, 0.5f, true));
  ASSERT_FALSE(render_testing::is_blank(lit));
  // Both layers fully lit == the unshadowed tiled image (the decoy channels unread).
  expect_close(render(R"({ "version": 1, "name": "none", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "lighting", "type": "tiled-lighting",
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo" }, "out": { "hdr": "hdr" } } ],
  "output": "hdr" })"),
               lit, "layers at 1 vs shadows none");
  // Each light's layer scales that light only: h(a, b) = h00 + a (h10 - h00) + b (h01 - h00).
  gpu::HostImage expected = h00;
  gpu::HostImage sum = h00;
  for (std::size_t i = 0; i < expected.texels.size(); ++i) {
    expected.texels[i] +=
        0.25f * (h10.texels[i] - h00.texels[i]) + 0.5f * (h01.texels[i] - h00.texels[i]);
    sum.texels[i] += (h10.texels[i] - h00.texels[i]) + (h01.texels[i] - h00.texels[i]);
  }
  expect_close(expected, mixed, "visibility 0.25 / 0.5");
  expect_close(sum, lit, "light contributions add up");
  EXPECT_GT(render_testing::texel_stats(h10).mean, render_testing::texel_stats(h00).mean * 1.5);
  EXPECT_GT(render_testing::texel_stats(h01).mean, render_testing::texel_stats(h00).mean * 1.5);
}

TEST_F(LayeredModeTest, LightWithoutLayerIsUnshadowedWithoutAtlas) {
  // Light 1 has no layer: its `b` is ignored and it shades fully.
  expect_close(render(layered_graph(0.0f, 1.0f, true)), render(layered_graph(0.0f, 0.0f, false)),
               "no-layer light");
}
