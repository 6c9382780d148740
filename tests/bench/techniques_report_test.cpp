// antumbra techniques without a device: where the crops are cut, which bench row a graph
// reads, the brighter/darker proxies and the table's shape.
#include <filesystem>

#include <gtest/gtest.h>

#include "techniques_report.hpp"

using namespace antumbra::app;

namespace {

FloatImage grey(unsigned width, unsigned height, float value, unsigned channels = 3) {
  FloatImage image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.texels.assign(std::size_t{width} * height * channels, value);
  return image;
}

TEST(TechniquesReport, CropGoesWhereThePenumbraeAreDensest) {
  FloatImage mask = grey(64, 32, 0.0f, 1);
  for (unsigned y = 20; y < 28; ++y) {
    for (unsigned x = 44; x < 60; ++x) mask.texels[y * 64 + x] = 2.0f;
  }
  const CropRect crop = densest_penumbra(&mask, 64, 32);
  EXPECT_EQ(crop.width, 16u);
  EXPECT_EQ(crop.height, 8u);
  EXPECT_EQ(crop.x, 44u);
  EXPECT_EQ(crop.y, 20u);
  const CropRect centre = densest_penumbra(nullptr, 64, 32);
  EXPECT_EQ(centre.x, 24u);
  EXPECT_EQ(centre.y, 12u);
}

TEST(TechniquesReport, BenchRowIsTable1AtTheLargestHeightWithTheElevenTapKernel) {
  auto row = [](const char* table, const char* technique, int kernel, unsigned height, double ms) {
    return nlohmann::json{{"table", table},   {"technique", technique},
                          {"kernel", kernel}, {"height", height},
                          {"status", "ok"},   {"frame", {{"medianMs", ms}}}};
  };
  const nlohmann::json bench = {
      {"scenarios",
       {row("table1", "pcss", 5, 1080, 1.0), row("table1", "pcss", 11, 1080, 2.0),
        row("table1", "pcss", 11, 720, 3.0), row("table2", "pcss", 11, 1080, 4.0),
        row("table1", "ssss", 11, 1080, 5.0), row("table1", "vssm", 0, 1080, 6.0)}}};
  EXPECT_EQ(bench_frame_ms(bench, "pcss.json"), 2.0);
  EXPECT_EQ(bench_frame_ms(bench, "layered-ssss.json"), 5.0);
  EXPECT_EQ(bench_frame_ms(bench, "vssm.json"), 6.0);
  EXPECT_FALSE(bench_frame_ms(bench, "sdf.json").has_value());
  EXPECT_FALSE(bench_frame_ms(nlohmann::json::object(), "pcss.json").has_value());
}

TEST(TechniquesReport, BrighterAndDarkerSeparateTheSignOfTheError) {
  const FloatImage reference = grey(4, 4, 0.5f);
  FloatImage image = grey(4, 4, 0.5f);
  for (std::size_t i = 0; i < std::size_t{12}; ++i) image.texels[i] = 0.75f;  // 4 pixels brighter
  const ErrorSides sides = error_sides(reference, image);
  EXPECT_NEAR(sides.brighter, 1000.0 * 0.25 * 4 / 16, 1e-3);
  EXPECT_EQ(sides.darker, 0.0);
  const ErrorSides flipped = error_sides(image, reference);
  EXPECT_NEAR(flipped.darker, sides.brighter, 1e-9);
  EXPECT_EQ(flipped.brighter, 0.0);
}

TEST(TechniquesReport, TableHasOneRowPerTechniqueAndEveryCrop) {
  TechniquesReport report;
  report.device = "llvmpipe";
  report.scene = "atrium.json";
  report.width = 960;
  report.height = 540;
  report.reference_crop = "techniques/reference.png";
  report.crop = {10, 20, 240, 135};
  TechniqueRow a;
  a.graph = "pcss.json";
  a.comparisons = {{MaskRegion::all, {100, 0.01, 40.0, 0.99}}};
  a.crop = "techniques/pcss.png";
  a.gpu_ms = 1.234;
  TechniqueRow b = a;
  b.graph = "sdf.json";
  b.crop = "techniques/sdf.png";
  b.gpu_ms.reset();
  report.rows = {a, b};
  const std::string md = techniques_markdown(report);
  EXPECT_NE(md.find("| `pcss.json` | 0.0100 | 40.0 | 0.9900 | - | - | -"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1.234 |"), std::string::npos);
  EXPECT_NE(md.find("![sdf.json](techniques/sdf.png)"), std::string::npos);
  EXPECT_NE(md.find("![reference](techniques/reference.png)"), std::string::npos);
}

// An empty time column says why: no bench file given, or what the given one lacks.
TEST(TechniquesReport, EmptyTimeColumnsSayWhy) {
  TechniquesReport report;
  report.width = 64;
  report.height = 36;
  TechniqueRow row;
  row.graph = "hard.json";
  report.rows = {row};
  note_empty_time_columns(report, "", "");
  EXPECT_NE(report.gpu_note.find("no `--gpu-bench` given"), std::string::npos) << report.gpu_note;
  EXPECT_NE(report.cpu_note.find("no `--cpu-bench` given"), std::string::npos) << report.cpu_note;
  note_empty_time_columns(report, "gpu/bench.json", "cpu/bench.json");
  EXPECT_NE(report.gpu_note.find("`gpu/bench.json` has no ok table1 row"), std::string::npos);
  EXPECT_NE(report.cpu_note.find("`cpu/bench.json` has no ok table1 row of `hard.json`"),
            std::string::npos);
  report.size_warning = "at 64x36 the ranking of techniques is not reliable";
  std::string md = techniques_markdown(report);
  EXPECT_NE(md.find("**Warning:** at 64x36 the ranking"), std::string::npos) << md;
  EXPECT_NE(md.find("The GPU ms column is empty: `gpu/bench.json` has"), std::string::npos) << md;
  EXPECT_NE(md.find("The lavapipe column is empty: `cpu/bench.json` has"), std::string::npos);

  report.rows[0].gpu_ms = 1.0;  // one number fills a column: no note
  report.rows[0].cpu_ratio = 1.0;
  report.size_warning.clear();
  note_empty_time_columns(report, "gpu/bench.json", "cpu/bench.json");
  EXPECT_TRUE(report.gpu_note.empty());
  EXPECT_TRUE(report.cpu_note.empty());
  md = techniques_markdown(report);
  EXPECT_EQ(md.find("Warning"), std::string::npos);
  EXPECT_EQ(md.find("column is empty"), std::string::npos);
}

// Without --out, techniques writes beside the other outputs, never over the committed
// docs/techniques.md (run from the repository, that is where a relative docs/ path lands).
TEST(TechniquesReport, TheDefaultOutputIsNotUnderDocs) {
  const std::filesystem::path out(kTechniquesDefaultOut);
  EXPECT_TRUE(out.is_relative());
  EXPECT_NE(*out.begin(), "docs");
  EXPECT_EQ(out.extension(), ".md");
}

}  // namespace
