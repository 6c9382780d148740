#include "editor_state.hpp"

#include <chrono>
#include <cstdio>

#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/atomic_file.hpp"
#include "antumbra/editor/recovery_file.hpp"
#include "antumbra/fg/plan_diff.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::editor_app {

EditorState::EditorState(runtime::RenderSession& session, editor::SceneDocument scene,
                         editor::GraphDocument graph, editor::PassDescLookup lookup,
                         double poll_interval_ms)
    : session_(session),
      scene_(std::move(scene)),
      graph_(std::move(graph)),
      lookup_(std::move(lookup)),
      poll_interval_ms_(poll_interval_ms) {
}

bool EditorState::start(scene::ImageCache* images) {
  reload_graph();
  reload_summary_ = "none yet";  // the first load is not a reload
  for (const auto& d : diagnostics_) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
  if (diagnostics_.has_errors()) return false;
  auto parsed = scene::parse_scene_text(scene_.to_text(), scene_.file().string(), images);
  if (!parsed.ok()) {
    for (const auto& d : parsed.diagnostics()) std::printf("  %s\n", base::format_text(d).c_str());
    return false;
  }
  scene_camera_ = parsed->camera;
  drag_limit_ = editor::drag_limit(parsed.value());
  camera_.reset(scene_camera_);
  session_.set_scene(std::move(parsed.value()));
  session_.set_camera(camera_.camera());  // what picking and overlays assume
  status_.set_cap(graph_cap());
  status_.update(scene_);
  watch_files();
  return true;
}

void EditorState::watch_files() {
  std::vector<std::filesystem::path> files{scene_.file(), graph_.file()};
  for (const auto& f : session_.executor().shader_files()) files.emplace_back(f);
  watcher_ = watch::FileWatcher();
  watcher_.set(files);
}

void EditorState::poll_files() {
  if (since_poll_.elapsed_ms() < poll_interval_ms_) return;
  since_poll_.restart();
  const auto changed = watcher_.poll();
  if (changed.empty()) return;
  since_change_.emplace();
  bool shaders = false;
  edited_shaders_.clear();
  for (const auto& path : changed) {
    if (path == scene_.file()) {
      reload_scene_file();
    } else if (path == graph_.file()) {
      reload_graph_file();
    } else {
      shaders = true;
      edited_shaders_.push_back(path.string());
    }
  }
  if (shaders) {
    reload_graph();  // pipelines rebuilt beside the live ones
    message_ = diagnostics_.has_errors()
                   ? "shader change refused: the last good frame keeps running"
                   : "shader change reloaded";
  }
  watch_files();  // the graph's shader set may have changed
}

void EditorState::frame_presented() {
  if (!since_change_) return;
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.1f ms", since_change_->elapsed_ms());
  since_change_.reset();
  message_ += std::string(" (file seen -> new frame ") + ms + ")";
  std::printf("editor: %s; graph: %s\n", message_.c_str(), reload_summary_.c_str());
  for (const auto& d : diagnostics_) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
  // What the new frame's passes report (a layer cap that is still too low) is said again
  // after every reload, not only the first time it appeared.
  for (const auto& d : session_.frame_diagnostics()) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
  std::fflush(stdout);
}

void EditorState::reload_scene_file() {
  if (scene_.dirty()) {
    message_ = "the scene changed on disk; your unsaved edits are kept";
    return;
  }
  auto loaded = editor::SceneDocument::load(scene_.file());
  if (!loaded.ok()) {
    diagnostics_ = loaded.diagnostics();
    message_ = "the scene on disk does not load; the last good scene keeps running";
    return;
  }
  auto parsed = scene::parse_scene_text(loaded->to_text(), scene_.file().string());
  if (!parsed.ok()) {
    diagnostics_ = parsed.diagnostics();
    message_ = "the scene on disk does not parse; the last good scene keeps running";
    return;
  }
  scene_ = std::move(loaded.value());
  std::erase(undo_order_, DocKind::scene);  // the new document has a fresh history
  std::erase(redo_order_, DocKind::scene);
  gesture_open_ = false;
  scene_camera_ = parsed->camera;
  drag_limit_ = editor::drag_limit(parsed.value());
  session_.set_scene(std::move(parsed.value()));
  session_.set_camera(camera_.camera());  // the artist's view stays where it was
  status_.update(scene_);
  message_ = "scene reloaded from disk";
}

void EditorState::reload_graph_file() {
  if (graph_.dirty()) {
    message_ = "the graph changed on disk; your unsaved edits are kept";
    return;
  }
  auto loaded = editor::GraphDocument::load(graph_.file(), lookup_);
  if (!loaded.ok()) {
    diagnostics_ = loaded.diagnostics();
    reload_summary_ = "refused: the last good graph keeps running";
    message_ = "the graph on disk does not load; the last good graph keeps running";
    return;
  }
  graph_ = std::move(loaded.value());
  std::erase(undo_order_, DocKind::graph);
  std::erase(redo_order_, DocKind::graph);
  gesture_open_ = false;
  reload_graph();
  message_ = "graph reloaded from disk";
}

int EditorState::graph_cap() const {
  return editor::layer_cap(graph_);
}

std::string EditorState::layering_pass() const {
  return editor::layering_pass(graph_);
}

void EditorState::open_gesture(DocKind kind) {
  end_frame(false);
  if (kind == DocKind::scene) {
    scene_.begin_gesture();
  } else {
    graph_.begin_gesture();
  }
  gesture_open_ = true;
  gesture_noted_ = false;
  gesture_kind_ = kind;
}

void EditorState::end_frame(bool held) {
  if (!gesture_open_ || held) return;
  if (gesture_kind_ == DocKind::scene) {
    scene_.end_gesture();
  } else {
    graph_.end_gesture();
  }
  gesture_open_ = false;
}

void EditorState::note_edit(DocKind kind) {
  const bool in_gesture = gesture_open_ && gesture_kind_ == kind;
  if (in_gesture && gesture_noted_) return;  // the drag's step is already counted
  undo_order_.push_back(kind);
  redo_order_.clear();
  if (in_gesture) gesture_noted_ = true;
}

void EditorState::scene_edited(const editor::EditResult& result) {
  if (!result) {
    message_ = "edit refused: " + result.message;
    return;
  }
  if (!result.changed) return;
  note_edit(DocKind::scene);
  sync_lights();
}

void EditorState::set_param(const std::string& pass, const std::string& name,
                            const base::Json& value) {
  const auto result = graph_.set_param(pass, name, value);
  if (!result) {
    message_ = "edit refused: " + result.message;
    return;
  }
  if (!result.message.empty()) message_ = result.message;  // e.g. "clamped to 32"
  if (!result.changed) return;
  note_edit(DocKind::graph);
  reload_graph();
}

void EditorState::undo() {
  if (undo_order_.empty()) return;
  gesture_open_ = false;  // the documents close an open gesture themselves
  const DocKind kind = undo_order_.back();
  undo_order_.pop_back();
  redo_order_.push_back(kind);
  if (kind == DocKind::scene) {
    scene_.undo();
    sync_lights();
  } else {
    graph_.undo();
    reload_graph();
  }
}

void EditorState::redo() {
  if (redo_order_.empty()) return;
  gesture_open_ = false;
  const DocKind kind = redo_order_.back();
  redo_order_.pop_back();
  undo_order_.push_back(kind);
  if (kind == DocKind::scene) {
    scene_.redo();
    sync_lights();
  } else {
    graph_.redo();
    reload_graph();
  }
}

// The editor edits lights only, so after the first upload only they are replaced. The
// document's lights are the engine's (overrides of imported lights merged the same way),
// and validated edits keep the file loadable, so the scene (its glTF geometry and images
// above all) is not parsed again on every slider step.
void EditorState::sync_lights() {
  session_.set_lights(scene_.lights());
  status_.update(scene_);
}

// A transaction: only a fully valid graph replaces the running one.
void EditorState::reload_graph() {
  gpu::CpuTimer clock;
  const bool had_plan = session_.executor().loaded();
  fg::Plan before;
  if (had_plan) before = session_.executor().plan();
  auto document = base::parse_json(graph_.to_text(), graph_.file().string());
  if (!document.ok()) {
    diagnostics_ = document.diagnostics();
  } else if (auto graph = fg::parse_graph(document.value()); !graph.ok()) {
    diagnostics_ = graph.diagnostics();
  } else {
    if (!view_resource_.empty()) graph->output = view_resource_;  // like render --output
    diagnostics_ = session_.load_graph(graph.value());
  }
  if (diagnostics_.has_errors()) {
    reload_summary_ = "refused: the last good graph keeps running";
  } else {
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.1f ms", clock.elapsed_ms());
    std::string diff_text;
    if (had_plan) {
      auto diff = fg::diff_plans(before, session_.executor().plan());
      diff.passes_rebuilt = session_.executor().passes_reading(edited_shaders_);
      diff_text = ": " + fg::to_text(diff);
    }
    reload_summary_ = std::string("reloaded in ") + ms + diff_text;
    edited_shaders_.clear();
  }
  status_.set_cap(graph_cap());
}

bool EditorState::resize(VkExtent2D extent) {
  if (extent.width == 0 || extent.height == 0) return false;
  const VkExtent2D previous = session_.viewport();
  session_.set_viewport(extent);
  reload_graph();
  if (!diagnostics_.has_errors()) return true;
  // Whatever refused it (a device limit, a shader broken on disk meanwhile): say it.
  std::string why = "unknown";
  for (const auto& d : diagnostics_) {
    if (d.severity == base::Severity::error) {
      why = base::format_text(d);
      break;
    }
  }
  message_ = "cannot render at " + std::to_string(extent.width) + "x" +
             std::to_string(extent.height) + " (" + why + "); the graph stays at its size";
  session_.set_viewport(previous);
  reload_graph();
  return false;
}

void EditorState::set_view_resource(const std::string& resource) {
  if (resource == view_resource_) return;
  const std::string previous = view_resource_;
  view_resource_ = resource;
  reload_graph();
  if (diagnostics_.has_errors()) {
    view_resource_ = previous;
    message_ = "cannot show '" + resource + "'";
    reload_graph();
  }
}

std::string EditorState::shown_resource() const {
  const auto& plan = session_.executor().plan();
  return plan.output < 0 ? std::string()
                         : plan.resources.at(static_cast<std::size_t>(plan.output)).name;
}

void EditorState::set_camera(const editor::ViewportCamera& camera) {
  camera_ = camera;
  session_.set_camera(camera_.camera());
}

void EditorState::reset_camera() {
  camera_.reset(scene_camera_);
  session_.set_camera(camera_.camera());
}

bool EditorState::save() {
  try {
    if (scene_.dirty()) scene_.save();
    if (graph_.dirty()) graph_.save();
    watch_files();  // our own writes are not changes to reload
    message_ =
        "saved " + scene_.file().filename().string() + " and " + graph_.file().filename().string();
    return true;
  } catch (const editor::SaveError& e) {
    message_ = std::string("save failed: ") + e.what();
    return false;
  }
}

void EditorState::autosave() {
  const auto now = editor::RecoveryFile::Clock::now();
  try {
    scene_.autosave_if_due(now);
    graph_.autosave_if_due(now);
  } catch (const editor::SaveError& e) {
    message_ = std::string("recovery file: ") + e.what();
  }
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

void EditorState::close() {
  scene_.close();
  graph_.close();
}

std::vector<std::string> EditorState::close_keeping_unsaved() {
  std::vector<std::string> kept;
  // Far enough ahead that the autosave interval has passed: the write happens now.
  const auto later = editor::RecoveryFile::Clock::now() + std::chrono::hours(24);
  const auto keep = [&](auto& document) {
    if (!document.dirty()) {
      document.close();
      return;
    }
    document.autosave_if_due(later);
    kept.push_back("unsaved changes to " + document.file().string() + " were not saved; kept in " +
                   editor::RecoveryFile::path_for(document.file()).string() +
                   " (the editor offers them when it opens the file)");
  };
  keep(scene_);
  keep(graph_);
  return kept;
}

}  // namespace antumbra::editor_app
