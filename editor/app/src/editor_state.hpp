#pragma once
// What the windowed editor's panels share: the edit session (antumbra/editor/
// edit_session.hpp: documents, undo, gestures, layer status, reloads, saving, the logic
// `edit --headless` runs too) over the window's RenderSession, plus what only a window
// shows: the status bar's drag note, per-pass GPU times and the log line after a reload
// from disk reaches the screen. Panels draw from it and forward their edits to it.

#include <string>
#include <vector>

#include "antumbra/editor/edit_session.hpp"
#include "antumbra/editor_app/session_renderer.hpp"
#include "antumbra/runtime/render_session.hpp"

namespace antumbra::editor_app {

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

  // Per-pass GPU times, refreshed every few frames (medians over those frames).
  [[nodiscard]] const std::vector<runtime::PassTiming>& timings() const { return timings_; }
  void refresh_timings();
  // "0.565 ms", or "-- ms" before the pass has been measured (the first frames after the
  // start or a reload): never a 0.000 that reads as a measurement.
  [[nodiscard]] std::string pass_time_text(const std::string& pass) const;

 private:
  runtime::RenderSession& session_;
  std::string drag_note_;
  std::vector<runtime::PassTiming> timings_;
};

}  // namespace antumbra::editor_app
