// `bench --baseline` as written: the table on stdout, bench_compare.csv, the additions to
// bench.json and the chart's markers, from two synthetic bench.json files.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "synthetic_bench.hpp"

namespace antumbra::app {
namespace {

using test::two_runs;

TEST(BenchBaselineReport, TextTable) {
  std::ostringstream out;
  write_comparison_text(out, two_runs().comparison);
  EXPECT_EQ(out.str(),
            "scenario  pass     baseline ms  this ms  ratio  flag\n"
            "t/pcss    gbuffer        1.000    1.000  1.000\n"
            "t/pcss    atlas          2.000    2.200  1.100  slower\n"
            "t/pcss    light          0.500    0.505  1.010\n"
            "t/pcss    frame          3.500    3.705  1.059  slower\n"
            "t/hard    gbuffer        1.000    1.000  1.000\n"
            "t/hard    tonemap            -    0.010      -  only in this run\n"
            "t/hard    frame          1.000    1.010  1.010\n"
            "t/new     frame              -    0.500      -  only in this run\n"
            "t/broken  frame              -    1.000      -  failed in baseline: invalid\n"
            "t/gone    frame          2.000        -      -  only in baseline\n"
            "2 of 6 compared rows slower (>= 5 % and >= 0.02 ms slower); 1 only in baseline, "
            "2 only in this run, 1 failed\n");
}

TEST(BenchBaselineReport, CsvColumns) {
  std::ostringstream out;
  write_comparison_csv(out, two_runs().comparison);
  std::istringstream in(out.str());
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 11u);
  EXPECT_EQ(lines[0], "scenario,pass,pass_type,baseline_median_ms,median_ms,ratio,flag");
  EXPECT_EQ(lines[2], "t/pcss,atlas,atlas,2,2.2,1.1,slower");
  EXPECT_EQ(lines[3], "t/pcss,light,light,0.5,0.505,1.01,");
  EXPECT_EQ(lines[4], "t/pcss,frame,,3.5,3.705,1.05857,slower");
  EXPECT_EQ(lines[6], "t/hard,tonemap,tonemap,,0.01,,only in this run");
  EXPECT_EQ(lines[9], "t/broken,frame,,,1,,failed in baseline: invalid");
  EXPECT_EQ(lines[10], "t/gone,frame,,2,,,only in baseline");
}

TEST(BenchBaselineReport, JsonBesideEveryMedian) {
  const auto two = two_runs();
  nlohmann::json bench{{"scenarios", results_json(two.run.results)}};
  add_comparison_json(bench, two.baseline, two.comparison);
  const auto& pcss = bench["scenarios"][0];
  EXPECT_DOUBLE_EQ(pcss["passes"][1]["baselineMedianMs"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(pcss["passes"][1]["ratio"].get<double>(), 2.2 / 2.0);
  EXPECT_EQ(pcss["passes"][1]["slower"], true);
  EXPECT_EQ(pcss["passes"][0]["slower"], false);
  EXPECT_FALSE(pcss["passes"][0].contains("baselineNote"));
  EXPECT_EQ(pcss["frame"]["slower"], true);
  const auto& tonemap = bench["scenarios"][1]["passes"][1];
  EXPECT_TRUE(tonemap["baselineMedianMs"].is_null());
  EXPECT_TRUE(tonemap["ratio"].is_null());
  EXPECT_EQ(tonemap["baselineNote"], "only in this run");
  EXPECT_EQ(bench["scenarios"][3]["frame"]["baselineNote"], "failed in baseline: invalid");
  const auto& baseline = bench["baseline"];
  EXPECT_EQ(baseline["file"], two.baseline.file);
  EXPECT_EQ(baseline["commit"], "abc1234");
  EXPECT_EQ(baseline["device"], "GPU A");
  EXPECT_EQ(baseline["driver"], "driver 1.0");
  EXPECT_EQ(baseline["slowerCount"], 2);
  EXPECT_DOUBLE_EQ(baseline["slowerRatio"].get<double>(), 1.05);
  EXPECT_DOUBLE_EQ(baseline["slowerMinMs"].get<double>(), 0.02);
  ASSERT_EQ(baseline["onlyInBaseline"].size(), 1u);
  EXPECT_EQ(baseline["onlyInBaseline"][0]["scenario"], "t/gone");
  EXPECT_DOUBLE_EQ(baseline["onlyInBaseline"][0]["medianMs"].get<double>(), 2.0);
}

TEST(BenchBaselineReport, ChartMarksTheBaselineAndTheRatio) {
  const auto two = two_runs();
  StackedChart chart{"t", "ms", {}, {}};
  for (const auto& r : two.run.results) chart.rows.push_back({r.scenario.name, {}, 0, 0, "x ms"});
  add_comparison_to_chart(chart, two.comparison);
  ASSERT_EQ(chart.rows.size(), 5u);  // this run's four, then the baseline's "t/gone"
  EXPECT_DOUBLE_EQ(chart.rows[0].marker, 3.5);
  EXPECT_EQ(chart.rows[0].annotation, "x ms | x1.059 of 3.500, 2 slower");
  EXPECT_EQ(chart.rows[1].annotation, "x ms | x1.010 of 1.000");
  EXPECT_DOUBLE_EQ(chart.rows[2].marker, 0.0);
  EXPECT_EQ(chart.rows[2].annotation, "x ms | only in this run");
  EXPECT_EQ(chart.rows[3].annotation, "x ms | failed in baseline: invalid");
  EXPECT_EQ(chart.rows[4].label, "t/gone");
  EXPECT_DOUBLE_EQ(chart.rows[4].marker, 2.0);
  EXPECT_EQ(chart.rows[4].annotation, "only in baseline");
  EXPECT_NE(chart.axis_label.find("baseline"), std::string::npos);
}

TEST(BenchBaselineReport, WritesBenchCompareCsvBesideTheReports) {
  const auto two = two_runs();
  const auto dir = test::write_file("x", "").parent_path();
  nlohmann::json bench{{"scenarios", results_json(two.run.results)}};
  StackedChart chart{"t", "ms", {}, {}};
  for (const auto& r : two.run.results) chart.rows.push_back({r.scenario.name});
  add_comparison_reports(dir, two.baseline, two.comparison, bench, chart);
  std::ifstream csv(dir / "bench_compare.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "scenario,pass,pass_type,baseline_median_ms,median_ms,ratio,flag");
  EXPECT_TRUE(bench.contains("baseline"));
  EXPECT_EQ(chart.rows.size(), 5u);
  EXPECT_THROW(add_comparison_reports("/nonexistent-dir/antumbra", two.baseline, two.comparison,
                                      bench, chart),
               std::runtime_error);
}

}  // namespace
}  // namespace antumbra::app
