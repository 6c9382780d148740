#pragma once
// One function per subcommand. Each returns the process exit code:
// 0 success, 1 diagnostics found, 2 usage error, 3 runtime or device error.

#include <optional>
#include <string>
#include <vector>

#include "bench_scenarios.hpp"
#include "image_metrics.hpp"
#include "techniques_report.hpp"

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/runtime/exit_codes.hpp"

namespace antumbra::app {

struct ValidateOptions {
  std::vector<std::string> files;
  std::string format = "text";  // text | json
  bool werror = false;
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
};

struct PlanOptions {
  std::string file;
  std::string format = "json";  // json | dot | text
  std::string size = "1280x720";
  std::string times;     // bench.json whose per-pass medians weigh the schedule; empty: 1 each
  std::string scenario;  // the bench.json scenario to take them from (needed when several)
};

struct PassesOptions {
  std::string type;             // empty: list every pass type
  std::string format = "text";  // text | json | markdown
};

struct RenderOptions {
  std::string graph;                 // empty: the default graph
  std::string scene;                 // empty: the default scene
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
  std::string size = "1280x720";
  int frames = 1;
  std::string out = "out/frame.png";
  std::string output;  // resource to write; empty: the graph's output
  std::string device = "auto";
  bool validation = false;
  std::string trace;
  std::string hdr_out;          // optional .pfm of the HDR resource
  std::string format = "text";  // text | json (timings, pass reports, diagnostics)
  bool watch = false;           // keep running; reload on file changes
  double watch_seconds = 0;     // with watch: stop after this long (0 = until interrupted)
  bool werror = false;          // warnings (compiler's and passes') fail the run: exit 1
};

struct BenchOptions {
  std::vector<std::string> filters;  // substrings of scenario names; empty = all
  int frames = 60;
  int warmup = 10;
  double scale = 1.0;  // resolution scale (small on lavapipe)
  std::string out = "out/bench";
  std::string device = "auto";
  bool validation = false;
  bool list = false;
  bool steps = false;         // also time the steps inside passes (labels): rows "pass.step"
  std::string baseline;       // bench.json to compare with; empty: no comparison
  double fail_slower = -1.0;  // with baseline: exit 1 when a row is this % slower; < 0: off
  bool quick = false;         // the CPU-device preset (apply_quick_preset)
  DistrictRows district;      // the 1024-light district's rows (--quick shrinks them)
  std::string warmup_from = "default";  // where `warmup` came from: default|--warmup|--quick
};

// Which of the settings `--quick` presets the command line gave explicitly: those win.
struct GivenBenchSettings {
  bool frames = false;
  bool warmup = false;
  bool scale = false;
};
// `bench --quick` (bench_scenarios.hpp, kQuick*) where it is set, and where `warmup` came
// from either way.
void apply_quick_preset(BenchOptions& options, const GivenBenchSettings& given);

struct CompareOptions {
  std::string a;
  std::string b;
  std::string mask_image;       // PFM whose channel 0 selects pixels (e.g. penumbraCount)
  std::string mask;             // all | penumbra | overlap; empty: every region available
  std::string format = "text";  // text | json
};

struct QualityOptions {
  std::vector<std::string> graphs;   // technique graphs compared with the reference
  std::string reference;             // empty: data/graphs/reference.json
  std::string scene;                 // empty: data/scenes/atrium.json
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
  std::string size = "960x540";      // the smallest size whose ranking held (cmd_compare.cpp)
  std::string resource = "hdr";      // the HDR resource of every graph
  std::string out;                   // folder for per-technique error heat maps; empty: none
  std::string device = "auto";
  bool validation = false;
  std::string format = "text";
};

int run_validate(const ValidateOptions& options);
int run_bench(const BenchOptions& options);
int run_plan(const PlanOptions& options);
struct SchemaOptions {
  bool scene = false;     // the scene file format instead of graph files
  bool markdown = false;  // with scene: the reference (docs/scenes.md), not the JSON Schema
};

int run_schema(const SchemaOptions& options);
int run_passes(const PassesOptions& options);
int run_render(const RenderOptions& options);
int run_devices(const std::string& device, bool validation);
int run_compare(const CompareOptions& options);
int run_quality(const QualityOptions& options);

// What `quality` measures, kept for `techniques`: the reference's frame and region mask,
// and per graph its frame, its comparisons and the MiB its own resources take (all but
// the G-buffer and the output). Nothing (diagnostics printed) when something does not
// load.
struct QualityFrames {
  std::string device;
  FloatImage reference;
  std::optional<FloatImage> mask;
  std::vector<FloatImage> frames;
  std::vector<std::vector<Comparison>> comparisons;
  std::vector<double> resource_mib;
};
std::optional<QualityFrames> render_quality_frames(const QualityOptions& options);

// A warning (QU001) when a frame of `width` x `height` has too few pixels for the
// ranking of techniques to hold; nothing when it has enough (quality and techniques).
std::optional<base::Diagnostic> ranking_size_warning(unsigned width, unsigned height);

struct TechniquesOptions {
  std::vector<std::string> graphs;  // empty: every shipped technique graph
  std::string scene;                // empty: data/scenes/atrium.json
  std::string size = "960x540";
  std::string gpu_bench;  // bench.json from the lent GPU (table1 rows); empty: no column
  std::string cpu_bench;  // bench.json from lavapipe (table1 rows); empty: no column
  std::string out = kTechniquesDefaultOut;  // never the committed docs/ unless named
  std::string device = "auto";
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
};
int run_techniques(const TechniquesOptions& options);

struct DocsTablesOptions {
  std::string root = ".";  // the repository: README.md, docs/, docs/results/
  bool check = false;      // compare only: report differing tables, write nothing
};
int run_docs_tables(const DocsTablesOptions& options);

// "1280x720" -> width, height; false when malformed or out of 1..16384.
bool parse_size(const std::string& text, unsigned& width, unsigned& height);

}  // namespace antumbra::app
