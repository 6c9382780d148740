// Percentiles, per-frame sums and the long CSV / JSON of `antumbra bench`, on made-up
// timings.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench_report.hpp"

namespace antumbra::app {
namespace {

TEST(Percentile, InterpolatesBetweenClosestRanks) {
  const std::vector<double> values{5.0, 1.0, 4.0, 2.0, 3.0};  // unsorted on purpose
  EXPECT_DOUBLE_EQ(percentile(values, 50.0), 3.0);
  EXPECT_DOUBLE_EQ(percentile(values, 10.0), 1.4);
  EXPECT_DOUBLE_EQ(percentile(values, 90.0), 4.6);
  EXPECT_DOUBLE_EQ(percentile(values, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(values, 100.0), 5.0);
}

TEST(Percentile, MedianOfAnEvenCountIsTheMiddlePairsMean) {
  EXPECT_DOUBLE_EQ(percentile({4.0, 1.0, 3.0, 2.0}, 50.0), 2.5);
}

TEST(Percentile, EmptyAndSingle) {
  EXPECT_DOUBLE_EQ(percentile({}, 50.0), 0.0);
  EXPECT_DOUBLE_EQ(percentile({7.0}, 10.0), 7.0);
  EXPECT_DOUBLE_EQ(percentile({7.0}, 90.0), 7.0);
}

TEST(Summarize, KeepsTheSpreadAndTheFrameCount) {
  std::vector<double> samples;
  for (int i = 1; i <= 11; ++i) samples.push_back(i);  // 1..11
  const auto s = summarize(samples);
  EXPECT_DOUBLE_EQ(s.median_ms, 6.0);
  EXPECT_DOUBLE_EQ(s.p10_ms, 2.0);
  EXPECT_DOUBLE_EQ(s.p90_ms, 10.0);
  EXPECT_EQ(s.frames, 11u);
}

TEST(FrameSamples, SumsFrameByFrameAndCutsToTheShortestPass) {
  const auto sums = frame_samples({{1.0, 2.0, 3.0}, {10.0, 20.0}});
  ASSERT_EQ(sums.size(), 2u);
  EXPECT_DOUBLE_EQ(sums[0], 11.0);
  EXPECT_DOUBLE_EQ(sums[1], 22.0);
  EXPECT_TRUE(frame_samples({}).empty());
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (const char c : text) {
    if (c == '"') quoted = !quoted;
    if (c == separator && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

std::vector<BenchResult> two_results() {
  Scenario s;
  s.name = "table1/pcss-11/180p";
  s.table = "table1";
  s.technique = "pcss";
  s.kernel = 11;
  s.width = 320;
  s.height = 180;
  s.face = 256;
  BenchResult ok{s};
  ok.passes.push_back({"gbuffer", "gbuffer", {1.5, 1.0, 2.0, 60}, 0.1});
  ok.passes.push_back({"odd,name", "shadow-pcss", {3.0, 2.5, 4.0, 60}, 0.2});
  ok.frame = {4.5, 4.0, 5.5, 60};
  Scenario t = s;
  t.name = "table1/ssss-11/180p";
  BenchResult failed{t, "invalid", "FG030 ...", {}, {}};
  return {ok, failed};
}

TEST(LongCsv, OneRowPerScenarioAndPassPlusTheFrame) {
  std::ostringstream out;
  write_long_csv(out, two_results());
  std::vector<std::string> lines;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 5u);  // header, 2 passes + frame, the failed scenario's frame
  const auto header = split(lines[0], ',');
  for (const auto& line : lines) EXPECT_EQ(split(line, ',').size(), header.size()) << line;
  EXPECT_EQ(lines[0],
            "scenario,table,technique,kernel,width,height,atlas_face,lights,moving_lights,scene,"
            "rasterizer,light_size,status,pass,pass_type,median_ms,p10_ms,p90_ms,frames");
  EXPECT_EQ(lines[1],
            "table1/pcss-11/180p,table1,pcss,11,320,180,256,16,0,atrium.json,hardware,0,ok,gbuffer,"
            "gbuffer,1.5,1,2,60");
  EXPECT_EQ(split(lines[2], ',')[13], "\"odd,name\"");
  EXPECT_EQ(
      lines[3],
      "table1/pcss-11/180p,table1,pcss,11,320,180,256,16,0,atrium.json,hardware,0,ok,frame,,4.5,4,"
      "5.5,60");
  EXPECT_EQ(
      lines[4],
      "table1/ssss-11/180p,table1,pcss,11,320,180,256,16,0,atrium.json,hardware,0,invalid,frame,"
      ",,,,0");
}

TEST(ResultsJson, CarriesTheSameNumbers) {
  const auto json = results_json(two_results());
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0]["atlasFace"], 256);
  EXPECT_DOUBLE_EQ(json[0]["frame"]["p90Ms"].get<double>(), 5.5);
  EXPECT_DOUBLE_EQ(json[0]["passes"][1]["p10Ms"].get<double>(), 2.5);
  EXPECT_EQ(json[0]["passes"][1]["frames"], 60);
  EXPECT_EQ(json[1]["status"], "invalid");
}

// The passes' notes about the last frame go into bench.json with their lists shortened to
// lengths (SHD002 names every unshadowed light), counts and small objects kept.
TEST(ResultsJson, NotesKeepCountsAndShortenLists) {
  auto results = two_results();
  const auto details = nlohmann::json::parse(
      R"({"rendered": 20, "texels": 20971520, "faceSizes": {"1024": 16},
          "lights": ["a", "b", "c"], "nested": {"big": [1, 2]}})");
  EXPECT_EQ(compact_details(details), nlohmann::json::parse(R"({"rendered": 20, "texels": 20971520,
                                      "faceSizes": {"1024": 16}, "lightsCount": 3,
                                      "nested": {"big": [1, 2]}})"));
  results[0].notes.push_back({{"code", "SHD010"}, {"details", compact_details(details)}});
  const auto json = results_json(results);
  EXPECT_EQ(json[0]["notes"][0]["details"]["lightsCount"], 3);
  EXPECT_EQ(json[0]["notes"][0]["details"]["texels"], 20971520);
  EXPECT_FALSE(json[1].contains("notes"));  // none reported: no key
}

// `bench --steps`: steps follow the frame row, typed by their pass, and stay out of the
// frame's sum; the JSON carries them as "steps" (absent without them).
TEST(LongCsv, StepsFollowTheFrameRowTypedByTheirPass) {
  auto results = two_results();
  results[0].steps.push_back({"shadows.cull", "shadows", {0.25, 0.2, 0.3, 60}, 0.0});
  std::ostringstream out;
  write_long_csv(out, results);
  std::vector<std::string> lines;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(split(lines[3], ',')[13], "frame");
  EXPECT_EQ(lines[4],
            "table1/pcss-11/180p,table1,pcss,11,320,180,256,16,0,atrium.json,hardware,0,ok,"
            "shadows.cull,step:shadows,0.25,0.2,0.3,60");
  const auto json = results_json(results);
  EXPECT_EQ(json[0]["steps"][0]["name"], "shadows.cull");
  EXPECT_EQ(json[0]["steps"][0]["pass"], "shadows");
  EXPECT_DOUBLE_EQ(json[0]["steps"][0]["medianMs"].get<double>(), 0.25);
  EXPECT_FALSE(json[1].contains("steps"));
  EXPECT_DOUBLE_EQ(json[0]["frame"]["medianMs"].get<double>(), 4.5);
}

// bench.json is rewritten after every scenario: its head says how far the run got.
TEST(BenchJson, IsCompleteOnlyOnceEveryPlannedScenarioIsIn) {
  BenchRun run;
  run.commit = "abc";
  run.device = "llvmpipe";
  run.driver = "Mesa";
  run.frames = 3;
  run.warmup = 1;
  run.warmup_from = "--quick";
  run.scale = 0.25;
  run.preset = "quick";
  run.planned = 3;
  run.finished = 2;
  const auto results = two_results();
  auto json = bench_json(run, results);
  EXPECT_EQ(json["complete"], false);
  EXPECT_EQ(json["scenariosPlanned"], 3);
  EXPECT_EQ(json["scenariosFinished"], 2);
  EXPECT_EQ(json["warmup"], 1);
  EXPECT_EQ(json["warmupFrom"], "--quick");
  EXPECT_EQ(json["preset"], "quick");
  EXPECT_EQ(json["scenarios"], results_json(results));
  run.planned = 2;
  run.preset.clear();
  json = bench_json(run, results);
  EXPECT_EQ(json["complete"], true);
  EXPECT_FALSE(json.contains("preset"));
}

TEST(BenchJson, TheFirstLineSaysWhereTheWarmupCameFrom) {
  BenchRun run;
  run.device = "llvmpipe";
  run.planned = 2;
  run.frames = 3;
  run.warmup = 10;
  EXPECT_EQ(bench_setup_line(run),
            "bench on llvmpipe: 2 scenario(s), 10 warm-up (default) + 3 timed frames each, "
            "scale 1.00");
  run.warmup = 0;
  run.warmup_from = "--warmup";
  EXPECT_EQ(bench_setup_line(run),
            "bench on llvmpipe: 2 scenario(s), 0 warm-up + 3 timed frames each, scale 1.00");
  run.warmup_from = "--quick";
  run.preset = "quick";
  EXPECT_NE(bench_setup_line(run).find("0 warm-up (--quick) + 3"), std::string::npos);
  EXPECT_NE(bench_setup_line(run).find("scale 1.00 (--quick)"), std::string::npos);
}

}  // namespace
}  // namespace antumbra::app
