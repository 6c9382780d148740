#include "antumbra/runtime/watch_loop.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fg/plan_diff.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/exit_codes.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "antumbra/watch/file_watcher.hpp"

namespace antumbra::runtime {
namespace {

void print(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note)
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
}

// Loads the graph file beside the running one through the one load path; diagnostics
// when it is refused.
base::Diagnostics reload_graph(RenderSession& session, const WatchOptions& options) {
  return session.load_graph(fg::GraphSource::from_file(options.graph_path),
                            [&](fg::GraphDesc& graph) {
                              if (!options.output.empty()) graph.output = options.output;
                            });
}

std::vector<std::filesystem::path> watched_files(const RenderSession& session,
                                                 const WatchOptions& options) {
  std::vector<std::filesystem::path> files{options.graph_path, options.scene_path};
  for (const auto& f : session.executor().shader_files()) files.emplace_back(f);
  return files;
}

}  // namespace

int run_watch_loop(RenderSession& session, const WatchOptions& options) {
  watch::FileWatcher watcher;
  watcher.set(watched_files(session, options));
  std::printf("watching %zu file(s); edit the graph, the scene or a shader\n", watcher.size());
  std::fflush(stdout);
  gpu::CpuTimer clock;
  int reloads = 0;
  while (options.seconds <= 0 || clock.elapsed_ms() < options.seconds * 1000.0) {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(options.poll_ms));
    const auto changed = watcher.poll();
    if (changed.empty()) continue;
    gpu::CpuTimer latency;
    const bool scene_changed =
        std::find(changed.begin(), changed.end(), std::filesystem::path(options.scene_path)) !=
        changed.end();
    const bool graph_changed = scene_changed ? changed.size() > 1 : true;
    base::Diagnostics diagnostics;
    const fg::Plan before = session.executor().plan();
    if (scene_changed) {
      auto scene = scene::load_scene_file(options.scene_path, nullptr, options.scene_options);
      diagnostics.append(scene.diagnostics());
      if (scene.ok()) session.set_scene(std::move(scene.value()));
    }
    // A shader edit re-prepares every pass: pipelines are rebuilt beside the live ones.
    if (graph_changed) diagnostics.append(reload_graph(session, options));
    print(diagnostics);
    if (diagnostics.has_errors()) {
      std::printf("reload failed (%s); the last good frame keeps running\n",
                  changed.front().string().c_str());
      std::fflush(stdout);
      continue;
    }
    const double compiled_ms = latency.elapsed_ms();
    session.render(1, nullptr);  // waits for the GPU: the new frame is done
    const double frame_ms = latency.elapsed_ms();
    const std::string resource =
        session.executor()
            .plan()
            .resources.at(static_cast<std::size_t>(session.executor().plan().output))
            .name;
    session.write_image(resource, options.out);
    ++reloads;
    watcher.set(watched_files(session, options));  // shaders may have changed
    std::printf(
        "reloaded %s in %.1f ms (change seen -> new frame written to %s; new frame rendered "
        "at %.1f ms, of which reload %.1f ms)\n",
        changed.front().string().c_str(), latency.elapsed_ms(), options.out.c_str(), frame_ms,
        compiled_ms);
    if (graph_changed) {
      auto diff = fg::diff_plans(before, session.executor().plan());
      std::vector<std::string> files;
      files.reserve(changed.size());
      for (const auto& f : changed) files.push_back(f.string());
      diff.passes_rebuilt = session.executor().passes_reading(files);
      std::printf("  %s\n", fg::to_text(diff).c_str());
    }
    // Warnings that still hold are reported again: a cap lowered in the file must say so.
    std::fflush(stdout);
    print(session.frame_diagnostics());
    std::fflush(stderr);
  }
  std::printf("watch ended after %d reload(s)\n", reloads);
  return kExitOk;
}

}  // namespace antumbra::runtime
