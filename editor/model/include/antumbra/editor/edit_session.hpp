#pragma once
// The edit session (docs/architecture.md, "The edit session"): what the editor does with
// an edit, whichever host drives it. It owns the two documents, one undo order across
// them, gestures (a drag is one undo step), the live layer status under the graph's cap,
// the navigation camera, the graph view (which resource is shown), reloads as
// transactions, files changed on disk, saving and recovery. The windowed editor
// (editor_app::EditorState) and `edit --headless` (app/edit_script.cpp) both run it over
// a RenderSession; tests run it over a renderer that only compiles. Every edit reaches the
// renderer and the layer report before the next frame. An edit is never lost: one the
// graph refuses stays in its document (undoable, saved when asked) while the last good
// graph keeps running, and a file changed on disk does not replace a document with unsaved
// edits.

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/layer_status.hpp"
#include "antumbra/editor/renderer.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/editor/viewport.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/watch/file_watcher.hpp"

namespace antumbra::editor {

enum class DocKind { scene, graph };

class EditSession {
 public:
  // How often poll_files() looks at the files on disk: a few times a second by default
  // (modification times are cheap, but not free at 60 Hz); tests poll on every call.
  static constexpr double kDefaultPollMs = 250.0;

  // `renderer` and `lookup` (the pass reflection: reloaded graphs use it) must outlive the
  // session.
  EditSession(Renderer& renderer, SceneDocument scene, GraphDocument graph, PassDescLookup lookup,
              double poll_interval_ms = kDefaultPollMs);

  // The first load of the graph and the scene; false on errors (diagnostics() says which).
  // `images`: decodes already made while opening the scene (may be null).
  bool start(scene::ImageCache* images = nullptr);

  [[nodiscard]] Renderer& renderer() { return renderer_; }
  [[nodiscard]] SceneDocument& scene() { return scene_; }
  [[nodiscard]] const SceneDocument& scene() const { return scene_; }
  [[nodiscard]] const GraphDocument& graph() const { return graph_; }
  [[nodiscard]] LayerStatus& status() { return status_; }
  [[nodiscard]] const LayerReport& report() { return status_.update(scene_); }

  // The viewport's navigation camera. Not part of the scene document (looking around is
  // not an edit); it survives scene reloads. reset_camera() returns to the scene's.
  [[nodiscard]] const ViewportCamera& camera() const { return camera_; }
  void set_camera(const ViewportCamera& camera);
  void reset_camera();
  // How far a viewport drag may move a light: the scene's extent (editor::drag_limit).
  [[nodiscard]] float drag_limit() const { return drag_limit_; }

  // Edits. A gesture (a drag, typing into a field) is one undo step however many edits
  // it forwards: open_gesture() when a widget becomes active or a viewport drag starts;
  // end_frame() closes it once nothing holds it any more (no active widget, no drag).
  void open_gesture(DocKind kind);
  void end_frame(bool held);
  [[nodiscard]] bool gesture_open() const { return gesture_open_; }
  // After an edit of scene(): its lights reach the renderer and the layer status.
  void scene_edited(const EditResult& result);
  // A parameter edit through the reflection, then a reload. A graph that refuses it keeps
  // the edit in the document (diagnostics() says why) and the last good graph running.
  EditResult set_param(const std::string& pass, const std::string& name, const base::Json& value);
  // A structural edit of the graph (a GraphEdits made over the document `edit` is given),
  // then a reload, as set_param. A graph the edit broke (a pass removed that others read)
  // keeps the edit in the document, undoable, while the last good graph keeps running.
  EditResult edit_graph(const std::function<EditResult(GraphDocument&)>& edit);
  // Asks an edit's question without making it (GraphEdits::check_connect while a wire is
  // dragged): `ask` must leave the document as it was.
  EditResult ask_graph(const std::function<EditResult(GraphDocument&)>& ask);
  // The pass types' reflection the documents are read with.
  [[nodiscard]] const PassDescLookup& lookup() const { return lookup_; }
  // One order across both documents; false when there is nothing to undo (redo).
  bool undo();
  bool redo();
  [[nodiscard]] bool can_undo() const { return !undo_order_.empty(); }
  [[nodiscard]] bool can_redo() const { return !redo_order_.empty(); }

  // The layer cap: the graph's light-layering maxLayers.
  [[nodiscard]] int graph_cap() const;
  [[nodiscard]] std::string layering_pass() const;  // its name, empty without one

  // Which graph image is shown: empty for the graph's own output (like render --output).
  [[nodiscard]] const std::string& view_resource() const { return view_resource_; }
  void set_view_resource(const std::string& resource);
  [[nodiscard]] std::string shown_resource() const;  // the resource being shown now

  // The graph renders at the viewport's size: a new size reallocates its images (a
  // reload). False (and message()) when the graph cannot be realised at that size: it
  // stays at the old one.
  bool resize(fg::Extent2D extent);

  // Live reload: the graph, the scene and every shader on disk, polled a few times a
  // second. A changed shader reloads the graph (the last good pipelines stay on error);
  // a changed graph or scene file replaces its document unless it has unsaved edits,
  // which win (the file is not lost: a save overwrites it only when asked).
  void poll_files();
  // What poll_files() does with the files it saw change.
  void reload_files(const std::vector<std::filesystem::path>& changed);
  // The same with the graph file and every shader taken as changed, whether or not the
  // watcher saw it (a write in the clock tick of the last one): a script's "reload".
  void reload_from_disk();
  // Milliseconds since the last change seen on disk, once: the host calls it after the
  // frame that shows the change (nothing when none is pending).
  std::optional<double> take_change_latency_ms();

  [[nodiscard]] bool dirty() const { return scene_.dirty() || graph_.dirty(); }
  bool save();  // atomic, both documents; false (and message()) when it failed
  bool save(DocKind kind);
  void autosave();
  void close();  // a clean end: recovery files go
  // An end nobody confirmed (--frames ran out): unsaved edits are written to recovery
  // files instead of being dropped. Returns a line per document kept that way.
  std::vector<std::string> close_keeping_unsaved();

  // The last load's diagnostics (or a file's that was refused).
  [[nodiscard]] const base::Diagnostics& diagnostics() const { return diagnostics_; }
  [[nodiscard]] const std::string& reload_summary() const { return reload_summary_; }
  // The graph document (as on disk, or as edited) does not compile: the frame is the last
  // good graph's, whose passes the renderer's plan holds, not the document's.
  [[nodiscard]] bool graph_refused() const { return graph_refused_; }
  [[nodiscard]] const std::string& message() const { return message_; }
  void set_message(std::string message) { message_ = std::move(message); }

 private:
  using Clock = std::chrono::steady_clock;
  enum class FileReload { reloaded, kept, refused };

  void note_edit(DocKind kind);
  bool step_history(std::vector<DocKind>& from, std::vector<DocKind>& to, bool back);
  void watch_files();  // (re)baselines the watched set: after loads and our own saves
  void apply_changes(const std::vector<std::filesystem::path>& changed, bool rebuild);
  void reload_scene_file();
  FileReload reload_graph_file();
  void sync_lights();
  void reload_graph();
  std::string reload_timing(Clock::time_point started, const fg::Plan* before) const;

  Renderer& renderer_;
  SceneDocument scene_;
  GraphDocument graph_;
  PassDescLookup lookup_;
  LayerStatus status_;
  // Which document each undo/redo step belongs to, most recent last.
  std::vector<DocKind> undo_order_;
  std::vector<DocKind> redo_order_;
  bool gesture_open_ = false;
  bool gesture_noted_ = false;
  DocKind gesture_kind_ = DocKind::scene;
  std::string view_resource_;
  ViewportCamera camera_{scene::Camera{}};
  scene::Camera scene_camera_;  // as the scene file has it
  float drag_limit_ = 1.0f;
  base::Diagnostics diagnostics_;
  std::string reload_summary_;
  bool graph_refused_ = false;
  std::vector<std::string> edited_shaders_;  // the shader files behind the pending reload
  std::string message_;
  watch::FileWatcher watcher_;
  Clock::time_point last_poll_ = Clock::now();
  double poll_interval_ms_ = kDefaultPollMs;
  std::optional<Clock::time_point> change_seen_;  // a change seen on disk, not yet shown
};

}  // namespace antumbra::editor
