#pragma once
// `antumbra bench --baseline B.json`: this run's medians beside a baseline bench.json's,
// scenario by scenario and pass by pass, with their ratio and a "slower" flag. Absolute
// times drift between machines and runs, a ratio measured in one session does not: the
// baseline is meant to be re-run, not trusted from an old file. No device here: the
// baseline is read and checked before any GPU work, and everything is tested on
// synthetic bench.json files (tests/bench/bench_baseline_test.cpp).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antumbra/base/json_document.hpp"
#include "bench_report.hpp"
#include "plot.hpp"

namespace antumbra::app {

// The team's A/B rule: a time is "slower" when it is at least 5 % above the baseline's
// AND at least 0.02 ms above it (below that, timestamp granularity and noise on small
// passes make any percentage meaningless). `--fail-slower PCT` replaces the 5 %.
inline constexpr double kSlowerRatio = 1.05;
inline constexpr double kSlowerMinMs = 0.02;

struct SlowerRule {
  double ratio = kSlowerRatio;
  double min_ms = kSlowerMinMs;
  static SlowerRule from_percent(double percent) { return {1.0 + percent / 100.0, kSlowerMinMs}; }
  // `run_ms` against `baseline_ms` under both thresholds.
  [[nodiscard]] bool slower(double baseline_ms, double run_ms) const;
};

// A `--fail-slower` percentage: finite and >= 0 (NaN and negatives are usage errors).
bool valid_slower_percent(double percent);

// A missing, unreadable or malformed baseline: the message names the file and, where the
// text is at fault, line:column and the JSON Pointer of the value and what was expected.
class BaselineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a bench.json says about its run, and its scenarios (read back as BenchResults:
// name, status, detail, the frame's and each pass's timings; other fields ignored).
struct BenchFile {
  std::string file;
  std::string commit;  // empty when the file predates these fields
  std::string device;
  std::string driver;
  std::optional<int> frames;
  std::optional<int> warmup;
  std::optional<double> scale;
  // false: an interrupted run's partial file (`bench` rewrites bench.json after every
  // scenario); absent in files from before partial writes, which were always complete.
  std::optional<bool> complete;
  std::optional<int> planned;  // scenarios the run chose
  std::vector<BenchResult> results;
};

// Throws BaselineError.
BenchFile parse_bench_file(const base::JsonDocument& document);
BenchFile load_bench_file(const std::string& path);

// What this run was measured with, for the warnings below.
struct RunSetup {
  std::string device;
  int frames = 0;
  int warmup = 0;
  double scale = 1.0;
};

// One line per setting in which the baseline differs from this run (device, frames,
// warm-up frames, scale): ratios across devices or settings mean little. And one when
// the baseline is an interrupted run's: it is compared as far as it goes (accepted, not
// refused: what finished was measured in full), the scenarios it never reached show
// as only in this run.
std::vector<std::string> setup_mismatches(const BenchFile& baseline, const RunSetup& run);

// One line of the comparison: a pass or a scenario's frame ("frame").
struct BaselineRow {
  enum class Kind {
    compared,          // both sides ok: ratio and flag
    only_in_baseline,  // the scenario or pass is not in this run
    only_in_run,       // the scenario or pass is not in the baseline
    failed,            // the scenario's status is not "ok" on one side or both
  };
  Kind kind = Kind::compared;
  std::string scenario;
  std::string pass;  // "frame" for the per-frame sum
  std::string type;  // the pass type; empty for the frame
  std::optional<double> baseline_ms;
  std::optional<double> run_ms;
  std::optional<double> ratio;  // run over baseline; none when not compared or baseline is 0
  bool slower = false;
  bool frame = false;           // the scenario's frame row (one-sided and failed scenarios too)
  std::string baseline_status;  // the scenario's status on each side; empty: absent there
  std::string run_status;
  // Where the row lives in this run's results (for bench.json and the plot): the
  // scenario's index, and the pass's (none: the frame). No scenario: only in baseline.
  std::optional<std::size_t> run_scenario;
  std::optional<std::size_t> run_pass;
};

struct BaselineComparison {
  std::vector<BaselineRow> rows;  // this run's order; rows only in the baseline last
  SlowerRule rule;
  [[nodiscard]] std::size_t count(BaselineRow::Kind kind) const;
  [[nodiscard]] std::size_t slower_count() const;
};

// Scenarios match by name, passes within a scenario by name (the n-th pass of a name
// with the n-th). Per scenario: its passes in this run's order, the baseline's extra
// passes, then the frame; a failed scenario is one "frame" row and never a ratio.
BaselineComparison compare_with_baseline(const std::vector<BenchResult>& baseline,
                                         const std::vector<BenchResult>& run,
                                         const SlowerRule& rule = {});

// "slower", "only in baseline", "only in this run", the failure, or "" (text and CSV).
std::string row_flag(const BaselineRow& row);

// The table on stdout: scenario, pass, baseline ms, this ms, ratio, flag; then the
// summary line with the count of slower rows.
void write_comparison_text(std::ostream& out, const BaselineComparison& comparison);

// bench_compare.csv: scenario,pass,pass_type,baseline_median_ms,median_ms,ratio,flag.
void write_comparison_csv(std::ostream& out, const BaselineComparison& comparison);

// Adds to a bench.json object (its "scenarios" from results_json of this run's results)
// baselineMedianMs, ratio and slower beside every compared medianMs ("baselineNote" for
// rows not compared) and a top-level "baseline" object: the file, its commit, device,
// driver and settings, the thresholds, the count of slower rows and the rows only in it.
void add_comparison_json(nlohmann::json& bench, const BenchFile& baseline,
                         const BaselineComparison& comparison);

// Marks the chart of this run (rows[i] is results[i]'s) with each scenario's baseline
// frame median and its ratio, and appends a row per scenario only in the baseline.
void add_comparison_to_chart(StackedChart& chart, const BaselineComparison& comparison);

// The three above for `bench --out DIR`: DIR/bench_compare.csv written atomically
// (std::runtime_error when it cannot be), this run's bench.json object and chart extended.
void add_comparison_reports(const std::filesystem::path& dir, const BenchFile& baseline,
                            const BaselineComparison& comparison, nlohmann::json& bench,
                            StackedChart& chart);

}  // namespace antumbra::app
