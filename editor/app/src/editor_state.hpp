#pragma once
// What the windowed editor's panels share: the edit session (antumbra/editor/
// edit_session.hpp: documents, undo, gestures, layer status, reloads, saving, the logic
// `edit --headless` runs too) over the window's RenderSession, plus what only a window
// shows: the status bar's drag note, per-pass GPU times and the log line after a reload
// from disk reaches the screen. Panels draw from it and forward their edits to it.

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "antumbra/editor/edit_session.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "antumbra/editor_app/session_renderer.hpp"
#include "antumbra/runtime/render_session.hpp"

namespace antumbra::editor_app {

// Prints each warning and error on its own line (stdout), notes left out.
void print_diagnostics(const base::Diagnostics& diagnostics);

using editor::DocKind;

class EditorState : public editor::EditSession {
 public:
  // `renderer` and `lookup` (the pass reflection) must outlive the state.
  EditorState(SessionRenderer& renderer, editor::SceneDocument scene, editor::GraphDocument graph,
              editor::PassDescLookup lookup, double poll_interval_ms = kDefaultPollMs)
      : EditSession(renderer, std::move(scene), std::move(graph), std::move(lookup),
                    poll_interval_ms),
        session_(renderer.session()) {}

  [[nodiscard]] runtime::RenderSession& session() { return session_; }

  // The status bar's line about the drag in progress (which plane), empty when none.
  void set_drag_note(std::string note) { drag_note_ = std::move(note); }
  [[nodiscard]] const std::string& drag_note() const { return drag_note_; }

  // Call after each presented frame: a reload from disk is timed from the poll that saw
  // the change to this frame, added to message() (the status bar) and printed to the log.
  void frame_presented();

  // The pass selected in the node view or the graph panel (one selection for both); a new
  // selection is revealed once in the graph panel (its parameters opened).
  [[nodiscard]] const std::string& selected_pass() const { return selected_pass_; }
  void select_pass(std::string pass) {
    reveal_ = pass != selected_pass_;
    selected_pass_ = std::move(pass);
  }
  bool take_selection_reveal() { return std::exchange(reveal_, false); }

  // Structural edits of the graph from the node view (editor::GraphEdits over the session's
  // pass registry, compiled at the viewport's size), each one undo step and a reload.
  editor::EditResult edit_structure(
      const std::function<editor::EditResult(editor::GraphEdits&)>& edit);
  // A connection's verdict without making it, remembered per pair (a drag asks every frame).
  editor::EditResult check_connect(const editor::PortRef& from, const editor::PortRef& to);

  // Input scripts (--frame-log) find widgets by where the panels say they are:
  // "graph panel: at X Y: param colour-grade.exposure", printed when it changes.
  void set_log_targets(bool on) { log_targets_ = on; }
  void log_target(const std::string& panel, const std::string& what, float x, float y);

  // Per-pass GPU times, refreshed every few frames (medians over those frames).
  [[nodiscard]] const std::vector<runtime::PassTiming>& timings() const { return timings_; }
  void refresh_timings();
  // "0.565 ms", or "-- ms" before the pass has been measured (the first frames after the
  // start or a reload): never a 0.000 that reads as a measurement.
  [[nodiscard]] std::string pass_time_text(const std::string& pass) const;

 private:
  runtime::RenderSession& session_;
  std::string drag_note_;
  std::string selected_pass_;
  struct ConnectVerdict {
    std::string key;  // from and to, at a graph revision
    editor::EditResult result;
  };
  ConnectVerdict last_verdict_;
  bool log_targets_ = false;
  std::map<std::string, std::string> logged_targets_;
  bool reveal_ = false;
  std::vector<runtime::PassTiming> timings_;
};

}  // namespace antumbra::editor_app
