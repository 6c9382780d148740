#include "editor_state.hpp"

#include <cstdio>

namespace antumbra::editor_app {

void print_diagnostics(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
}

editor::EditResult EditorState::edit_structure(
    const std::function<editor::EditResult(editor::GraphEdits&)>& edit) {
  fg::CompileOptions options;
  options.viewport = {session_.viewport().width, session_.viewport().height};
  return edit_graph([&](editor::GraphDocument& graph) {
    editor::GraphEdits edits(graph, session_.pass_registry().reflection(), options);
    return edit(edits);
  });
}

editor::EditResult EditorState::check_connect(const editor::PortRef& from,
                                              const editor::PortRef& to) {
  const std::string key = from.pass + "." + from.port + ">" + to.pass + "." + to.port + "@" +
                          std::to_string(graph().revision());
  if (key == last_verdict_.key) return last_verdict_.result;
  fg::CompileOptions options;
  options.viewport = {session_.viewport().width, session_.viewport().height};
  last_verdict_ = {key, ask_graph([&](editor::GraphDocument& graph) {
                     return editor::GraphEdits(graph, session_.pass_registry().reflection(),
                                               options)
                         .check_connect(from, to);
                   })};
  return last_verdict_.result;
}

void EditorState::log_target(const std::string& panel, const std::string& what, float x, float y) {
  if (!log_targets_) return;
  const std::string at =
      std::to_string(static_cast<int>(x)) + " " + std::to_string(static_cast<int>(y));
  std::string& last = logged_targets_[panel + ": " + what];
  if (last == at) return;
  last = at;
  std::printf("%s: at %s: %s\n", panel.c_str(), at.c_str(), what.c_str());
  std::fflush(stdout);
}

void EditorState::frame_presented() {
  const auto latency = take_change_latency_ms();
  if (!latency) return;
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.1f ms", *latency);
  // A refused file made no new frame: the status keeps saying so instead of timing one.
  if (!graph_refused()) set_message(message() + " (file seen -> new frame " + ms + ")");
  std::printf("editor: %s; graph: %s\n", message().c_str(), reload_summary().c_str());
  print_diagnostics(diagnostics());
  // What the new frame's passes report (a layer cap that is still too low) is said again
  // after every reload, not only the first time it appeared.
  print_diagnostics(session_.frame_diagnostics());
  std::fflush(stdout);
}

std::string EditorState::pass_time_text(const std::string& pass) const {
  for (const auto& t : timings_) {
    if (t.name != pass || t.gpu_samples.empty()) continue;
    char text[32];
    std::snprintf(text, sizeof text, "%.3f ms", t.gpu_ms);
    return text;
  }
  return "-- ms";
}

void EditorState::refresh_timings() {
  timings_ = session_.pass_timings();
  session_.reset_timings();  // medians over the next window of frames, not since start
}

}  // namespace antumbra::editor_app
