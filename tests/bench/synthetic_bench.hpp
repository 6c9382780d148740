#pragma once
// Synthetic bench.json files for the `bench --baseline` tests: what `antumbra bench`
// writes, cut down to what the comparison reads, and two runs to compare.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bench_baseline.hpp"

namespace antumbra::app::test {

using Passes = std::vector<std::pair<std::string, double>>;  // name (and type), median ms

inline nlohmann::json scenario(const std::string& name, double frame_ms, const Passes& passes,
                               const std::string& status = "ok") {
  auto list = nlohmann::json::array();
  for (const auto& [pass, ms] : passes) {
    list.push_back({{"name", pass}, {"type", pass}, {"medianMs", ms}, {"p10Ms", ms}});
  }
  return {{"scenario", name},
          {"status", status},
          {"detail", status == "ok" ? "" : "FG030 ..."},
          {"frame", {{"medianMs", frame_ms}, {"p10Ms", frame_ms}, {"frames", 60}}},
          {"passes", list}};
}

inline nlohmann::json bench_json(const std::string& device, std::vector<nlohmann::json> scenarios) {
  return {
      {"commit", "abc1234"}, {"device", device}, {"driver", "driver 1.0"},           {"frames", 60},
      {"warmup", 10},        {"scale", 1.0},     {"scenarios", std::move(scenarios)}};
}

// A file under the temporary folder, unique per test (ctest runs tests side by side).
inline std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() / "antumbra_bench_baseline_test" /
                   (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The baseline: pcss and hard compared, "gone" only in it, "broken" failed in it.
inline nlohmann::json baseline_json() {
  return bench_json(
      "GPU A",
      {scenario("t/pcss", 3.5, {{"gbuffer", 1.0}, {"atlas", 2.0}, {"light", 0.5}}),
       scenario("t/hard", 1.0, {{"gbuffer", 1.0}}), scenario("t/gone", 2.0, {{"gbuffer", 2.0}}),
       scenario("t/broken", 0.0, {}, "invalid")});
}

// This run: pcss's atlas 10 % (0.2 ms) slower and its frame 5.9 %; light 1 %; hard's
// tonemap only here, its frame 1 % (0.01 ms) slower; "new" only here; "broken" ok.
inline nlohmann::json run_json() {
  return bench_json(
      "GPU A",
      {scenario("t/pcss", 3.705, {{"gbuffer", 1.0}, {"atlas", 2.2}, {"light", 0.505}}),
       scenario("t/hard", 1.01, {{"gbuffer", 1.0}, {"tonemap", 0.01}}),
       scenario("t/new", 0.5, {{"gbuffer", 0.5}}), scenario("t/broken", 1.0, {{"gbuffer", 1.0}})});
}

// Both written to files and read back as `bench --baseline` reads a baseline.
struct TwoRuns {
  BenchFile baseline;
  BenchFile run;
  BaselineComparison comparison;
};

inline TwoRuns two_runs(const SlowerRule& rule = {}) {
  TwoRuns two;
  two.baseline = load_bench_file(write_file("B.json", baseline_json().dump(2)).string());
  two.run = load_bench_file(write_file("R.json", run_json().dump(2)).string());
  two.comparison = compare_with_baseline(two.baseline.results, two.run.results, rule);
  return two;
}

}  // namespace antumbra::app::test
