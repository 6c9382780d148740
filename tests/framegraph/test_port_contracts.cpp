// Declared size and layer contracts between the ports of one pass (fg::PortDesc::size_of,
// layers_of): each relation accepted and refused at its edges, relative sizes judged by
// their scales, absolute and mixed ones by their extents, FG092 located at the binding of
// the port that states the contract and naming both resources and their sizes.

#include <gtest/gtest.h>

#include <string>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/fg/registry.hpp"

using namespace antumbra;
using namespace antumbra::fg;

namespace {

// "writer" makes `full`; "shrink" reads it and writes `small` under the given contracts.
Registry registry_with(std::optional<SizeContract> size, std::optional<LayerContract> layers) {
  Registry registry;
  registry.add(PassDesc{.type = "writer",
                        .ports = {{.name = "full",
                                   .direction = PortDirection::output,
                                   .access = Access::storage_write,
                                   .stage = Stage::compute,
                                   .max_layers = 0}}});
  registry.add(PassDesc{
      .type = "shrink",
      .ports =
          {{.name = "full", .access = Access::sampled, .stage = Stage::compute, .max_layers = 0},
           {.name = "small",
            .direction = PortDirection::output,
            .access = Access::storage_write,
            .stage = Stage::compute,
            .max_layers = 0,
            .size_of = std::move(size),
            .layers_of = std::move(layers)}},
      .side_effects = true});
  return registry;
}

std::string graph(const std::string& full_size, const std::string& small_size, int full_layers = 1,
                  int small_layers = 1) {
  return R"({"version": 1, "resources": {
    "a": {"kind": "image", "format": "rgba8", "size": )" +
         full_size + R"(, "layers": )" + std::to_string(full_layers) + R"(},
    "b": {"kind": "image", "format": "rgba8", "size": )" +
         small_size + R"(, "layers": )" + std::to_string(small_layers) + R"(}},
  "passes": [
    {"name": "w", "type": "writer", "out": {"full": "a"}},
    {"name": "s", "type": "shrink", "in": {"full": "a"}, "out": {"small": "b"}}],
  "output": "b"})";
}

Result<Plan> compile_with(const Registry& registry, const std::string& text,
                          Extent2D viewport = {64, 32}) {
  CompileOptions options;
  options.viewport = viewport;
  return compile_text(text, "contract.json", registry, options);
}

bool accepts(SizeRelation relation, const std::string& full, const std::string& small,
             Extent2D viewport = {64, 32}) {
  return compile_with(registry_with(SizeContract{"full", relation}, std::nullopt),
                      graph(full, small), viewport)
      .ok();
}

}  // namespace

TEST(PortContracts, SameSize) {
  EXPECT_TRUE(accepts(SizeRelation::same, "\"viewport\"", "\"viewport\""));
  EXPECT_TRUE(accepts(SizeRelation::same, "[64, 32]", "\"viewport\""));  // mixed: the extents
  EXPECT_FALSE(accepts(SizeRelation::same, "\"viewport\"", "\"viewport/2\""));
  EXPECT_FALSE(accepts(SizeRelation::same, "[64, 32]", "[64, 33]"));
}

// The reported case of the default graph's blur: located at the port stating the contract,
// both resources and both sizes named.
TEST(PortContracts, ABrokenContractIsLocatedAtItsBindingAndNamesBothResources) {
  const auto registry = registry_with(SizeContract{"full", SizeRelation::same}, std::nullopt);
  const auto result = compile_with(registry, graph("\"viewport\"", "\"viewport/2\""));
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* d = result.diagnostics().find("FG092");
  ASSERT_NE(d, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/passes/1/out/small");
  EXPECT_GT(d->line, 0);
  for (const char* part : {"port 'small' must be same size as `full`",
                           "its resource 'b' is viewport/2 (32x16 at a 64x32 viewport)",
                           "'a', bound to port 'full', is viewport (64x32 at a 64x32 viewport)",
                           "; change one of /resources/b/size and /resources/a/size"}) {
    EXPECT_NE(d->message.find(part), std::string::npos) << part << "\n" << d->message;
  }
}

TEST(PortContracts, SameOrHalf) {
  EXPECT_TRUE(accepts(SizeRelation::same_or_half, "\"viewport\"", "\"viewport\""));
  EXPECT_TRUE(accepts(SizeRelation::same_or_half, "\"viewport\"", "\"viewport/2\""));
  EXPECT_FALSE(accepts(SizeRelation::same_or_half, "\"viewport\"", "\"viewport/4\""));
  EXPECT_FALSE(accepts(SizeRelation::same_or_half, "\"viewport/2\"", "\"viewport\""));
  EXPECT_TRUE(accepts(SizeRelation::same_or_half, "[101, 60]", "[50, 30]"));   // floor(101 / 2)
  EXPECT_FALSE(accepts(SizeRelation::same_or_half, "[100, 60]", "[50, 20]"));  // not one factor
}

// Two relative sizes are judged by their scales: the verdict cannot change with the window.
TEST(PortContracts, RelativeSizesHoldAtEveryViewport) {
  for (const Extent2D viewport : {Extent2D{64, 32}, Extent2D{47, 27}, Extent2D{1, 1}}) {
    EXPECT_TRUE(accepts(SizeRelation::fraction, "\"viewport\"", "\"viewport/3\"", viewport));
    EXPECT_FALSE(accepts(SizeRelation::same, "\"viewport\"", "\"viewport/2\"", viewport));
  }
  // At 1x1 both sizes resolve to 1x1, yet half of the viewport is not the viewport.
  EXPECT_FALSE(accepts(SizeRelation::same, "\"viewport\"", "\"viewport/2\"", {1, 1}));
}

TEST(PortContracts, Fractions) {
  EXPECT_TRUE(accepts(SizeRelation::fraction, "[1920, 1080]", "[640, 360]"));
  EXPECT_TRUE(accepts(SizeRelation::fraction, "[47, 27]", "[23, 13]"));  // floor(x / 2)
  EXPECT_FALSE(accepts(SizeRelation::fraction, "[1920, 1080]", "[640, 540]"));
  EXPECT_FALSE(accepts(SizeRelation::fraction, "\"viewport/2\"", "\"viewport\""));
  EXPECT_TRUE(accepts(SizeRelation::exact_fraction, "[1024, 1024]", "[256, 256]"));
  EXPECT_FALSE(accepts(SizeRelation::exact_fraction, "[1024, 1024]", "[300, 300]"));
  EXPECT_TRUE(accepts(SizeRelation::exact_fraction_even, "[1024, 1024]", "[1024, 1024]"));
  EXPECT_TRUE(accepts(SizeRelation::exact_fraction_even, "[1024, 1024]", "[512, 512]"));
  EXPECT_FALSE(accepts(SizeRelation::exact_fraction_even, "[1536, 1536]", "[512, 512]"));
  // Mixed: judged at the viewport compiled for.
  EXPECT_TRUE(accepts(SizeRelation::fraction, "\"viewport\"", "[32, 16]", {64, 32}));
  EXPECT_FALSE(accepts(SizeRelation::fraction, "\"viewport\"", "[30, 16]", {64, 32}));
}

TEST(PortContracts, Layers) {
  const auto same = registry_with(std::nullopt, LayerContract{"full", LayerRelation::same});
  const auto at_least = registry_with(std::nullopt, LayerContract{"full", LayerRelation::at_least});
  EXPECT_TRUE(compile_with(same, graph("\"viewport\"", "\"viewport\"", 6, 6)).ok());
  const auto fewer = compile_with(same, graph("\"viewport\"", "\"viewport\"", 6, 4));
  ASSERT_FALSE(fewer.ok());
  const base::Diagnostic* d = fewer.diagnostics().find("FG092");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("'b' has 4 layer(s) and 'a', bound to port 'full', 6; change one of "
                            "/resources/b/layers and /resources/a/layers"),
            std::string::npos)
      << d->message;
  EXPECT_FALSE(compile_with(same, graph("\"viewport\"", "\"viewport\"", 6, 8)).ok());
  EXPECT_TRUE(compile_with(at_least, graph("\"viewport\"", "\"viewport\"", 6, 8)).ok());
  EXPECT_FALSE(compile_with(at_least, graph("\"viewport\"", "\"viewport\"", 6, 5)).ok());
}

// An unbound other port leaves nothing to compare.
TEST(PortContracts, AnUnboundOtherPortHolds) {
  Registry registry;
  registry.add(PassDesc{.type = "lone",
                        .ports = {{.name = "full", .stage = Stage::compute, .optional = true},
                                  {.name = "small",
                                   .direction = PortDirection::output,
                                   .access = Access::storage_write,
                                   .stage = Stage::compute,
                                   .size_of = SizeContract{"full", SizeRelation::same}}},
                        .side_effects = true});
  const auto result = compile_with(registry, R"({"version": 1, "resources": {
      "b": {"kind": "image", "format": "rgba8", "size": [3, 3]}},
    "passes": [{"name": "l", "type": "lone", "out": {"small": "b"}}], "output": "b"})");
  EXPECT_TRUE(result.ok()) << result.diagnostics().to_text();
}

// A contract against a port the type lacks would be skipped as if unbound: refused when the
// type is registered.
TEST(PortContracts, TheRegistryRefusesAContractAgainstAPortTheTypeLacks) {
  Registry registry;
  PassDesc desc{.type = "typo",
                .ports = {{.name = "out",
                           .direction = PortDirection::output,
                           .size_of = SizeContract{"depht", SizeRelation::same}}}};
  try {
    registry.add(desc);
    FAIL() << "registered";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'out' states a contract against 'depht'"),
              std::string::npos)
        << e.what();
  }
}

// The reference prints the contracts from the same declaration the compiler checks.
TEST(PortContracts, TheReferenceShowsThem) {
  const auto registry = registry_with(SizeContract{"full", SizeRelation::fraction},
                                      LayerContract{"full", LayerRelation::at_least});
  const Json json = pass_reference_json(*registry.find("shrink"));
  const Json& small = json.at("ports").at(1);
  EXPECT_EQ(small.at("sizeOf"), (Json{{"port", "full"}, {"relation", "fraction"}}));
  EXPECT_EQ(small.at("layersOf"), (Json{{"port", "full"}, {"relation", "atLeast"}}));
  EXPECT_NE(pass_reference_markdown(registry).find(
                "an integer fraction of `full`; at least as many layers as `full`"),
            std::string::npos);
}
