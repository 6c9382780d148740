#pragma once
// What the windowed editor's panels share: the two documents, the running session, the
// live layer status, one undo order across both documents, gestures (a drag is one undo
// step), saving and recovery. Panels draw from it and forward their edits to it; every
// edit reaches the GPU and the layer report before the next frame is rendered.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/layer_status.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/editor/viewport.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/watch/file_watcher.hpp"

namespace antumbra::editor_app {

enum class DocKind { scene, graph };

class EditorState {
 public:
  // `lookup` (the pass reflection) must outlive the state: reloaded graphs use it.
  // How often poll_files() looks at the files on disk: a few times a second by default
  // (modification times are cheap, but not free at 60 Hz); tests poll on every call.
  static constexpr double kDefaultPollMs = 250.0;

  EditorState(runtime::RenderSession& session, editor::SceneDocument scene,
              editor::GraphDocument graph, editor::PassDescLookup lookup,
              double poll_interval_ms = kDefaultPollMs);

  // The first load of the graph and the scene; false (diagnostics printed) on errors.
  // `images`: decodes already made while opening the scene (may be null).
  bool start(scene::ImageCache* images = nullptr);

  [[nodiscard]] runtime::RenderSession& session() { return session_; }
  [[nodiscard]] editor::SceneDocument& scene() { return scene_; }
  [[nodiscard]] const editor::GraphDocument& graph() const { return graph_; }
  [[nodiscard]] editor::LayerStatus& status() { return status_; }
  [[nodiscard]] const editor::LayerReport& report() { return status_.update(scene_); }

  // The viewport's navigation camera. Not part of the scene document (looking around is
  // not an edit); it survives scene reloads. reset_camera() returns to the scene's.
  [[nodiscard]] const editor::ViewportCamera& camera() const { return camera_; }
  void set_camera(const editor::ViewportCamera& camera);
  void reset_camera();
  // How far a viewport drag may move a light: the scene's extent (editor::drag_limit).
  [[nodiscard]] float drag_limit() const { return drag_limit_; }
  // The status bar's line about the drag in progress (which plane), empty when none.
  void set_drag_note(std::string note) { drag_note_ = std::move(note); }
  [[nodiscard]] const std::string& drag_note() const { return drag_note_; }

  // Edits. A gesture (a drag, typing into a field) is one undo step however many edits
  // it forwards: open_gesture() when a widget becomes active or a viewport drag starts;
  // end_frame() closes it once nothing holds it any more (no active widget, no drag).
  // No ImGui here: the views pass what they saw, so tests drive it without a window.
  void open_gesture(DocKind kind);
  void end_frame(bool held);
  [[nodiscard]] bool gesture_open() const { return gesture_open_; }
  void scene_edited(const editor::EditResult& result);
  void set_param(const std::string& pass, const std::string& name, const base::Json& value);
  void undo();
  void redo();
  [[nodiscard]] bool can_undo() const { return !undo_order_.empty(); }
  [[nodiscard]] bool can_redo() const { return !redo_order_.empty(); }

  // The layer cap: the graph's light-layering maxLayers.
  [[nodiscard]] int graph_cap() const;
  [[nodiscard]] std::string layering_pass() const;  // its name, empty without one

  // Which graph image the window shows: empty for the graph's own output.
  [[nodiscard]] const std::string& view_resource() const { return view_resource_; }
  void set_view_resource(const std::string& resource);
  [[nodiscard]] std::string shown_resource() const;  // the resource being shown now

  // The graph renders at the window's size: a new size reallocates its images (a reload).
  // False (and message()) when the graph cannot be realised at that size: it stays at
  // the old one.
  bool resize(VkExtent2D extent);

  // Live reload: the graph, the scene and every shader on disk, polled a few times a
  // second. A changed shader reloads the graph (the last good pipelines stay on error);
  // a changed graph or scene file replaces its document unless it has unsaved edits,
  // which win (the file is not lost: a save overwrites it only when asked).
  void poll_files();
  // Call after each presented frame: a reload from disk is timed from the poll that saw
  // the change to this frame, added to message() (the status bar) and printed to the log.
  void frame_presented();

  [[nodiscard]] bool dirty() const { return scene_.dirty() || graph_.dirty(); }
  bool save();  // atomic, both documents; false (and message()) when it failed
  void autosave();
  void close();  // a clean end: recovery files go
  // An end nobody confirmed (--frames ran out): unsaved edits are written to recovery
  // files instead of being dropped. Returns a line per document kept that way.
  std::vector<std::string> close_keeping_unsaved();

  [[nodiscard]] const base::Diagnostics& diagnostics() const { return diagnostics_; }
  [[nodiscard]] const std::string& reload_summary() const { return reload_summary_; }
  [[nodiscard]] const std::string& message() const { return message_; }
  // Per-pass GPU times, refreshed every few frames (medians over those frames).
  [[nodiscard]] const std::vector<runtime::PassTiming>& timings() const { return timings_; }
  void refresh_timings();
  // "0.565 ms", or "-- ms" before the pass has been measured (the first frames after the
  // start or a reload): never a 0.000 that reads as a measurement.
  [[nodiscard]] std::string pass_time_text(const std::string& pass) const;
  void set_message(std::string message) { message_ = std::move(message); }

 private:
  void note_edit(DocKind kind);
  void watch_files();  // (re)baselines the watched set: after loads and our own saves
  void reload_scene_file();
  void reload_graph_file();
  void sync_lights();
  void reload_graph();

  runtime::RenderSession& session_;
  editor::SceneDocument scene_;
  editor::GraphDocument graph_;
  editor::PassDescLookup lookup_;
  editor::LayerStatus status_;
  // Which document each undo/redo step belongs to, most recent last.
  std::vector<DocKind> undo_order_;
  std::vector<DocKind> redo_order_;
  bool gesture_open_ = false;
  bool gesture_noted_ = false;
  DocKind gesture_kind_ = DocKind::scene;
  std::string view_resource_;
  editor::ViewportCamera camera_{scene::Camera{}};
  scene::Camera scene_camera_;  // as the scene file has it
  float drag_limit_ = 1.0f;
  std::string drag_note_;
  base::Diagnostics diagnostics_;
  std::string reload_summary_;
  std::vector<std::string> edited_shaders_;  // the shader files behind the pending reload
  std::string message_;
  std::vector<runtime::PassTiming> timings_;
  watch::FileWatcher watcher_;
  gpu::CpuTimer since_poll_;
  double poll_interval_ms_ = kDefaultPollMs;
  std::optional<gpu::CpuTimer> since_change_;  // a change seen on disk, not yet on screen
};

}  // namespace antumbra::editor_app
