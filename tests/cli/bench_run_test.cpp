// `bench` and `techniques` on a device (lavapipe, tiny sizes): an interrupted bench
// leaves whole CSV and JSON files of the scenarios that finished, --warmup 0 runs no
// warm-up frame, and `techniques` without --out leaves the committed docs alone.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace antumbra::test {
namespace {

namespace fs = std::filesystem;

// bench.json's scenarios finished so far; -1 while it is missing or unreadable (a
// rename is atomic, so a file that exists always parses).
int finished(const fs::path& json) {
  if (!fs::exists(json)) return -1;
  return nlohmann::json::parse(read_text(json)).value("scenariosFinished", -1);
}

std::vector<std::string> csv_lines(const fs::path& csv) {
  std::vector<std::string> out;
  std::istringstream in(read_text(csv));
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Two scenarios; killed during the second, once bench.json holds the first.
TEST(BenchPartial, AKilledRunLeavesTheScenariosThatFinished) {
  const auto dir = test_folder();
  const auto out = dir / "bench";
  const std::string first = "table1/hard/36p";
  const std::string second = "table1/ssss-11/36p";
  // Enough frames that the second scenario lasts seconds after the first is written.
  Program bench({"bench", "--scenario", first, "--scenario", second, "--scale", "0.05", "--frames",
                 "150", "--out", out.string()},
                ANTUMBRA_TEST_SOURCE_DIR, dir);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  while (finished(out / "bench.json") < 1 && bench.running() &&
         std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(bench.running()) << "the run ended before it could be killed; stderr:\n"
                               << read_text(dir / "stderr");
  const auto killed = bench.kill_and_wait();
  ASSERT_EQ(finished(out / "bench.json"), 1) << killed.err;
  // Its first line says the warm-up it adds by default.
  EXPECT_NE(killed.err.find("2 scenario(s), 10 warm-up (default) + 150 timed frames each"),
            std::string::npos)
      << killed.err;

  const auto json = nlohmann::json::parse(read_text(out / "bench.json"));
  EXPECT_EQ(json["complete"], false);
  EXPECT_EQ(json["scenariosPlanned"], 2);
  ASSERT_EQ(json["scenarios"].size(), 1u);
  const auto& scenario = json["scenarios"][0];
  EXPECT_EQ(scenario["scenario"], first);
  EXPECT_EQ(scenario["status"], "ok");
  EXPECT_EQ(scenario["frame"]["frames"], 150);
  EXPECT_GT(scenario["frame"]["medianMs"].get<double>(), 0.0);

  const auto csv = csv_lines(out / "bench.csv");
  ASSERT_GE(csv.size(), 3u);  // the header, the first scenario's passes and frame
  EXPECT_EQ(csv.front().rfind("scenario,table,", 0), 0u);
  for (std::size_t i = 1; i < csv.size(); ++i) {
    EXPECT_EQ(csv[i].rfind(first + ",", 0), 0u) << csv[i];
  }
  EXPECT_NE(csv.back().find(",frame,,"), std::string::npos) << csv.back();
  EXPECT_TRUE(fs::exists(out / "bench.png"));

  // A partial file is accepted as a baseline, with a warning saying what it lacks.
  fs::create_directories(dir / "compare");
  const auto compared = run_antumbra(
      {"bench", "--scenario", first, "--scale", "0.05", "--frames", "1", "--warmup", "0",
       "--baseline", (out / "bench.json").string(), "--out", (dir / "compare").string()},
      dir / "compare");
  EXPECT_EQ(compared.exit_code, 0) << compared.err;
  EXPECT_NE(compared.err.find("is partial (an interrupted run: 1 of 2 scenarios finished)"),
            std::string::npos)
      << compared.err;
}

TEST(BenchWarmup, ZeroWarmupFramesRunUnderValidation) {
  const auto dir = test_folder();
  const auto out = dir / "bench";
  const auto run =
      run_antumbra({"bench", "--scenario", "table1/hard/36p", "--scale", "0.05", "--frames", "1",
                    "--warmup", "0", "--validation", "--out", out.string()},
                   dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("1 scenario(s), 0 warm-up + 1 timed frames each, scale 0.05"),
            std::string::npos)
      << run.err;
  const auto json = nlohmann::json::parse(read_text(out / "bench.json"));
  EXPECT_EQ(json["warmup"], 0);
  EXPECT_EQ(json["warmupFrom"], "--warmup");
  EXPECT_EQ(json["complete"], true);
  EXPECT_EQ(json["scenariosFinished"], 1);
  ASSERT_EQ(json["scenarios"].size(), 1u);
  EXPECT_EQ(json["scenarios"][0]["status"], "ok");
  EXPECT_EQ(json["scenarios"][0]["frame"]["frames"], 1);
}

TEST(BenchQuick, ExplicitFramesAndWarmupWinOverThePreset) {
  const auto dir = test_folder();
  const auto run = run_antumbra({"bench", "--quick", "--scenario", "table1/hard/36p", "--scale",
                                 "0.05", "--frames", "1", "--out", (dir / "bench").string()},
                                dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("1 warm-up (--quick) + 1 timed frames each, scale 0.05 (--quick)"),
            std::string::npos)
      << run.err;
  const auto json = nlohmann::json::parse(read_text(dir / "bench" / "bench.json"));
  EXPECT_EQ(json["preset"], "quick");
  EXPECT_EQ(json["warmupFrom"], "--quick");
}

// Run where a user would, in a folder with a docs/techniques.md of its own; the data
// comes from ANTUMBRA_ROOT. One graph at 64x36 keeps it to seconds on lavapipe.
TEST(TechniquesOut, WithoutOutTheCommittedDocsStayAsTheyAre) {
  const auto dir = test_folder();
  fs::create_directories(dir / "docs");
  const std::string committed = "# committed table\n";
  std::ofstream(dir / "docs" / "techniques.md") << committed;
  Program techniques({"techniques", "--graph", "hard.json", "--size", "64x36"}, dir, dir,
                     {std::string("ANTUMBRA_ROOT=") + ANTUMBRA_TEST_SOURCE_DIR});
  const auto run = techniques.wait();
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_text(dir / "docs" / "techniques.md"), committed);
  EXPECT_FALSE(fs::exists(dir / "docs" / "techniques"));
  EXPECT_NE(run.out.find("wrote out/techniques.md"), std::string::npos) << run.out;
  const std::string md = read_text(dir / "out" / "techniques.md");
  EXPECT_NE(md.find("| `hard.json` |"), std::string::npos) << md;
  EXPECT_TRUE(fs::exists(dir / "out" / "techniques" / "hard.png"));
  // A small frame and no bench files: said on stderr and in the file.
  EXPECT_NE(run.err.find("at 64x36 the ranking of techniques is not reliable"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("the lavapipe x hard column is empty: no `--cpu-bench` given"),
            std::string::npos)
      << run.err;
  EXPECT_NE(md.find("**Warning:** at 64x36"), std::string::npos) << md;
  EXPECT_NE(md.find("The lavapipe column is empty: no `--cpu-bench` given"), std::string::npos)
      << md;
}

}  // namespace
}  // namespace antumbra::test
