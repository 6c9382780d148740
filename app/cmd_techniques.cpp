// antumbra techniques: every shadow technique graph against the reference, with its
// memory, artefact proxies and (from bench.json files) its time, written as one Markdown
// table with crops of the same region (docs/techniques.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "antumbra/gpu/image_io.hpp"
#include "antumbra/runtime/data_paths.hpp"
#include "commands.hpp"
#include "techniques_report.hpp"

namespace antumbra::app {
namespace {

// The shipped graphs that each draw the frame with one shadow technique.
const std::vector<std::string> kTechniqueGraphs = {"hard.json",
                                                   "pcf.json",
                                                   "pcss.json",
                                                   "layered-ssss.json",
                                                   "layered-ssss-min.json",
                                                   "vsm.json",
                                                   "evsm2.json",
                                                   "evsm4.json",
                                                   "msm.json",
                                                   "vssm.json",
                                                   "sdf.json",
                                                   "penumbra-wedges.json"};

// `crop` of `image`, each pixel twice as large, display-encoded (clamped, gamma 2.2).
gpu::HostImage crop_image(const FloatImage& image, const CropRect& crop) {
  gpu::HostImage out;
  out.width = crop.width * 2;
  out.height = crop.height * 2;
  out.channels = 4;
  out.texels.resize(std::size_t{out.width} * out.height * 4);
  for (unsigned y = 0; y < out.height; ++y) {
    for (unsigned x = 0; x < out.width; ++x) {
      for (unsigned c = 0; c < 4; ++c) {
        const float v = c < 3 && c < image.channels
                            ? image.at(crop.x + x / 2, crop.y + y / 2, c)
                            : (c < 3 ? image.at(crop.x + x / 2, crop.y + y / 2, 0) : 1.0f);
        out.texels[(std::size_t{y} * out.width + x) * 4 + c] =
            c < 3 ? std::pow(std::clamp(v, 0.0f, 1.0f), 1.0f / 2.2f) : 1.0f;
      }
    }
  }
  return out;
}

std::optional<nlohmann::json> read_bench(const std::string& path) {
  if (path.empty()) return std::nullopt;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("techniques: cannot read " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("techniques: " + path +
                             " is not a bench.json (antumbra bench --out writes one): " + e.what());
  }
}

// quality's warning for a frame too small to rank techniques by; nothing for a malformed
// size, which the rendering refuses next.
std::optional<base::Diagnostic> size_warning_of(const std::string& size) {
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(size, width, height)) return std::nullopt;
  return ranking_size_warning(width, height);
}

// A "-" column says on stderr too why it has no number.
void warn_empty_columns(const TechniquesReport& report) {
  for (const auto& [column, note] :
       {std::pair{"GPU ms", &report.gpu_note}, std::pair{"lavapipe x hard", &report.cpu_note}}) {
    if (!note->empty()) {
      std::fprintf(stderr, "antumbra techniques: warning: the %s column is empty: %s\n", column,
                   note->c_str());
    }
  }
}

}  // namespace

int run_techniques(const TechniquesOptions& options) {
  const auto gpu_bench = read_bench(options.gpu_bench);
  const auto cpu_bench = read_bench(options.cpu_bench);
  const runtime::DataPaths paths = runtime::find_data_paths();
  QualityOptions quality;
  for (const auto& g : options.graphs.empty() ? kTechniqueGraphs : options.graphs) {
    quality.graphs.push_back(
        std::filesystem::path(g).has_parent_path() ? g : (paths.graphs() / g).string());
  }
  quality.scene = options.scene;
  quality.size = options.size;
  quality.device = options.device;
  quality.allow_outside_paths = options.allow_outside_paths;
  // Said before minutes of rendering, and again in the file.
  const auto size_warning = size_warning_of(options.size);
  if (size_warning) std::fprintf(stderr, "%s\n", base::format_text(*size_warning).c_str());
  auto frames = render_quality_frames(quality);
  if (!frames) return runtime::kExitDiagnostics;

  TechniquesReport report;
  report.device = frames->device;
  report.scene = std::filesystem::path(options.scene.empty() ? "atrium.json" : options.scene)
                     .filename()
                     .string();
  report.width = frames->reference.width;
  report.height = frames->reference.height;
  report.crop =
      densest_penumbra(frames->mask ? &*frames->mask : nullptr, report.width, report.height);
  if (gpu_bench) report.gpu_device = gpu_bench->value("device", "the lent GPU");
  const std::filesystem::path out(options.out);
  const std::filesystem::path crops = out.parent_path() / "techniques";
  std::filesystem::create_directories(crops);
  report.reference_crop = "techniques/reference.png";
  if (!gpu::write_png(crops / "reference.png", crop_image(frames->reference, report.crop))) {
    return runtime::kExitRuntime;
  }
  // The ratio column's denominator; 0 without a CPU bench or its hard row.
  const double cpu_hard = cpu_bench ? bench_frame_ms(*cpu_bench, "hard.json").value_or(0.0) : 0.0;
  for (std::size_t i = 0; i < frames->frames.size(); ++i) {
    TechniqueRow row;
    row.graph = std::filesystem::path(quality.graphs[i]).filename().string();
    row.comparisons = frames->comparisons[i];
    row.sides = error_sides(frames->reference, frames->frames[i]);
    row.resource_mib = frames->resource_mib[i];
    if (gpu_bench) row.gpu_ms = bench_frame_ms(*gpu_bench, row.graph);
    if (cpu_bench && cpu_hard > 0.0) {
      if (auto ms = bench_frame_ms(*cpu_bench, row.graph)) row.cpu_ratio = *ms / cpu_hard;
    }
    const std::string stem = std::filesystem::path(row.graph).stem().string();
    row.crop = "techniques/" + stem + ".png";
    if (!gpu::write_png(crops / (stem + ".png"), crop_image(frames->frames[i], report.crop))) {
      return runtime::kExitRuntime;
    }
    report.rows.push_back(std::move(row));
  }
  if (size_warning) report.size_warning = size_warning->message;
  note_empty_time_columns(report, options.gpu_bench, options.cpu_bench);
  warn_empty_columns(report);
  std::ofstream file(out);
  file << techniques_markdown(report);
  if (!file) {
    std::fprintf(stderr, "antumbra techniques: cannot write %s\n", options.out.c_str());
    return runtime::kExitRuntime;
  }
  std::printf("wrote %s and %zu crops under %s\n", options.out.c_str(), report.rows.size() + 1,
              crops.string().c_str());
  return runtime::kExitOk;
}

}  // namespace antumbra::app
