// The accuracy targets of layered SSSS (docs/technique.md 1, step 6, and 7), checked on the
// quality results committed under docs/results/ (`antumbra quality --format json` against
// data/graphs/reference.json, which traces rays): re-measuring after a change that costs
// accuracy fails here, without a device. Which results these are is docs/measuring.md's
// table. tests/quality/technique_quality_gpu_test.cpp checks looser bars on lavapipe at
// 320x180, where the layers' half resolution is a coarser share of the frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

const std::filesystem::path kResults =
    std::filesystem::path(ANTUMBRA_TEST_SOURCE_DIR) / "docs" / "results";

nlohmann::json load(const std::string& name) {
  std::ifstream in(kResults / name);
  EXPECT_TRUE(in.good()) << (kResults / name);
  return nlohmann::json::parse(in, nullptr, false);
}

// RMSE of graph `graph` (data/graphs/NAME.json) over `region`; -1 when not measured.
double rmse(const nlohmann::json& results, const std::string& graph, const std::string& region) {
  for (const auto& g : results.value("graphs", nlohmann::json::array())) {
    if (g.value("graph", "") == "data/graphs/" + graph + ".json") {
      return g.at("regions").at(region).at("rmse").get<double>();
    }
  }
  return -1.0;
}

// The numbers were measured against the shipped reference graph, on the scene and at the
// size the targets name. Files written since `quality` records the reference's passes
// ("referencePasses") must show rays; older ones record only the graph's path.
void expect_measured_on(const nlohmann::json& results, const std::string& file,
                        const std::string& scene, int width, int height) {
  EXPECT_EQ(std::filesystem::path(results.value("reference", "")).filename(), "reference.json")
      << file;
  for (const auto& pass : results.value("referencePasses", nlohmann::json::array())) {
    EXPECT_EQ(pass.value("params", nlohmann::json::object()).value("visibility", "shadowMaps"),
              "rays")
        << file << ": the reference pass " << pass.value("name", "") << " does not trace rays";
  }
  EXPECT_EQ(std::filesystem::path(results.value("scene", "")).filename(), scene) << file;
  EXPECT_EQ(results.value("width", 0), width) << file;
  EXPECT_EQ(results.value("height", 0), height) << file;
}

struct AtriumResults {
  const char* file;
  int width;
  int height;
};

class CommittedQuality : public ::testing::TestWithParam<AtriumResults> {};

// On the default atrium, layered SSSS is no further from the reference than PCSS over all
// pixels, penumbra pixels and overlapping-penumbra pixels.
TEST_P(CommittedQuality, LayeredSsssIsNoWorseThanPcss) {
  const std::string file = GetParam().file;
  const auto results = load(file);
  ASSERT_FALSE(results.is_discarded()) << file;
  expect_measured_on(results, file, "atrium.json", GetParam().width, GetParam().height);
  for (const char* region : {"all", "penumbra", "overlap"}) {
    const double layered = rmse(results, "layered-ssss", region);
    const double pcss = rmse(results, "pcss", region);
    ASSERT_GT(layered, 0.0) << file << ": no layered-ssss " << region;
    ASSERT_GT(pcss, 0.0) << file << ": no pcss " << region;
    EXPECT_LE(layered, pcss) << file << " region " << region;
  }
}

INSTANTIATE_TEST_SUITE_P(Atrium, CommittedQuality,
                         ::testing::Values(AtriumResults{"quality-640x360.json", 640, 360},
                                           AtriumResults{"quality-1280x720.json", 1280, 720}),
                         [](const ::testing::TestParamInfo<AtriumResults>& results) {
                           return std::to_string(results.param.width) + "x" +
                                  std::to_string(results.param.height);
                         });

// On the scene of four overlapping penumbrae, layered SSSS keeps at most 0.6x PCSS's error
// and 0.1x the single-layer variant's on the overlapping pixels.
TEST(CommittedQualityOverlap, LayeredSsssKeepsItsLeadWherePenumbraeOverlap) {
  const auto results = load("quality-overlap-640x360.json");
  ASSERT_FALSE(results.is_discarded());
  expect_measured_on(results, "quality-overlap-640x360.json", "overlap.json", 640, 360);
  const double layered = rmse(results, "layered-ssss", "overlap");
  const double pcss = rmse(results, "pcss", "overlap");
  const double single = rmse(results, "single-layer", "overlap");
  ASSERT_GT(layered, 0.0);
  ASSERT_GT(pcss, 0.0);
  ASSERT_GT(single, 0.0) << "the overlap results lack data/graphs/single-layer.json";
  EXPECT_LE(layered, 0.6 * pcss);
  EXPECT_LE(layered, 0.1 * single);
}

}  // namespace
