#include "antumbra/editor/edit_session.hpp"

#include <algorithm>
#include <cassert>
#include <cstdio>

#include "antumbra/editor/atomic_file.hpp"
#include "antumbra/editor/recovery_file.hpp"
#include "antumbra/fg/plan_diff.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::editor {
namespace {

// The status line of a file the reload refused: what, the first error where it stands,
// and how many there are, so the artist need not scroll the panel to learn why.
std::string refusal_text(const char* what, const base::Diagnostics& diagnostics) {
  const base::Diagnostic* first = nullptr;
  int errors = 0;
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::error) continue;
    if (first == nullptr) first = &d;
    ++errors;
  }
  std::string text = std::string("the ") + what + " on disk is refused";
  if (first != nullptr) {
    text += " (" + std::to_string(errors) + " error" + (errors == 1 ? "" : "s") +
            "): " + first->code + " " + first->message;
    if (first->line > 0) {
      text += " (" + std::filesystem::path(first->file).filename().string() + ":" +
              std::to_string(first->line) + ":" + std::to_string(first->column) + ")";
    }
  }
  return text + "; the last good " + what + " keeps running";
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

EditSession::EditSession(Renderer& renderer, SceneDocument scene, GraphDocument graph,
                         PassDescLookup lookup, double poll_interval_ms)
    : renderer_(renderer),
      scene_(std::move(scene)),
      graph_(std::move(graph)),
      lookup_(std::move(lookup)),
      poll_interval_ms_(poll_interval_ms) {
}

bool EditSession::start(scene::ImageCache* images) {
  reload_graph();
  reload_summary_ = "none yet";  // the first load is not a reload
  if (diagnostics_.has_errors()) return false;
  auto parsed = scene::parse_scene_text(scene_.to_text(), scene_.file().string(), images,
                                        scene_.file_options());
  if (!parsed.ok()) {
    diagnostics_ = parsed.diagnostics();
    return false;
  }
  scene_camera_ = parsed->camera;
  drag_limit_ = editor::drag_limit(parsed.value());
  status_.set_fix_bounds(parsed->bounds);  // a suggested move keeps lights in the scene
  camera_.reset(scene_camera_);
  renderer_.set_scene(std::move(parsed.value()));
  renderer_.set_camera(camera_.camera());  // what picking and overlays assume
  status_.set_cap(graph_cap());
  status_.update(scene_);
  watch_files();
  return true;
}

void EditSession::watch_files() {
  std::vector<std::filesystem::path> files{scene_.file(), graph_.file()};
  for (const auto& f : renderer_.shader_files()) files.emplace_back(f);
  watcher_ = watch::FileWatcher();
  watcher_.set(files);
}

void EditSession::poll_files() {
  if (ms_since(last_poll_) < poll_interval_ms_) return;
  last_poll_ = Clock::now();
  reload_files(watcher_.poll());
}

void EditSession::reload_files(const std::vector<std::filesystem::path>& changed) {
  apply_changes(changed, false);
}

void EditSession::reload_from_disk() {
  std::vector<std::filesystem::path> changed = watcher_.poll();  // for the summary's list
  if (std::find(changed.begin(), changed.end(), graph_.file()) == changed.end()) {
    changed.push_back(graph_.file());
  }
  apply_changes(changed, true);
}

// One reload for a changed graph file and changed shaders together (`rebuild`: even when
// no shader was seen to change). A graph file that is refused leaves everything as it
// was; the shaders reach the frame with the next reload, which builds every pipeline from
// the files as they are then.
void EditSession::apply_changes(const std::vector<std::filesystem::path>& changed, bool rebuild) {
  if (changed.empty()) return;
  change_seen_ = Clock::now();
  bool graph_changed = false;
  edited_shaders_.clear();
  for (const auto& path : changed) {
    if (path == scene_.file()) {
      reload_scene_file();
    } else if (path == graph_.file()) {
      graph_changed = true;
    } else {
      edited_shaders_.push_back(path.string());
    }
  }
  const FileReload graph = graph_changed ? reload_graph_file() : FileReload::kept;
  if (graph == FileReload::kept && (rebuild || !edited_shaders_.empty())) {
    reload_graph();  // pipelines rebuilt beside the live ones
    message_ = diagnostics_.has_errors()
                   ? "shader change refused: the last good frame keeps running"
                   : "shader change reloaded";
  }
  watch_files();  // the graph's shader set may have changed
}

std::optional<double> EditSession::take_change_latency_ms() {
  if (!change_seen_) return std::nullopt;
  const double ms = ms_since(*change_seen_);
  change_seen_.reset();
  return ms;
}

void EditSession::reload_scene_file() {
  if (scene_.dirty()) {
    message_ = "the scene changed on disk; your unsaved edits are kept";
    return;
  }
  auto loaded = SceneDocument::load(scene_.file(), nullptr, scene_.file_options());
  if (!loaded.ok()) {
    diagnostics_ = loaded.diagnostics();
    message_ = refusal_text("scene", diagnostics_);
    return;
  }
  auto parsed = scene::parse_scene_text(loaded->to_text(), scene_.file().string(), nullptr,
                                        scene_.file_options());
  if (!parsed.ok()) {
    diagnostics_ = parsed.diagnostics();
    message_ = refusal_text("scene", diagnostics_);
    return;
  }
  scene_ = std::move(loaded.value());
  std::erase(undo_order_, DocKind::scene);  // the new document has a fresh history
  std::erase(redo_order_, DocKind::scene);
  gesture_open_ = false;
  scene_camera_ = parsed->camera;
  drag_limit_ = editor::drag_limit(parsed.value());
  status_.set_fix_bounds(parsed->bounds);
  renderer_.set_scene(std::move(parsed.value()));
  renderer_.set_camera(camera_.camera());  // the artist's view stays where it was
  status_.update(scene_);
  message_ = "scene reloaded from disk";
}

EditSession::FileReload EditSession::reload_graph_file() {
  if (graph_.dirty()) {
    message_ = "the graph changed on disk; your unsaved edits are kept";
    return FileReload::kept;
  }
  auto loaded = GraphDocument::load(graph_.file(), lookup_);
  if (!loaded.ok()) {
    diagnostics_ = loaded.diagnostics();
    graph_refused_ = true;
    reload_summary_ = "refused: the last good graph keeps running";
    message_ = refusal_text("graph", diagnostics_);
    return FileReload::refused;
  }
  // The document follows the file even when the compiler refuses it: the artist's text is
  // the truth, and an edit made here must not overwrite it with the old graph.
  graph_ = std::move(loaded.value());
  std::erase(undo_order_, DocKind::graph);
  std::erase(redo_order_, DocKind::graph);
  gesture_open_ = false;
  reload_graph();
  if (graph_refused_) {
    message_ = refusal_text("graph", diagnostics_);
    return FileReload::refused;
  }
  message_ = "graph reloaded from disk";
  return FileReload::reloaded;
}

int EditSession::graph_cap() const {
  return layer_cap(graph_);
}

std::string EditSession::layering_pass() const {
  return editor::layering_pass(graph_);
}

void EditSession::open_gesture(DocKind kind) {
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

void EditSession::end_frame(bool held) {
  if (!gesture_open_ || held) return;
  if (gesture_kind_ == DocKind::scene) {
    scene_.end_gesture();
  } else {
    graph_.end_gesture();
  }
  gesture_open_ = false;
}

void EditSession::note_edit(DocKind kind) {
  const bool in_gesture = gesture_open_ && gesture_kind_ == kind;
  if (in_gesture && gesture_noted_) return;  // the drag's step is already counted
  undo_order_.push_back(kind);
  redo_order_.clear();
  if (in_gesture) gesture_noted_ = true;
}

void EditSession::scene_edited(const EditResult& result) {
  if (!result) {
    message_ = "edit refused: " + result.message;
    return;
  }
  if (!result.changed) return;
  note_edit(DocKind::scene);
  sync_lights();
}

EditResult EditSession::set_param(const std::string& pass, const std::string& name,
                                  const base::Json& value) {
  auto result = graph_.set_param(pass, name, value);
  if (!result) {
    message_ = "edit refused: " + result.message;
    return result;
  }
  if (!result.message.empty()) message_ = result.message;  // e.g. "clamped to 32"
  if (!result.changed) return result;
  note_edit(DocKind::graph);
  reload_graph();
  return result;
}

EditResult EditSession::edit_graph(const std::function<EditResult(GraphDocument&)>& edit) {
  end_frame(false);  // a structural edit is a step of its own, never part of a drag
  auto result = edit(graph_);
  if (!result) {
    message_ = "edit refused: " + result.message;
    return result;
  }
  if (!result.changed) return result;
  note_edit(DocKind::graph);
  reload_graph();
  return result;
}

EditResult EditSession::ask_graph(const std::function<EditResult(GraphDocument&)>& ask) {
  const std::uint64_t before = graph_.revision();
  EditResult answer = ask(graph_);
  assert(graph_.revision() == before && "a question edited the graph");
  (void)before;
  return answer;
}

bool EditSession::undo() {
  return step_history(undo_order_, redo_order_, true);
}

bool EditSession::redo() {
  return step_history(redo_order_, undo_order_, false);
}

// Takes the newest step of `from` (undo or redo order), moves it to `to` and undoes
// (`back`) or redoes it in its document, which then reaches the renderer.
bool EditSession::step_history(std::vector<DocKind>& from, std::vector<DocKind>& to, bool back) {
  if (from.empty()) return false;
  gesture_open_ = false;  // the documents close an open gesture themselves
  const DocKind kind = from.back();
  from.pop_back();
  to.push_back(kind);
  if (kind == DocKind::scene) {
    back ? scene_.undo() : scene_.redo();
    sync_lights();
  } else {
    back ? graph_.undo() : graph_.redo();
    reload_graph();
  }
  // Replaces what the last action said ("saved ..."), which the step made untrue.
  message_ = std::string(back ? "undid" : "redid") + " a " +
             (kind == DocKind::scene ? "scene" : "graph") + " edit";
  return true;
}

// The editor edits lights only, so after the first upload only they are replaced. The
// document's lights are the engine's (overrides of imported lights merged the same way),
// and validated edits keep the file loadable, so the scene (its glTF geometry and images
// above all) is not parsed again on every slider step.
void EditSession::sync_lights() {
  renderer_.set_lights(scene_.lights());
  status_.update(scene_);
}

// A transaction through the one load path: only a fully valid graph replaces the running
// one.
void EditSession::reload_graph() {
  const Clock::time_point started = Clock::now();
  std::optional<fg::Plan> before;
  if (const fg::Plan* live = renderer_.plan()) before = *live;
  diagnostics_ =
      renderer_.load_graph(fg::GraphSource::from_text(graph_.to_text(), graph_.file().string()),
                           [this](fg::GraphDesc& graph) {
                             if (!view_resource_.empty())
                               graph.output = view_resource_;  // like render --output
                           });
  graph_refused_ = diagnostics_.has_errors();
  if (graph_refused_) {
    reload_summary_ = "refused: the last good graph keeps running";
  } else {
    reload_summary_ = reload_timing(started, before ? &*before : nullptr);
    edited_shaders_.clear();
  }
  status_.set_cap(graph_cap());
}

// "reloaded in 4.2 ms: <what changed>" (the first load has nothing to compare with).
std::string EditSession::reload_timing(Clock::time_point started, const fg::Plan* before) const {
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.1f ms", ms_since(started));
  std::string diff_text;
  if (before != nullptr && renderer_.plan() != nullptr) {
    auto diff = fg::diff_plans(*before, *renderer_.plan());
    diff.passes_rebuilt = renderer_.passes_reading(edited_shaders_);
    diff_text = ": " + fg::to_text(diff);
  }
  return std::string("reloaded in ") + ms + diff_text;
}

bool EditSession::resize(fg::Extent2D extent) {
  if (extent.width == 0 || extent.height == 0) return false;
  const fg::Extent2D previous = renderer_.viewport();
  renderer_.set_viewport(extent);
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
  renderer_.set_viewport(previous);
  reload_graph();
  return false;
}

void EditSession::set_view_resource(const std::string& resource) {
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

std::string EditSession::shown_resource() const {
  const fg::Plan* plan = renderer_.plan();
  return plan == nullptr || plan->output < 0
             ? std::string()
             : plan->resources.at(static_cast<std::size_t>(plan->output)).name;
}

void EditSession::set_camera(const ViewportCamera& camera) {
  camera_ = camera;
  renderer_.set_camera(camera_.camera());
}

void EditSession::reset_camera() {
  camera_.reset(scene_camera_);
  renderer_.set_camera(camera_.camera());
}

bool EditSession::save() {
  if (!save(DocKind::scene) || !save(DocKind::graph)) return false;
  message_ =
      "saved " + scene_.file().filename().string() + " and " + graph_.file().filename().string();
  return true;
}

bool EditSession::save(DocKind kind) {
  try {
    if (kind == DocKind::scene && scene_.dirty()) scene_.save();
    if (kind == DocKind::graph && graph_.dirty()) graph_.save();
    watch_files();  // our own writes are not changes to reload
    message_ =
        "saved " + (kind == DocKind::scene ? scene_.file() : graph_.file()).filename().string();
    return true;
  } catch (const SaveError& e) {
    message_ = std::string("save failed: ") + e.what();
    return false;
  }
}

void EditSession::autosave() {
  const auto now = RecoveryFile::Clock::now();
  try {
    scene_.autosave_if_due(now);
    graph_.autosave_if_due(now);
  } catch (const SaveError& e) {
    message_ = std::string("recovery file: ") + e.what();
  }
}

void EditSession::close() {
  scene_.close();
  graph_.close();
}

std::vector<std::string> EditSession::close_keeping_unsaved() {
  std::vector<std::string> kept;
  // Far enough ahead that the autosave interval has passed: the write happens now.
  const auto later = RecoveryFile::Clock::now() + std::chrono::hours(24);
  const auto keep = [&](auto& document) {
    if (!document.dirty()) {
      document.close();
      return;
    }
    document.autosave_if_due(later);
    kept.push_back("unsaved changes to " + document.file().string() + " were not saved; kept in " +
                   RecoveryFile::path_for(document.file()).string() +
                   " (the editor offers them when it opens the file)");
  };
  keep(scene_);
  keep(graph_);
  return kept;
}

}  // namespace antumbra::editor
