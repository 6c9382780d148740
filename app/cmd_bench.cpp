// antumbra bench: named scenarios in one process (one device, so ratios compare like
// with like), warm-up then timed frames, per-pass and whole-frame GPU median, p10 and
// p90, long CSV + JSON + PNG plot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "antumbra/editor/atomic_file.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "bench_baseline.hpp"
#include "bench_report.hpp"
#include "bench_scenarios.hpp"
#include "build_commit.hpp"
#include "commands.hpp"
#include "driver_summary.hpp"
#include "plot.hpp"

namespace antumbra::app {
namespace {

// Stacked per-pass medians, one colour per pass type (the atlas is one colour whatever
// a graph names it; passes of one type add up); the whisker is the frame's p10..p90.
StackedChart chart_of(const std::string& device, const std::vector<BenchResult>& results) {
  StackedChart chart;
  chart.title = "antumbra bench on " + device + ": GPU time per frame";
  chart.axis_label =
      "milliseconds (bars: per-pass medians by pass type, stacked; whisker: frame "
      "p10..p90)";
  for (const auto& r : results) {
    StackedRow row{r.scenario.name, {}, r.frame.p10_ms, r.frame.p90_ms, r.status};
    for (const auto& p : r.passes) {
      auto it = std::find(chart.series.begin(), chart.series.end(), p.type);
      if (it == chart.series.end()) it = chart.series.insert(it, p.type);
      const auto index = static_cast<std::size_t>(it - chart.series.begin());
      row.segments.resize(std::max(row.segments.size(), index + 1), 0.0);
      row.segments[index] += p.gpu.median_ms;
    }
    if (r.status == "ok") {
      char text[96];
      std::snprintf(text, sizeof text, "%.3f ms [%.3f, %.3f]", r.frame.median_ms, r.frame.p10_ms,
                    r.frame.p90_ms);
      row.annotation = text;
    }
    chart.rows.push_back(std::move(row));
  }
  return chart;
}

// `--baseline`: the file, read before any GPU work, and this run's comparison with it.
struct Baseline {
  BenchFile file;
  BaselineComparison comparison;  // filled after the run
};

// Nothing when the file is missing or not a bench.json (said on stderr: a usage error).
std::optional<Baseline> read_baseline(const std::string& path) {
  try {
    return Baseline{load_bench_file(path), {}};
  } catch (const BaselineError& e) {
    std::fprintf(stderr, "antumbra bench: --baseline: %s\n", e.what());
    return std::nullopt;
  }
}

void warn_setup(const BenchFile& baseline, const BenchRun& run) {
  for (const auto& line :
       setup_mismatches(baseline, {run.device, run.frames, run.warmup, run.scale})) {
    std::fprintf(stderr, "antumbra bench: warning: %s\n", line.c_str());
  }
}

// --fail-slower PCT replaces the flag's 5 %.
SlowerRule rule_of(const BenchOptions& options) {
  return options.fail_slower >= 0.0 ? SlowerRule::from_percent(options.fail_slower) : SlowerRule{};
}

// The table on stdout, and the warnings again beside it (the run's log may be long).
void print_comparison(const Baseline& baseline, const BenchRun& run) {
  std::fflush(stdout);
  write_comparison_text(std::cout, baseline.comparison);
  std::cout.flush();
  warn_setup(baseline.file, run);
}

// The reports of the scenarios measured so far, rewritten after each one. Every file
// goes to a temporary beside it and is renamed over it, so a run killed at any moment
// leaves whole files; bench.json, last, says how far the run got ("complete").
void write_reports(const std::filesystem::path& dir, const BenchRun& run,
                   const std::vector<BenchResult>& results, std::optional<Baseline>& baseline,
                   const SlowerRule& rule) {
  std::filesystem::create_directories(dir);
  std::ostringstream csv;
  write_long_csv(csv, results);
  editor::write_file_atomically(dir / "bench.csv", csv.str());
  auto bench = bench_json(run, results);
  auto chart = chart_of(run.device, results);
  if (baseline) {
    baseline->comparison = compare_with_baseline(baseline->file.results, results, rule);
    add_comparison_reports(dir, baseline->file, baseline->comparison, bench, chart);
  }
  write_stacked_chart((dir / "bench.png").string(), chart);
  editor::write_file_atomically(dir / "bench.json", bench.dump(2) + '\n');
}

// Moving lights are placed anew before every frame, warm-up included, from one frame count
// that starts at 0 with each scenario: every run measures the same sequence of frames.
void measure(runtime::RenderSession& session, const BenchOptions& options,
             const std::vector<scene::PointLight>& base_lights, BenchResult& r) {
  runtime::RenderSession::BeforeFrame move;
  std::uint64_t frame = 0;
  if (r.scenario.moving > 0) {
    move = [&, motion = bench_motion(r.scenario)](int /*frame in this call*/) {
      session.set_lights(scene::animate_lights(base_lights, frame++, motion));
    };
  }
  session.render(options.warmup, nullptr, move);
  session.reset_timings();
  session.render(options.frames, nullptr, move);
  std::vector<std::vector<double>> samples;
  for (const auto& p : session.pass_timings()) {
    r.passes.push_back({p.name, p.type, summarize(p.gpu_samples), p.cpu_ms});
    samples.push_back(p.gpu_samples);
  }
  r.frame = summarize(frame_samples(samples));
  for (const auto& step : session.step_timings()) {
    r.steps.push_back({step.name, step.type, summarize(step.gpu_samples), 0.0});
  }
  for (const auto& m : session.last_report().messages()) {
    r.notes.push_back({{"code", m.code},
                       {"pass", m.pass},
                       {"severity", base::to_string(m.severity)},
                       {"message", m.message},
                       {"details", compact_details(nlohmann::json::parse(m.details.dump()))}});
  }
}

// Scenes by file name under data/scenes/, each loaded once per run.
class SceneCache {
 public:
  explicit SceneCache(std::filesystem::path folder) : folder_(std::move(folder)) {}
  const base::Result<scene::Scene>& get(const std::string& file) {
    auto it = scenes_.find(file);
    if (it == scenes_.end()) {
      it = scenes_.emplace(file, scene::load_scene_file((folder_ / file).string())).first;
    }
    return it->second;
  }

 private:
  std::filesystem::path folder_;
  std::map<std::string, base::Result<scene::Scene>> scenes_;
};

BenchResult run_scenario(runtime::RenderSession& session, const runtime::DataPaths& paths,
                         SceneCache& scenes, const Scenario& scenario,
                         const BenchOptions& options) {
  BenchResult r{scenario};
  const auto& base = scenes.get(scenario.scene);
  if (!base.ok()) {
    r.status = "invalid";
    r.detail = base.diagnostics().to_text();
    return r;
  }
  const auto graph_path = paths.graphs() / scenario.graph;
  if (!std::filesystem::exists(graph_path)) {
    r.status = "missing-graph";
    r.detail = graph_path.string() + " does not exist";
    return r;
  }
  // The one load path in its two halves (fg/graph_source.hpp), the scenario's changes
  // between them.
  auto graph = fg::read_graph(fg::GraphSource::from_file(graph_path.string()));
  if (!graph.ok()) {
    r.status = "invalid";
    r.detail = graph.diagnostics().to_text();
    return r;
  }
  if (auto unmatched = apply_overrides(graph.value(), scenario.overrides); !unmatched.empty()) {
    r.status = "invalid";
    r.detail = "override matches no pass: " + unmatched.front();
    return r;
  }
  fit_shadow_resources(graph.value(), scenario.lights, scenario.face);
  fit_atlas_format(graph.value(), scenario.rasterizer);
  fit_page_pool(graph.value(), scenario.pool_layers);
  session.set_viewport({scenario.width, scenario.height});
  if (auto diagnostics = session.load_graph(graph.value()); diagnostics.has_errors()) {
    r.status = "invalid";
    r.detail = diagnostics.to_text();
    return r;
  }
  scene::Scene scene = with_light_count(base.value(), scenario.lights);
  set_light_size(scene, scenario.light_size);
  const std::vector<scene::PointLight> base_lights = scene.lights;
  session.set_scene(std::move(scene));
  // The scene's moving objects from their frame 0, as the moving lights (measure).
  session.restart_motion();
  measure(session, options, base_lights, r);
  return r;
}

// What the run is set to do, for its first line and the head of bench.json.
BenchRun run_head(const gpu::Context& gpu, const BenchOptions& options, std::size_t planned) {
  BenchRun run;
  run.commit = build_commit();
  run.device = gpu.device_name();
  run.driver = driver_summary(gpu);
  run.frames = options.frames;
  run.warmup = options.warmup;
  run.warmup_from = options.warmup_from;
  run.scale = options.scale;
  run.preset = options.quick ? "quick" : "";
  run.planned = planned;
  return run;
}

// Scenario `index` of `chosen`, with its line on stderr; one that throws is a result of
// status "error", so the rest still run.
BenchResult run_reported(runtime::RenderSession& session, const runtime::DataPaths& paths,
                         SceneCache& scenes, const BenchOptions& options,
                         const std::vector<Scenario>& chosen, std::size_t index,
                         const gpu::CpuTimer& clock) {
  const auto& s = chosen[index];
  std::fprintf(stderr, "[%zu/%zu] %-40s ", index + 1, chosen.size(), s.name.c_str());
  std::fflush(stderr);
  BenchResult r;
  try {
    r = run_scenario(session, paths, scenes, s, options);
  } catch (const std::exception& e) {
    r = BenchResult{s};
    // A lost device ends the run (the caller stops): every later scenario would fail too.
    r.status = session.gpu().device_lost() ? "device-lost" : "error";
    r.detail = e.what();
  }
  if (r.status == "ok") {
    std::fprintf(stderr, "%9.3f ms  [p10 %.3f, p90 %.3f]  (%.0f s elapsed)\n", r.frame.median_ms,
                 r.frame.p10_ms, r.frame.p90_ms, clock.elapsed_ms() / 1000.0);
  } else {
    std::fprintf(stderr, "%s: %s\n", r.status.c_str(),
                 r.detail.substr(0, r.detail.find('\n')).c_str());
  }
  return r;
}

// --list: the names the filters select, those a run would measure.
int list_scenarios(const std::vector<Scenario>& chosen) {
  for (const auto& s : chosen) std::printf("%s\n", s.name.c_str());
  return runtime::kExitOk;
}

// The exit code once the reports are written.
int run_exit_code(const BenchOptions& options, const gpu::Context& gpu, int failures,
                  const std::optional<Baseline>& baseline) {
  if (options.validation && gpu.validation_error_count() > 0) {
    std::fprintf(stderr, "antumbra bench: %zu validation error(s)\n", gpu.validation_error_count());
    return runtime::kExitRuntime;
  }
  if (failures > 0) return runtime::kExitRuntime;
  // Flags alone never fail a run; --fail-slower makes them an exit 1 for scripts.
  const bool fail =
      baseline && options.fail_slower >= 0.0 && baseline->comparison.slower_count() > 0;
  return fail ? runtime::kExitDiagnostics : runtime::kExitOk;
}

}  // namespace

void apply_quick_preset(BenchOptions& options, const GivenBenchSettings& given) {
  if (given.warmup) options.warmup_from = "--warmup";
  if (!options.quick) return;
  if (!given.frames) options.frames = kQuickFrames;
  if (!given.warmup) {
    options.warmup = kQuickWarmup;
    options.warmup_from = "--quick";
  }
  if (!given.scale) options.scale = kQuickScale;
  options.district = kQuickDistrict;
}

int run_bench(const BenchOptions& options) {
  const auto chosen =
      select_scenarios(builtin_scenarios(options.scale, options.district), options.filters);
  if (chosen.empty()) {
    std::fprintf(stderr, "antumbra bench: no scenario matches; see `antumbra bench --list`\n");
    return runtime::kExitUsage;
  }
  if (options.list) return list_scenarios(chosen);
  std::optional<Baseline> baseline;
  if (!options.baseline.empty() && !(baseline = read_baseline(options.baseline))) {
    return runtime::kExitUsage;
  }
  const runtime::DataPaths paths = runtime::find_data_paths();
  SceneCache scenes(paths.scenes());
  if (const auto& atrium = scenes.get("atrium.json"); !atrium.ok()) {
    std::fprintf(stderr, "%s", atrium.diagnostics().to_text().c_str());
    return runtime::kExitDiagnostics;
  }
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.time_steps = options.steps;
  runtime::RenderSession session(paths, session_options);
  BenchRun run = run_head(session.gpu(), options, chosen.size());
  std::fprintf(stderr, "%s\n", bench_setup_line(run).c_str());
  if (baseline) warn_setup(baseline->file, run);
  const SlowerRule rule = rule_of(options);
  std::vector<BenchResult> results;
  int failures = 0;
  gpu::CpuTimer clock;
  try {
    // Written before the first scenario too: a previous run's files in the folder are
    // replaced by this run's (empty, incomplete) ones, and an unwritable folder fails now.
    write_reports(options.out, run, results, baseline, rule);
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      results.push_back(run_reported(session, paths, scenes, options, chosen, i, clock));
      const auto& status = results.back().status;
      if (status != "ok" && status != "missing-graph") ++failures;
      run.finished = results.size();
      write_reports(options.out, run, results, baseline, rule);
      if (status == "device-lost") {
        std::fprintf(stderr, "antumbra bench: stopped after %zu of %zu scenarios: %s\n",
                     results.size(), chosen.size(), results.back().detail.c_str());
        return runtime::kExitRuntime;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antumbra bench: %s\n", e.what());
    return runtime::kExitRuntime;
  }
  std::printf("wrote %s/bench.csv, bench.json, bench.png%s\n", options.out.c_str(),
              baseline ? ", bench_compare.csv" : "");
  if (baseline) print_comparison(*baseline, run);
  return run_exit_code(options, session.gpu(), failures, baseline);
}

}  // namespace antumbra::app
