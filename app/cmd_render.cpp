// antumbra render: compile the graph, render headless, write the image, print timings.
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fg/registry.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/load_progress.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/runtime/watch_loop.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "commands.hpp"

namespace antumbra::app {
namespace {

void print_diagnostics(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note)
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
}

void print_timings(const runtime::RenderSession& session,
                   const std::vector<runtime::PassTiming>& timings, int frames) {
  std::printf("%-20s %-20s %10s %10s\n", "pass", "type", "gpu ms", "cpu ms");
  double gpu_total = 0.0;
  double cpu_total = 0.0;
  for (const auto& t : timings) {
    std::printf("%-20s %-20s %10.3f %10.3f\n", t.name.c_str(), t.type.c_str(), t.gpu_ms, t.cpu_ms);
    gpu_total += t.gpu_ms;
    cpu_total += t.cpu_ms;
  }
  std::printf("%-20s %-20s %10.3f %10.3f   (median of %d frame(s))\n", "total", "", gpu_total,
              cpu_total, frames);
  for (const auto& culled : session.executor().plan().culled_passes) {
    std::printf("%-20s (culled: its outputs reach no graph output)\n", culled.c_str());
  }
}

// Everything a tool needs from one run: timings, what the passes reported (e.g.
// layer-cap warnings with the lights and conflicting pairs) and the diagnostics.
nlohmann::json render_report_json(const runtime::RenderSession& session, const std::string& device,
                                  const RenderOptions& options, const std::string& resource,
                                  const base::Diagnostics& diagnostics) {
  auto passes = nlohmann::json::array();
  for (const auto& t : session.pass_timings()) {
    passes.push_back(
        {{"name", t.name}, {"type", t.type}, {"gpuMs", t.gpu_ms}, {"cpuMs", t.cpu_ms}});
  }
  // One list: the compiler's diagnostics, then what the passes reported about the last
  // frame (with their machine-readable details, e.g. the conflicting pairs of LY001).
  auto all = diagnostics.to_json();
  const auto frame = session.frame_diagnostics();
  const auto& messages = session.last_report().messages();
  for (std::size_t i = 0; i < frame.size(); ++i) {
    auto item = base::to_json(frame[i]);
    item["pass"] = messages[i].pass;
    item["details"] = nlohmann::json::parse(messages[i].details.dump());
    all.push_back(std::move(item));
  }
  return {{"ok", true},
          {"device", device},
          {"graph", session.executor().plan().file},
          {"output", resource},
          {"image", options.out},
          {"frames", options.frames},
          {"passes", passes},
          {"culled", session.executor().plan().culled_passes},
          {"diagnostics", all}};
}

// A run that fails still answers a tool that asked for JSON: {"ok": false, diagnostics}.
int fail_render(const base::Diagnostics& diagnostics, int code, bool json,
                const std::string& graph_path) {
  print_diagnostics(diagnostics);
  if (json) {
    std::printf("%s\n", nlohmann::json{{"ok", false},
                                       {"graph", graph_path},
                                       {"exitCode", code},
                                       {"diagnostics", diagnostics.to_json()}}
                            .dump(2)
                            .c_str());
  }
  return code;
}

// What a render reads from disk, checked before the GPU is touched.
struct RenderInputs {
  std::string graph_path;
  std::string scene_path;
  fg::GraphDesc graph;
  scene::Scene scene;
};

// Wall-clock milliseconds of the CPU stages of one render, in the order they run.
struct StageTimes {
  double parse_ms = 0.0;
  double device_ms = 0.0;
  double compile_ms = 0.0;
  double upload_ms = 0.0;
  double render_ms = 0.0;
  double write_ms = 0.0;
};

// --output names a resource that becomes the graph's output: it is kept alive (never
// aliased) and only the passes that feed it run. False (after saying why) when the graph
// has no such resource.
bool apply_output_resource(const RenderOptions& options, const std::string& graph_path,
                           fg::GraphDesc& graph) {
  if (options.output.empty()) return true;
  if (graph.find_resource(options.output) < 0) {
    std::vector<std::string> names;
    for (const auto& r : graph.resources) names.push_back(r.name);
    std::fprintf(stderr, "antumbra render: --output \"%s\" is not a resource of %s%s\n",
                 options.output.c_str(), graph_path.c_str(),
                 fg::did_you_mean(options.output, names).c_str());
    return false;
  }
  graph.output = options.output;
  return true;
}

// User input first, so a broken file fails fast without touching the GPU. Returns the
// exit code of the failure, or kExitOk with `inputs` filled.
int load_render_inputs(const RenderOptions& options, bool json, RenderInputs& inputs) {
  // The one load path's read (fg/graph_source.hpp): the device, and with it the load's
  // second half (RenderSession::load_graph), comes after the scene is read too.
  auto graph = fg::read_graph(fg::GraphSource::from_file(inputs.graph_path));
  if (!graph.ok()) {
    return fail_render(graph.diagnostics(), runtime::exit_code_for(graph.diagnostics()), json,
                       inputs.graph_path);
  }
  if (!apply_output_resource(options, inputs.graph_path, graph.value())) {
    return runtime::kExitUsage;
  }
  scene::ImageCache images;  // the load's shared state, progress sink included
  runtime::LoadProgressPrinter progress;
  images.set_progress(progress.sink());
  auto scene = scene::load_scene_file(inputs.scene_path, &images,
                                      {.allow_outside_paths = options.allow_outside_paths});
  progress.finish();
  images.set_progress({});
  if (!scene.ok()) {
    return fail_render(scene.diagnostics(), runtime::exit_code_for(scene.diagnostics()), json,
                       inputs.graph_path);
  }
  print_diagnostics(scene.diagnostics());
  inputs.graph = std::move(graph.value());
  inputs.scene = std::move(scene.value());
  return runtime::kExitOk;
}

runtime::SessionOptions session_options_for(const RenderOptions& options, unsigned width,
                                            unsigned height) {
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.viewport = {width, height};
  // `renderdoccmd capture ... render` captures the frame written (README).
  session_options.capture_last_frame = true;
  return session_options;
}

// A valid graph this device cannot hold (memory, limits) is a runtime failure, as the
// README promises (3), not a problem in the file (1).
int graph_load_exit_code(const base::Diagnostics& diagnostics) {
  return diagnostics.find(codes::graph::kRealiseFailed) != nullptr ? runtime::kExitRuntime
                                                                   : runtime::kExitDiagnostics;
}

const fg::PlanResource& output_resource(const runtime::RenderSession& session) {
  return session.executor().plan().resources.at(
      static_cast<std::size_t>(session.executor().plan().output));
}

void write_render_images(runtime::RenderSession& session, const RenderOptions& options,
                         const std::string& resource) {
  const auto out_dir = std::filesystem::path(options.out).parent_path();
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
  session.write_image(resource, options.out);
  if (!options.hdr_out.empty()) session.write_image(resource, options.hdr_out);
}

void print_render_report(runtime::RenderSession& session, const RenderOptions& options,
                         const std::string& resource, const base::Diagnostics& diagnostics,
                         const StageTimes& times, bool json) {
  if (json) {
    std::printf("%s\n", render_report_json(session, session.gpu().device_name(), options, resource,
                                           diagnostics)
                            .dump(2)
                            .c_str());
  } else {
    print_timings(session, session.pass_timings(), options.frames);
    print_diagnostics(session.frame_diagnostics());
  }
  if (!json) {
    std::printf(
        "cpu stages: parse %.1f ms, device %.1f ms, compile+realise %.1f ms, upload %.1f ms, "
        "render %.1f ms, write %.1f ms\n",
        times.parse_ms, times.device_ms, times.compile_ms, times.upload_ms, times.render_ms,
        times.write_ms);
    // The resource's own size: a half-resolution buffer is written as it is.
    const auto& written = output_resource(session);
    std::printf("wrote %s (%s, %ux%u)\n", options.out.c_str(), resource.c_str(),
                written.extent.width, written.extent.height);
  }
}

// The CPU stages before the frames go on the trace's CPU thread, one after the other.
void write_trace(runtime::TraceWriter& trace, const StageTimes& times, const std::string& path) {
  double t = 0.0;
  for (const auto& [name, ms] : {std::pair{"parse", times.parse_ms},
                                 {"device", times.device_ms},
                                 {"compile", times.compile_ms},
                                 {"upload", times.upload_ms}}) {
    trace.add({name, "cpu", t * 1000.0, ms * 1000.0, 1});
    t += ms;
  }
  trace.write(path);
}

// After a successful render: validation errors, then --werror's warnings, decide.
int render_exit_code(runtime::RenderSession& session, const RenderOptions& options,
                     const base::Diagnostics& diagnostics) {
  if (options.validation && session.gpu().validation_error_count() > 0) {
    std::fprintf(stderr, "antumbra render: %zu validation error(s)\n",
                 session.gpu().validation_error_count());
    return runtime::kExitRuntime;
  }
  const std::size_t warnings =
      diagnostics.warning_count() + session.frame_diagnostics().warning_count();
  if (options.werror && warnings > 0) {
    std::fprintf(stderr, "antumbra render: %zu warning(s) with --werror\n", warnings);
    return runtime::kExitDiagnostics;
  }
  return runtime::kExitOk;
}

}  // namespace

int run_render(const RenderOptions& options) {
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(options.size, width, height)) {
    std::fprintf(stderr, "antumbra render: --size must be WxH with 1..16384, got \"%s\"\n",
                 options.size.c_str());
    return runtime::kExitUsage;
  }
  const runtime::DataPaths paths = runtime::find_data_paths();
  RenderInputs inputs;
  inputs.graph_path =
      options.graph.empty() ? (paths.graphs() / "layered-ssss.json").string() : options.graph;
  inputs.scene_path =
      options.scene.empty() ? (paths.scenes() / "atrium.json").string() : options.scene;
  gpu::CpuTimer stage;
  const bool json = options.format == "json";
  if (const int code = load_render_inputs(options, json, inputs); code != runtime::kExitOk) {
    return code;
  }
  StageTimes times;
  times.parse_ms = stage.elapsed_ms();

  stage.restart();
  runtime::RenderSession session(paths, session_options_for(options, width, height));
  times.device_ms = stage.elapsed_ms();
  if (!json) {
    std::printf("device: %s%s\n", session.gpu().device_name().c_str(),
                options.validation ? " (validation + synchronization validation on)" : "");
  }

  stage.restart();
  const auto diagnostics = session.load_graph(inputs.graph);
  if (diagnostics.has_errors()) {
    return fail_render(diagnostics, graph_load_exit_code(diagnostics), json, inputs.graph_path);
  }
  print_diagnostics(diagnostics);
  times.compile_ms = stage.elapsed_ms();

  stage.restart();
  session.set_scene(std::move(inputs.scene));
  times.upload_ms = stage.elapsed_ms();

  runtime::TraceWriter trace;
  stage.restart();
  session.render(options.frames, options.trace.empty() ? nullptr : &trace);
  times.render_ms = stage.elapsed_ms();

  stage.restart();
  const std::string resource = output_resource(session).name;
  write_render_images(session, options, resource);
  times.write_ms = stage.elapsed_ms();

  print_render_report(session, options, resource, diagnostics, times, json);
  if (!options.trace.empty()) write_trace(trace, times, options.trace);
  if (options.watch) {
    std::fflush(stdout);
    runtime::WatchOptions watch{inputs.graph_path, inputs.scene_path, options.output, options.out,
                                options.watch_seconds};
    watch.scene_options.allow_outside_paths = options.allow_outside_paths;
    const int code = runtime::run_watch_loop(session, watch);
    if (code != runtime::kExitOk) return code;
  }
  return render_exit_code(session, options, diagnostics);
}

}  // namespace antumbra::app
