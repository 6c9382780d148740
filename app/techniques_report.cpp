#include "techniques_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace antumbra::app {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string optional_number(const std::optional<double>& value, const char* pattern) {
  return value ? format(pattern, *value) : "-";
}

// The bench's technique name of a graph file (bench_scenarios.cpp's list).
std::string bench_technique(const std::string& graph) {
  std::string stem = graph.substr(0, graph.rfind('.'));
  if (stem.rfind("layered-", 0) == 0) stem = stem.substr(8);
  if (stem == "lighting") return "lighting-only";
  return stem;
}

const Comparison* region(const TechniqueRow& row, MaskRegion which) {
  for (const auto& c : row.comparisons) {
    if (c.region == which && c.metrics.pixels > 0) return &c;
  }
  return nullptr;
}

std::string metrics_cell(const TechniqueRow& row, MaskRegion which) {
  const Comparison* c = region(row, which);
  if (c == nullptr) return "- | - | -";
  return format("%.4f", c->metrics.rmse) + " | " + format("%.1f", c->metrics.psnr) + " | " +
         format("%.4f", c->metrics.ssim);
}

}  // namespace

CropRect densest_penumbra(const FloatImage* mask, unsigned width, unsigned height) {
  CropRect best{width * 3 / 8, height * 3 / 8, std::max(width / 4, 1u), std::max(height / 4, 1u)};
  if (mask == nullptr || mask->width != width || mask->height != height) return best;
  // Summed-area table of the weights, so every window costs four lookups.
  const std::size_t stride = std::size_t{width} + 1;
  std::vector<double> table(stride * (std::size_t{height} + 1), 0.0);
  for (unsigned y = 0; y < height; ++y) {
    double row = 0.0;
    for (unsigned x = 0; x < width; ++x) {
      const float count = mask->at(x, y, 0);
      row += count >= 2.0f ? 2.0 : (count >= 1.0f ? 1.0 : 0.0);
      table[(y + 1) * stride + x + 1] = table[y * stride + x + 1] + row;
    }
  }
  double most = -1.0;
  const unsigned step = std::max(1u, std::min(best.width, best.height) / 8);
  for (unsigned y = 0; y + best.height <= height; y += step) {
    for (unsigned x = 0; x + best.width <= width; x += step) {
      const std::size_t x1 = x + best.width;
      const std::size_t y1 = y + best.height;
      const double sum = table[y1 * stride + x1] - table[y * stride + x1] - table[y1 * stride + x] +
                         table[y * stride + x];
      if (sum > most) {
        most = sum;
        best.x = x;
        best.y = y;
      }
    }
  }
  return best;
}

std::optional<double> bench_frame_ms(const nlohmann::json& bench, const std::string& graph) {
  const std::string technique = bench_technique(graph);
  const nlohmann::json* found = nullptr;
  auto rank = [](const nlohmann::json& s) {
    const int kernel = s.value("kernel", 0);
    return std::make_pair(s.value("height", 0u), kernel == 11 ? 2 : (kernel == 0 ? 1 : 0));
  };
  if (!bench.contains("scenarios") || !bench["scenarios"].is_array()) return std::nullopt;
  for (const auto& s : bench["scenarios"]) {
    if (s.value("table", "") != "table1" || s.value("technique", "") != technique ||
        s.value("status", "") != "ok") {
      continue;
    }
    if (found == nullptr || rank(s) > rank(*found)) found = &s;
  }
  if (found == nullptr) return std::nullopt;
  return (*found)["frame"].value("medianMs", 0.0);
}

ErrorSides error_sides(const FloatImage& reference, const FloatImage& image) {
  const auto a = display_luminance(reference);
  const auto b = display_luminance(image);
  ErrorSides sides;
  const std::size_t n = std::min(a.size(), b.size());
  if (n == 0) return sides;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = static_cast<double>(b[i]) - a[i];
    (d > 0.0 ? sides.brighter : sides.darker) += std::abs(d);
  }
  sides.brighter *= 1000.0 / static_cast<double>(n);
  sides.darker *= 1000.0 / static_cast<double>(n);
  return sides;
}

void note_empty_time_columns(TechniquesReport& report, const std::string& gpu_bench,
                             const std::string& cpu_bench) {
  bool gpu = false;
  bool cpu = false;
  for (const auto& row : report.rows) {
    gpu = gpu || row.gpu_ms.has_value();
    cpu = cpu || row.cpu_ratio.has_value();
  }
  report.gpu_note.clear();
  report.cpu_note.clear();
  if (!gpu) {
    report.gpu_note = gpu_bench.empty()
                          ? "no `--gpu-bench` given (the bench.json of `antumbra bench "
                            "--scenario table1/` on a GPU)"
                          : "`" + gpu_bench +
                                "` has no ok table1 row of these graphs (measure "
                                "them with `antumbra bench --scenario table1/`)";
  }
  if (!cpu) {
    report.cpu_note = cpu_bench.empty()
                          ? "no `--cpu-bench` given (the bench.json of `antumbra bench "
                            "--scenario table1/ --scale 0.25` on lavapipe; techniques does not "
                            "time frames itself)"
                          : "`" + cpu_bench +
                                "` has no ok table1 row of `hard.json` (the "
                                "ratio's denominator) or of these graphs";
  }
}

std::string techniques_markdown(const TechniquesReport& report) {
  std::string md;
  md += "# Shadow techniques compared\n\n";
  md +=
      "Written by `antumbra techniques` (docs/technique.md explains each technique). Quality: "
      "every graph against the 256-sample area-light reference (`reference.json`) on `" +
      report.scene + "` at " + std::to_string(report.width) + "x" + std::to_string(report.height) +
      " on " + report.device +
      "; RMSE, PSNR (dB) and SSIM of display luminance over all pixels, penumbra pixels "
      "and overlapping-penumbra pixels (the reference's penumbra count). Brighter / "
      "darker: luminance above / below the reference averaged over all pixels (1/1000): "
      "light let through (bleeding, leaks, peter-panning) and light taken away (acne, an "
      "overestimated umbra). Memory: the graph's own resources (atlas, maps, fields, "
      "layers) at this size, and what passes report keeping of their own (penumbra-wedges' "
      "second depth layer and wedge buffers), without short-lived scratch images.";
  if (!report.gpu_device.empty()) {
    md +=
        " GPU: the frame's median at 1080p with 16 lights (`bench` table1, every shadow "
        "face redrawn each frame) on " +
        report.gpu_device + ".";
  }
  md += " Lavapipe: the frame time over `hard.json`'s on this machine's CPU.\n\n";
  if (!report.size_warning.empty()) md += "**Warning:** " + report.size_warning + ".\n\n";
  if (!report.gpu_note.empty()) md += "The GPU ms column is empty: " + report.gpu_note + ".\n\n";
  if (!report.cpu_note.empty()) {
    md += "The lavapipe column is empty: " + report.cpu_note + ".\n\n";
  }
  md +=
      "| graph | all RMSE | PSNR | SSIM | penumbra RMSE | PSNR | SSIM | overlap RMSE | PSNR | "
      "SSIM | brighter | darker | memory MiB | GPU ms | lavapipe x hard |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : report.rows) {
    md += "| `" + row.graph + "` | " + metrics_cell(row, MaskRegion::all) + " | " +
          metrics_cell(row, MaskRegion::penumbra) + " | " + metrics_cell(row, MaskRegion::overlap) +
          " | " + format("%.2f", row.sides.brighter) + " | " + format("%.2f", row.sides.darker) +
          " | " + format("%.1f", row.resource_mib) + " | " + optional_number(row.gpu_ms, "%.3f") +
          " | " + optional_number(row.cpu_ratio, "%.2f") + " |\n";
  }
  md += "\nThe same region (" + std::to_string(report.crop.width) + "x" +
        std::to_string(report.crop.height) + " pixels at " + std::to_string(report.crop.x) + ", " +
        std::to_string(report.crop.y) +
        ", where the reference's penumbrae are densest), reference first:\n\n";
  md += "| reference |";
  for (const auto& row : report.rows) md += " `" + row.graph + "` |";
  md += "\n|---|";
  for (std::size_t i = 0; i < report.rows.size(); ++i) md += "---|";
  md += "\n| ![reference](" + report.reference_crop + ") |";
  for (const auto& row : report.rows) md += " ![" + row.graph + "](" + row.crop + ") |";
  md += "\n";
  return md;
}

}  // namespace antumbra::app
