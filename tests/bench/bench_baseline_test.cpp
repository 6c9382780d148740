// `bench --baseline`: reading a baseline bench.json (and the errors that name the file
// and the place), matching scenarios and passes, the ratio and the "slower" rule.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_bench.hpp"

namespace antumbra::app {
namespace {

using Kind = BaselineRow::Kind;
using test::two_runs;
using test::write_file;

TEST(BenchBaseline, ReadsWhatTheComparisonNeeds) {
  const auto two = two_runs();
  const auto& b = two.baseline;
  EXPECT_EQ(b.device, "GPU A");
  EXPECT_EQ(b.commit, "abc1234");
  EXPECT_EQ(b.frames, 60);
  ASSERT_EQ(b.results.size(), 4u);
  EXPECT_EQ(b.results[0].scenario.name, "t/pcss");
  EXPECT_DOUBLE_EQ(b.results[0].frame.median_ms, 3.5);
  ASSERT_EQ(b.results[0].passes.size(), 3u);
  EXPECT_EQ(b.results[0].passes[1].name, "atlas");
  EXPECT_DOUBLE_EQ(b.results[0].passes[1].gpu.median_ms, 2.0);
  EXPECT_EQ(b.results[3].status, "invalid");
}

TEST(BenchBaseline, RatiosAndFlagsOfTwoBenchFiles) {
  const auto rows = two_runs().comparison.rows;
  ASSERT_EQ(rows.size(), 10u);
  const auto expect = [&](std::size_t i, const char* scenario, const char* pass, Kind kind,
                          std::optional<double> ratio, bool slower) {
    SCOPED_TRACE(i);
    EXPECT_EQ(rows[i].scenario, scenario);
    EXPECT_EQ(rows[i].pass, pass);
    EXPECT_EQ(rows[i].kind, kind);
    EXPECT_EQ(rows[i].ratio.has_value(), ratio.has_value());
    if (ratio && rows[i].ratio) {
      EXPECT_NEAR(*rows[i].ratio, *ratio, 1e-12);
    }
    EXPECT_EQ(rows[i].slower, slower);
  };
  expect(0, "t/pcss", "gbuffer", Kind::compared, 1.0, false);
  expect(1, "t/pcss", "atlas", Kind::compared, 1.1, true);
  expect(2, "t/pcss", "light", Kind::compared, 1.01, false);
  expect(3, "t/pcss", "frame", Kind::compared, 3.705 / 3.5, true);
  expect(4, "t/hard", "gbuffer", Kind::compared, 1.0, false);
  expect(5, "t/hard", "tonemap", Kind::only_in_run, std::nullopt, false);
  expect(6, "t/hard", "frame", Kind::compared, 1.01, false);  // 1 %, and 0.01 ms
  expect(7, "t/new", "frame", Kind::only_in_run, std::nullopt, false);
  expect(8, "t/broken", "frame", Kind::failed, std::nullopt, false);
  expect(9, "t/gone", "frame", Kind::only_in_baseline, std::nullopt, false);
  EXPECT_DOUBLE_EQ(*rows[1].baseline_ms, 2.0);
  EXPECT_DOUBLE_EQ(*rows[1].run_ms, 2.2);
  EXPECT_EQ(rows[1].run_scenario, 0u);
  EXPECT_EQ(rows[1].run_pass, 1u);
  EXPECT_FALSE(rows[3].run_pass);
  EXPECT_FALSE(rows[9].run_scenario);
}

TEST(BenchBaseline, FailSlowerPercentSetsTheRatioThreshold) {
  const auto comparison = two_runs(SlowerRule::from_percent(10.0)).comparison;
  EXPECT_EQ(comparison.slower_count(), 1u);  // the atlas (10 %), not the frame (5.9 %)
  EXPECT_TRUE(comparison.rows[1].slower);
}

TEST(SlowerRule, FivePercentAndTwoHundredthsOfAMillisecond) {
  const SlowerRule rule;
  EXPECT_FALSE(rule.slower(1.0, 1.049));  // 4.9 %
  EXPECT_TRUE(rule.slower(1.0, 1.05));    // 5 %
  EXPECT_TRUE(rule.slower(10.0, 10.5));   // 5 %, not lost to rounding
  EXPECT_TRUE(rule.slower(0.4, 0.42));    // 5 % and exactly 0.02 ms
  EXPECT_FALSE(rule.slower(0.1, 0.11));   // 10 % but only 0.01 ms
  EXPECT_FALSE(rule.slower(2.0, 1.0));    // faster
  EXPECT_TRUE(rule.slower(0.0, 0.5));     // a pass that took no time now takes some
  EXPECT_FALSE(rule.slower(0.0, 0.01));
  const auto ten = SlowerRule::from_percent(10.0);
  EXPECT_FALSE(ten.slower(1.0, 1.09));
  EXPECT_TRUE(ten.slower(1.0, 1.1));
}

TEST(SlowerRule, EdgesReadFromBenchFiles) {
  using test::scenario;
  const auto baseline = load_bench_file(
      write_file("B.json",
                 test::bench_json(
                     "G", {scenario("s", 3.3, {{"a", 1.0}, {"b", 1.0}, {"c", 0.1}, {"d", 0.2}})})
                     .dump())
          .string());
  const auto run = load_bench_file(
      write_file(
          "R.json",
          test::bench_json(
              "G", {scenario("s", 3.442, {{"a", 1.049}, {"b", 1.05}, {"c", 0.11}, {"d", 0.22}})})
              .dump())
          .string());
  const auto rows = compare_with_baseline(baseline.results, run.results).rows;
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_FALSE(rows[0].slower);  // 4.9 %
  EXPECT_TRUE(rows[1].slower);   // 5 %
  EXPECT_FALSE(rows[2].slower);  // 10 %, 0.01 ms
  EXPECT_TRUE(rows[3].slower);   // 10 %, 0.02 ms
  EXPECT_FALSE(rows[4].slower);  // the frame: 4.3 %
}

TEST(SlowerRule, PercentMustBeFiniteAndNotNegative) {
  EXPECT_TRUE(valid_slower_percent(0.0));
  EXPECT_TRUE(valid_slower_percent(5.0));
  EXPECT_FALSE(valid_slower_percent(-1.0));
  EXPECT_FALSE(valid_slower_percent(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(valid_slower_percent(std::numeric_limits<double>::infinity()));
}

TEST(BenchBaseline, PassesOfOneNameMatchInOrder) {
  BenchResult a{Scenario{"s"}};
  a.passes = {{"blur", "blur", {1.0}}, {"blur", "blur", {2.0}}, {"x", "x", {1.0}}};
  BenchResult b = a;
  b.passes = {{"blur", "blur", {1.0}}, {"blur", "blur", {3.0}}};
  const auto rows = compare_with_baseline({a}, {b}).rows;
  ASSERT_EQ(rows.size(), 4u);  // blur, blur, x (only in baseline), frame
  EXPECT_DOUBLE_EQ(*rows[1].ratio, 1.5);
  EXPECT_EQ(rows[2].pass, "x");
  EXPECT_EQ(rows[2].kind, Kind::only_in_baseline);
}

TEST(BenchBaseline, FailedScenariosAreNeverRatios) {
  using test::scenario;
  const auto file = [](const char* name, std::vector<nlohmann::json> scenarios) {
    return load_bench_file(
        write_file(name, test::bench_json("G", std::move(scenarios)).dump()).string());
  };
  const auto baseline = file("B.json", {scenario("s1", 1.0, {{"p", 1.0}}, "error"),
                                        scenario("s2", 1.0, {{"p", 1.0}}, "invalid")});
  const auto run = file("R.json", {scenario("s1", 1.0, {{"p", 1.0}}),
                                   scenario("s2", 1.0, {{"p", 1.0}}, "missing-graph"),
                                   scenario("s3", 1.0, {{"p", 1.0}}, "error")});
  const auto rows = compare_with_baseline(baseline.results, run.results).rows;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].kind, Kind::only_in_run);
  EXPECT_EQ(row_flag(rows[2]), "only in this run (error)");
  for (const auto& row : {rows[0], rows[1]}) {
    EXPECT_EQ(row.kind, Kind::failed);
    EXPECT_FALSE(row.ratio);
    EXPECT_FALSE(row.baseline_ms);
    EXPECT_FALSE(row.slower);
  }
  EXPECT_DOUBLE_EQ(*rows[0].run_ms, 1.0);
  EXPECT_FALSE(rows[1].run_ms);
  EXPECT_EQ(row_flag(rows[0]), "failed in baseline: error");
  EXPECT_EQ(row_flag(rows[1]), "failed in both: invalid / missing-graph");
}

TEST(BenchBaselineFile, MissingFileNamesIt) {
  try {
    load_bench_file("/nonexistent-dir/B.json");
    FAIL() << "no error";
  } catch (const BaselineError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/B.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

std::string error_of(const std::string& text) {
  const auto path = write_file("B.json", text).string();
  try {
    load_bench_file(path);
  } catch (const BaselineError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BenchBaselineFile, SyntaxErrorSaysLineAndColumn) {
  const auto message = error_of("{\n  \"scenarios\": [\n    {\"scenario\": \"a\",, }\n  ]\n}\n");
  EXPECT_NE(message.find("B.json:3:22:"), std::string::npos) << message;
  EXPECT_NE(message.find("error[FG001]"), std::string::npos) << message;
}

TEST(BenchBaselineFile, WrongShapeSaysWhereAndWhatWasExpected) {
  auto message = error_of(
      "{\n"
      "  \"device\": \"GPU A\",\n"
      "  \"scenarios\": [\n"
      "    {\"scenario\": \"a\", \"status\": \"ok\",\n"
      "     \"frame\": {\"medianMs\": \"1.0\"}, \"passes\": []}\n"
      "  ]\n"
      "}\n");
  EXPECT_NE(message.find("B.json:5:28: expected a number of milliseconds at "
                         "/scenarios/0/frame/medianMs, found a string"),
            std::string::npos)
      << message;
  message = error_of(R"({"device": "x"})");
  EXPECT_NE(message.find("B.json:1:1: expected an array at /scenarios, found nothing"),
            std::string::npos)
      << message;
  message = error_of(R"({"scenarios": [{"scenario": "a", "status": "ok", "passes": []}]})");
  EXPECT_NE(message.find("expected an object at /scenarios/0/frame"), std::string::npos) << message;
  message = error_of(R"({"scenarios": [], "frames": 6.5})");
  EXPECT_NE(message.find("expected an integer at /frames, found a number"), std::string::npos)
      << message;
}

TEST(BenchBaseline, WarnsWhenDeviceOrSettingsDiffer) {
  auto baseline = two_runs().baseline;
  EXPECT_TRUE(setup_mismatches(baseline, {"GPU A", 60, 10, 1.0}).empty());
  const auto lines = setup_mismatches(baseline, {"GPU B", 30, 10, 0.25});
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[0].find("measured on GPU A, this run on GPU B"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("--frames 60, this run 30"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find("--scale 1, this run 0.25"), std::string::npos) << lines[2];
  baseline.device.clear();  // a file from before bench.json named its device
  baseline.frames.reset();
  EXPECT_EQ(setup_mismatches(baseline, {"GPU B", 30, 10, 1.0}).size(), 0u);
}

// A killed run's bench.json ("complete": false) is accepted as a baseline, with a warning
// that says how far it got; the scenarios it never reached are only in this run.
TEST(BenchBaseline, APartialBaselineIsComparedAsFarAsItGoesWithAWarning) {
  auto json = test::baseline_json();
  json["complete"] = false;
  json["scenariosPlanned"] = 10;
  json["scenariosFinished"] = 4;
  const auto partial = load_bench_file(write_file("partial.json", json.dump(2)).string());
  ASSERT_TRUE(partial.complete.has_value());
  EXPECT_FALSE(*partial.complete);
  EXPECT_EQ(partial.planned, 10);
  const auto lines = setup_mismatches(partial, {"GPU A", 60, 10, 1.0});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("partial.json is partial (an interrupted run: 4 of 10 scenarios "
                          "finished)"),
            std::string::npos)
      << lines[0];
  const auto run = load_bench_file(write_file("R.json", test::run_json().dump(2)).string());
  const auto comparison = compare_with_baseline(partial.results, run.results);
  EXPECT_EQ(comparison.count(Kind::only_in_run), two_runs().comparison.count(Kind::only_in_run));

  json["complete"] = true;  // a finished run, and a file from before the key: no warning
  EXPECT_TRUE(setup_mismatches(load_bench_file(write_file("done.json", json.dump(2)).string()),
                               {"GPU A", 60, 10, 1.0})
                  .empty());
  EXPECT_FALSE(two_runs().baseline.complete.has_value());
  json["complete"] = "no";
  try {
    load_bench_file(write_file("bad.json", json.dump(2)).string());
    ADD_FAILURE() << "a non-boolean \"complete\" was accepted";
  } catch (const BaselineError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a boolean at /complete"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace antumbra::app
