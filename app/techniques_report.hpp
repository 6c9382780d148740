#pragma once
// `antumbra techniques`: one table of every shadow technique (docs/techniques.md). The
// parts that need no device: where the crops are cut, how a technique's bench row is
// found, the measured artefact proxies and the Markdown itself (tests/app).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image_metrics.hpp"

namespace antumbra::app {

struct CropRect {
  unsigned x = 0;
  unsigned y = 0;
  unsigned width = 0;
  unsigned height = 0;
};

// The window of a quarter of the image on each axis holding the most penumbra pixels of
// `mask` (channel 0 = penumbra count; overlapping penumbrae count twice): where the
// techniques differ most. The image's centre quarter when there is no mask.
CropRect densest_penumbra(const FloatImage* mask, unsigned width, unsigned height);

// The frame median (ms) of the technique that graph file `graph` (e.g. "pcss.json")
// measures in `bench` (bench.json: {"scenarios": [...]}): its table1 row at the largest
// height present, the 11-tap kernel where the technique has kernels. Nothing when absent.
std::optional<double> bench_frame_ms(const nlohmann::json& bench, const std::string& graph);

// Luminance brighter and darker than the reference, each averaged over all pixels (in
// 1/1000): light the technique lets through that the reference does not (bleeding,
// leaks, peter-panning, missing contact shadows) and light it takes away (acne, an
// overestimated umbra).
struct ErrorSides {
  double brighter = 0.0;
  double darker = 0.0;
};
ErrorSides error_sides(const FloatImage& reference, const FloatImage& image);

struct TechniqueRow {
  std::string graph;  // file name, e.g. "pcss.json"
  std::vector<Comparison> comparisons;
  ErrorSides sides;
  double resource_mib = 0.0;
  std::optional<double> gpu_ms;     // frame median, lent GPU
  std::optional<double> cpu_ratio;  // lavapipe frame time over hard's
  std::string crop;                 // crop image, relative to the Markdown file
};

struct TechniquesReport {
  std::string device;  // where the quality frames were rendered
  std::string scene;
  unsigned width = 0;
  unsigned height = 0;
  std::string gpu_device;  // the GPU bench's device, empty without one
  std::string reference_crop;
  CropRect crop;
  std::vector<TechniqueRow> rows;
  std::string size_warning;  // the frame is too small to rank by (ranking_size_warning)
  // Why the GPU ms / lavapipe columns hold no number at all; empty when one has a number.
  std::string gpu_note;
  std::string cpu_note;
};

// Sets the report's gpu_note and cpu_note for its rows: the `--gpu-bench` / `--cpu-bench`
// file given (empty: none) and, where a column is empty all the same, what that file
// lacks. A "-" column without a reason reads as "not measurable"; it only means "not
// measured here".
void note_empty_time_columns(TechniquesReport& report, const std::string& gpu_bench,
                             const std::string& cpu_bench);

std::string techniques_markdown(const TechniquesReport& report);

// Where `techniques` writes without --out: out/techniques.md under the working
// directory, never the committed docs/techniques.md (which `--out docs/techniques.md`
// regenerates on purpose).
inline constexpr const char* kTechniquesDefaultOut = "out/techniques.md";

}  // namespace antumbra::app
