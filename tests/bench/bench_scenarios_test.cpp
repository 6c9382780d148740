// Scenario names and sizes under --scale: the names say the size that is rendered and
// the shadow atlas shrinks with the screen.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "antumbra/base/json_document.hpp"
#include "bench_scenarios.hpp"

namespace antumbra::app {
namespace {

const Scenario& named(const std::vector<Scenario>& all, const std::string& name) {
  for (const auto& s : all) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no scenario " + name);
}

TEST(BenchScenarios, FullScaleKeepsTheSeedsNames) {
  const auto all = builtin_scenarios(1.0);
  const auto& s = named(all, "table1/pcss-11/720p");
  EXPECT_EQ(s.width, 1280u);
  EXPECT_EQ(s.height, 720u);
  EXPECT_EQ(s.face, 1024u);
  EXPECT_EQ(named(all, "lights/ssss-11/1080p/1024l").face, 512u);
}

TEST(BenchScenarios, NamesCarryTheScaledSize) {
  const auto all = builtin_scenarios(0.25);
  std::set<std::string> names;
  for (const auto& s : all) {
    names.insert(s.name);
    EXPECT_EQ(s.name.find("720p"), std::string::npos) << s.name;
    EXPECT_EQ(s.name.find("1080p"), std::string::npos) << s.name;
    const std::string size = '/' + std::to_string(s.height) + 'p';
    EXPECT_NE(s.name.find(size), std::string::npos) << s.name;
  }
  EXPECT_EQ(names.size(), all.size()) << "two scenarios share a name";
  const auto& s = named(all, "table1/pcss-11/180p");
  EXPECT_EQ(s.width, 320u);
  EXPECT_EQ(s.height, 180u);
  EXPECT_EQ(named(all, "table2/ssss-11/270p/4l").width, 480u);
}

TEST(BenchScenarios, ScaleShrinksTheAtlasFaces) {
  const auto all = builtin_scenarios(0.25);
  EXPECT_EQ(named(all, "table1/hard/180p").face, 256u);
  EXPECT_EQ(named(all, "lights/ssss-11/270p/1024l").face, 128u);
}

TEST(BenchScenarios, FaceSizesDivideByTheDerivedMapsFactors) {
  for (const double scale : {0.01, 0.1, 0.33, 0.5, 1.0, 1.7}) {
    for (const int lights : {16, 1024}) {
      const unsigned face = shadow_face_size(lights, scale);
      EXPECT_GE(face, 16u);
      EXPECT_EQ(face % 16, 0u) << "scale " << scale;
    }
  }
  EXPECT_EQ(shadow_face_size(16, 0.1), 96u);
}

TEST(BenchScenarios, FitShadowResourcesUsesTheFaceAndKeepsTheMinMapsFactor) {
  auto document = base::load_json_file(std::string(ANTUMBRA_TEST_SOURCE_DIR) +
                                       "/data/graphs/layered-ssss-min.json");
  ASSERT_TRUE(document.ok());
  auto graph = fg::parse_graph(document.value());
  ASSERT_TRUE(graph.ok());
  fit_shadow_resources(graph.value(), 4, shadow_face_size(4, 0.25));
  const auto& resources = graph->resources;
  const auto& atlas = resources[static_cast<std::size_t>(graph->find_resource("atlas"))];
  const auto& colour = resources[static_cast<std::size_t>(graph->find_resource("shadowColour"))];
  const auto& min_depth = resources[static_cast<std::size_t>(graph->find_resource("minDepth"))];
  EXPECT_EQ(atlas.size.width, 256u);
  EXPECT_EQ(atlas.size.height, 256u);
  EXPECT_EQ(atlas.layers, 24u);
  EXPECT_EQ(colour.size.width, 256u);
  EXPECT_EQ(min_depth.size.width, 32u);  // the graph's 1024 / 128 = 8 kept
  EXPECT_EQ(min_depth.layers, 24u);
}

}  // namespace
}  // namespace antumbra::app
