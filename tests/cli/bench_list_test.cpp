// `bench --list` and `bench --quick` without a device: --list prints what the filters
// select (the names a run would measure), and --quick's scale shows in those names
// unless --scale is given.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_process.hpp"

namespace antumbra::test {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(BenchList, HonoursTheScenarioFilters) {
  const auto run = run_antumbra({"bench", "--list", "--scenario", "table1/hard/", "--scenario",
                                 "moving/ssss-11/1080p/16l/compute/screen/vis"},
                                test_folder());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(lines(run.out),
            (std::vector<std::string>{"table1/hard/720p", "table1/hard/1080p",
                                      "moving/ssss-11/1080p/16l/compute/screen/vis"}));
}

TEST(BenchList, AFilterThatMatchesNothingIsAUsageError) {
  const auto run =
      run_antumbra({"bench", "--list", "--scenario", "no-such-scenario"}, test_folder());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_NE(run.err.find("no scenario matches"), std::string::npos) << run.err;
}

TEST(BenchList, QuickShrinksTheTableAndTheDistrictFurther) {
  const auto run =
      run_antumbra({"bench", "--quick", "--list", "--scenario", "moving/hard/"}, test_folder());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto names = lines(run.out);
  ASSERT_EQ(names.size(), 16u);  // 4 light counts x 4 rasteriser variants
  EXPECT_EQ(names.front(), "moving/hard/270p/16l");
  EXPECT_EQ(names.back(), "moving/hard/135p/256l-district/compute/screen/vis");
}

TEST(BenchList, AnExplicitScaleWinsOverQuick) {
  const auto run =
      run_antumbra({"bench", "--quick", "--scale", "0.5", "--list", "--scenario", "moving/hard/"},
                   test_folder());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto names = lines(run.out);
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "moving/hard/540p/16l");
  EXPECT_EQ(names.back(), "moving/hard/270p/256l-district/compute/screen/vis");
}

TEST(BenchHelp, StatesTheDefaultWarmupAndWhatQuickSets) {
  const auto run = run_antumbra({"bench", "--help"}, test_folder());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("--warmup INT:INT in [0 - 100000]=10"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--frames 3 --warmup 1 --scale 0.25"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace antumbra::test
