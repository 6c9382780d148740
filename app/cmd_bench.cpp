// antumbra bench: named scenarios in one process (one device, so ratios compare like
// with like), warm-up then timed frames, per-pass GPU medians, CSV + JSON + PNG plot.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "antumbra/fg/json_document.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "bench_scenarios.hpp"
#include "commands.hpp"
#include "plot.hpp"
#include "render_session.hpp"

namespace antumbra::app {
namespace {

struct Outcome {
  Scenario scenario;
  std::string status = "ok";  // ok | missing-graph | invalid | error
  std::string detail;
  unsigned width = 0;
  unsigned height = 0;
  double total_gpu_ms = 0.0;
  std::vector<PassTiming> passes;
};

void write_reports(const std::filesystem::path& dir, const std::string& device,
                   const BenchOptions& options, const std::vector<Outcome>& outcomes) {
  std::filesystem::create_directories(dir);
  std::ofstream csv(dir / "bench.csv");
  csv << "scenario,table,technique,kernel,width,height,lights,status,total_gpu_ms,passes\n";
  auto json = nlohmann::json::array();
  std::vector<BarRow> rows;
  for (const auto& o : outcomes) {
    std::string passes;
    auto pass_json = nlohmann::json::array();
    for (const auto& p : o.passes) {
      passes += (passes.empty() ? "" : ";") + p.name + "=" + std::to_string(p.gpu_ms);
      pass_json.push_back(
          {{"name", p.name}, {"type", p.type}, {"gpuMs", p.gpu_ms}, {"cpuMs", p.cpu_ms}});
    }
    csv << o.scenario.name << ',' << o.scenario.table << ',' << o.scenario.technique << ','
        << o.scenario.kernel << ',' << o.width << ',' << o.height << ',' << o.scenario.lights << ','
        << o.status << ',' << o.total_gpu_ms << ',' << passes << '\n';
    json.push_back({{"scenario", o.scenario.name},
                    {"table", o.scenario.table},
                    {"technique", o.scenario.technique},
                    {"kernel", o.scenario.kernel},
                    {"width", o.width},
                    {"height", o.height},
                    {"lights", o.scenario.lights},
                    {"status", o.status},
                    {"detail", o.detail},
                    {"totalGpuMs", o.total_gpu_ms},
                    {"passes", pass_json}});
    char annotation[64];
    std::snprintf(annotation, sizeof annotation, "%.3f ms", o.total_gpu_ms);
    rows.push_back({o.scenario.name, o.total_gpu_ms, o.status == "ok" ? annotation : o.status});
  }
  std::ofstream(dir / "bench.json") << nlohmann::json{{"device", device},
                                                      {"frames", options.frames},
                                                      {"warmup", options.warmup},
                                                      {"scale", options.scale},
                                                      {"scenarios", json}}
                                           .dump(2)
                                    << '\n';
  write_bar_chart((dir / "bench.png").string(),
                  "antumbra bench: total GPU ms per frame on " + device, rows);
}

Outcome run_scenario(RenderSession& session, const DataPaths& paths, const scene::Scene& base,
                     const Scenario& scenario, const BenchOptions& options) {
  Outcome o{scenario};
  o.width = std::max(16u, static_cast<unsigned>(std::lround(scenario.width * options.scale)));
  o.height = std::max(16u, static_cast<unsigned>(std::lround(scenario.height * options.scale)));
  const auto graph_path = paths.graphs() / scenario.graph;
  if (!std::filesystem::exists(graph_path)) {
    o.status = "missing-graph";
    o.detail = graph_path.string() + " does not exist";
    return o;
  }
  auto document = fg::load_json_file(graph_path.string());
  auto graph = document.ok() ? fg::parse_graph(document.value())
                             : fg::Result<fg::GraphDesc>(document.diagnostics());
  if (!graph.ok()) {
    o.status = "invalid";
    o.detail = graph.diagnostics().to_text();
    return o;
  }
  if (auto unmatched = apply_overrides(graph.value(), scenario.overrides); !unmatched.empty()) {
    o.status = "invalid";
    o.detail = "override matches no pass: " + unmatched.front();
    return o;
  }
  fit_shadow_resources(graph.value(), scenario.lights);
  session.set_viewport({o.width, o.height});
  if (auto diagnostics = session.load_graph(graph.value()); diagnostics.has_errors()) {
    o.status = "invalid";
    o.detail = diagnostics.to_text();
    return o;
  }
  session.set_scene(with_light_count(base, scenario.lights));
  session.render(options.warmup, nullptr);
  session.reset_timings();
  session.render(options.frames, nullptr);
  o.passes = session.pass_timings();
  for (const auto& p : o.passes) o.total_gpu_ms += p.gpu_ms;
  return o;
}

}  // namespace

int run_bench(const BenchOptions& options) {
  const auto all = builtin_scenarios();
  const auto chosen = select_scenarios(all, options.filters);
  if (options.list) {
    for (const auto& s : all) std::printf("%s\n", s.name.c_str());
    return kExitOk;
  }
  if (chosen.empty()) {
    std::fprintf(stderr, "antumbra bench: no scenario matches; see `antumbra bench --list`\n");
    return kExitUsage;
  }
  const DataPaths paths = find_data_paths();
  auto base = scene::load_scene_file((paths.scenes() / "atrium.json").string());
  if (!base.ok()) {
    std::fprintf(stderr, "%s", base.diagnostics().to_text().c_str());
    return kExitDiagnostics;
  }
  SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  RenderSession session(paths, session_options);
  std::fprintf(stderr,
               "bench on %s: %zu scenario(s), %d warm-up + %d timed frames each, scale %.2f\n",
               session.gpu().device_name().c_str(), chosen.size(), options.warmup, options.frames,
               options.scale);
  std::vector<Outcome> outcomes;
  int failures = 0;
  gpu::CpuTimer clock;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const auto& s = chosen[i];
    std::fprintf(stderr, "[%zu/%zu] %-40s ", i + 1, chosen.size(), s.name.c_str());
    std::fflush(stderr);
    Outcome o;
    try {
      o = run_scenario(session, paths, base.value(), s, options);
    } catch (const std::exception& e) {
      o = Outcome{s};
      o.status = "error";
      o.detail = e.what();
    }
    if (o.status == "ok") {
      std::fprintf(stderr, "%9.3f ms  (%.0f s elapsed)\n", o.total_gpu_ms,
                   clock.elapsed_ms() / 1000.0);
    } else {
      std::fprintf(stderr, "%s: %s\n", o.status.c_str(),
                   o.detail.substr(0, o.detail.find('\n')).c_str());
      if (o.status != "missing-graph") ++failures;
    }
    outcomes.push_back(std::move(o));
  }
  write_reports(options.out, session.gpu().device_name(), options, outcomes);
  std::printf("wrote %s/bench.csv, bench.json, bench.png\n", options.out.c_str());
  if (options.validation && session.gpu().validation_error_count() > 0) {
    std::fprintf(stderr, "antumbra bench: %zu validation error(s)\n",
                 session.gpu().validation_error_count());
    return kExitRuntime;
  }
  return failures > 0 ? kExitRuntime : kExitOk;
}

}  // namespace antumbra::app
