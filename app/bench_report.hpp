#pragma once
// What `antumbra bench` keeps of a run and how it writes it: per-pass and whole-frame
// GPU time as median, 10th and 90th percentile over the timed frames, written as a
// long-format CSV (one row per scenario and pass, the frame as pass "frame") and as
// JSON with the same numbers. No device here: tested on made-up samples.

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_scenarios.hpp"

namespace antumbra::app {

// Percentile p (0..100) of `values`, linear between closest ranks (numpy's default),
// so that p = 50 is the usual median. 0 for no values.
double percentile(std::vector<double> values, double p);

struct TimingStats {
  double median_ms = 0.0;
  double p10_ms = 0.0;
  double p90_ms = 0.0;
  std::size_t frames = 0;
};
TimingStats summarize(const std::vector<double>& samples_ms);

// Sums the passes' samples frame by frame (passes all record the same frames; a pass
// with fewer samples cuts the frame count, so no frame is summed half).
std::vector<double> frame_samples(const std::vector<std::vector<double>>& per_pass);

struct PassStats {
  std::string name;
  std::string type;
  TimingStats gpu;
  double cpu_median_ms = 0.0;
};

struct BenchResult {
  Scenario scenario;
  std::string status = "ok";  // ok | missing-graph | invalid | error
  std::string detail;
  std::vector<PassStats> passes;
  TimingStats frame;  // per-frame sum of the passes
  // `bench --steps`: the steps inside passes (type: the pass), not part of the frame's sum.
  std::vector<PassStats> steps;
  // What the passes reported about the last timed frame, e.g. SHD010's faces and texels
  // drawn and SHD005's lights drawn smaller (bench.json's "notes": code, pass, severity,
  // message, details with lists shortened to their lengths: compact_details).
  nlohmann::json notes = nlohmann::json::array();
};

// A pass message's details for bench.json: scalars and small objects as they are, each
// list as "<key>Count" (SHD002 lists every unshadowed light: thousands in the city).
nlohmann::json compact_details(const nlohmann::json& details);

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& text);

// The long CSV: header, then per scenario one row per pass, one "frame" row (a failed
// scenario: its "frame" row only, without numbers), then one row per step (pass_type
// "step:<pass>"; already inside their passes' times).
void write_long_csv(std::ostream& out, const std::vector<BenchResult>& results);

nlohmann::json results_json(const std::vector<BenchResult>& results);

// What a run was asked to do, for the head of bench.json and the run's first line.
// `warmup_from` says where the warm-up count came from ("default", "--warmup" or
// "--quick"): warm-up frames are never timed, so a reader of a short run must see them.
struct BenchRun {
  std::string commit;
  std::string device;
  std::string driver;
  int frames = 0;
  int warmup = 0;
  std::string warmup_from = "default";
  double scale = 1.0;
  std::string preset;        // "quick", or empty
  std::size_t planned = 0;   // scenarios chosen
  std::size_t finished = 0;  // of them, the ones measured so far
};

// bench.json without a baseline: the run's head, "complete" (false until every planned
// scenario is in: the file is rewritten after each one, so an interrupted run leaves
// what finished) and the scenarios.
nlohmann::json bench_json(const BenchRun& run, const std::vector<BenchResult>& results);

// "bench on DEVICE: N scenario(s), W warm-up (default) + F timed frames each, scale S".
std::string bench_setup_line(const BenchRun& run);

}  // namespace antumbra::app
