#include "antumbra/editor_app/windowed_editor.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/exit_codes.hpp"
#include "antumbra/runtime/load_progress.hpp"
#include "editor_state.hpp"
#include "imgui_layer.hpp"
#include "layout_view.hpp"
#include "node_view_panel.hpp"
#include "panels.hpp"
#include "presenter.hpp"
#include "viewport_view.hpp"
#include "window.hpp"

namespace antumbra::editor_app {
namespace {

namespace fs = std::filesystem;

constexpr int kTimingWindowFrames = 30;  // per-pass GPU times: medians over this many

std::string window_title(const EditorState& state, const fs::path& scene, const fs::path& graph) {
  return std::string(state.dirty() ? "* " : "") + "antumbra edit - " + scene.filename().string() +
         ", " + graph.filename().string();
}

// Ctrl+Z, Ctrl+Shift+Z, Ctrl+S; Ctrl+Q closes like the window's close button (with the
// prompt when there are unsaved changes); F2 opens or closes the node view. A text field
// that has the keyboard keeps its own undo.
void handle_shortcuts(EditorState& state, const std::vector<KeyPress>& presses, Window& window,
                      LayoutView& layout) {
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& press : presses) {
    if (press.key == GLFW_KEY_F2 && press.mods == 0) layout.toggle_node_view();
    if ((press.mods & GLFW_MOD_CONTROL) == 0) continue;
    if (press.key == GLFW_KEY_Z) {
      if ((press.mods & GLFW_MOD_SHIFT) != 0) {
        state.redo();
      } else {
        state.undo();
      }
    } else if (press.key == GLFW_KEY_S) {
      state.save();
    } else if (press.key == GLFW_KEY_Q) {
      window.set_should_close(true);  // seen at the top of the next frame
    }
  }
}

// The status bar: the layout's bottom strip, under the viewport and the column.
void draw_status_bar(EditorState& state, const editor::Rect& rect, LayoutView& layout) {
  if (rect.empty()) return;
  ImGui::SetNextWindowPos({rect.x, rect.y});
  ImGui::SetNextWindowSize({rect.width, rect.height});
  // Less padding above and below than ImGui's: one line fits the bar's smallest height.
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {style.WindowPadding.x, style.FramePadding.y});
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PopStyleVar();
  ImGui::BeginDisabled(!state.can_undo());
  if (ImGui::SmallButton("Undo")) state.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!state.can_redo());
  if (ImGui::SmallButton("Redo")) state.redo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::SmallButton("Save")) state.save();
  ImGui::SameLine();
  if (ImGui::SmallButton(layout.node_view_open() ? "Hide nodes (F2)" : "Nodes (F2)")) {
    layout.toggle_node_view();
  }
  ImGui::SameLine();
  ImGui::Text("%s %s", state.dirty() ? "unsaved changes." : "",
              state.drag_note().empty() ? state.message().c_str() : state.drag_note().c_str());
  ImGui::End();
}

glm::ivec2 size_of(VkExtent2D extent) {
  return {static_cast<int>(extent.width), static_cast<int>(extent.height)};
}

VkExtent2D extent_of(const editor::PixelRect& rect) {
  return {static_cast<std::uint32_t>(rect.width), static_cast<std::uint32_t>(rect.height)};
}

// The graph follows the viewport's size (the window's less the panels) once it has
// stopped changing for a moment, so a drag of the window's border or of a splitter
// reallocates the graph's images once, not every frame; meanwhile the image is fitted
// into the viewport. A size that failed is not retried until the size changes again.
struct PendingResize {
  VkExtent2D extent{0, 0};
  VkExtent2D failed{0, 0};
  gpu::CpuTimer since;
};

bool same(VkExtent2D a, VkExtent2D b) {
  return a.width == b.width && a.height == b.height;
}

void follow_window_size(EditorState& state, VkExtent2D window, PendingResize& pending) {
  constexpr double kSettleMs = 250.0;
  if (same(window, state.session().viewport()) || same(window, pending.failed)) return;
  if (!same(window, pending.extent)) {
    pending.extent = window;
    pending.since.restart();
    return;
  }
  if (pending.since.elapsed_ms() < kSettleMs) return;
  if (state.resize({window.width, window.height})) {
    pending.failed = {0, 0};
    std::printf("editor: graph resized to %ux%u (%s)\n", window.width, window.height,
                state.reload_summary().c_str());
  } else {
    pending.failed = window;
    std::printf("editor: %s\n", state.message().c_str());
  }
  std::fflush(stdout);
}

enum class CloseChoice { none, close, cancel };

// The prompt on closing with unsaved changes: Save / Discard / Cancel.
CloseChoice draw_close_prompt(EditorState& state, bool open_now) {
  constexpr const char* kTitle = "Unsaved changes";
  if (open_now) ImGui::OpenPopup(kTitle);
  CloseChoice choice = CloseChoice::none;
  if (ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The scene or the graph has unsaved changes.");
    if (ImGui::Button("Save")) {
      if (state.save()) choice = CloseChoice::close;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) choice = CloseChoice::close;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) choice = CloseChoice::cancel;
    if (choice != CloseChoice::none) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return choice;
}

struct Documents {
  editor::SceneDocument scene;
  editor::GraphDocument graph;
  // Images decoded while opening the scene, so that the renderer's own load of it does
  // not decode them again (a large model's textures are most of its load time).
  std::unique_ptr<scene::ImageCache> images;
};

// `registry` must outlive the documents: the graph's lookup reads its reflection.
std::optional<Documents> load_documents(const WindowedOptions& options,
                                        const fgvk::PassRegistry& registry) {
  const runtime::DataPaths paths = runtime::find_data_paths();
  const fs::path graph_path =
      options.graph.empty() ? paths.graphs() / "layered-ssss.json" : fs::path(options.graph);
  const fs::path scene_path =
      options.scene.empty() ? paths.scenes() / "atrium.json" : fs::path(options.scene);
  auto images = std::make_unique<scene::ImageCache>();
  runtime::LoadProgressPrinter progress;
  images->set_progress(progress.sink());
  auto scene = editor::SceneDocument::open(scene_path, images.get(),
                                           {.allow_outside_paths = options.allow_outside_paths});
  progress.finish();
  images->set_progress({});
  auto graph = editor::GraphDocument::load(graph_path, editor::lookup_in(registry.reflection()));
  print_diagnostics(scene.diagnostics());
  print_diagnostics(graph.diagnostics());
  if (!scene.ok() || !graph.ok()) return std::nullopt;
  if (scene->recovery_available() || graph->recovery_available()) {
    std::printf("note: a recovery file with unsaved edits exists beside the scene or graph\n");
  }
  return Documents{std::move(scene.value()), std::move(graph.value()), std::move(images)};
}

// False (after saying why) when no window can be opened, e.g. without a display.
bool open_window(const WindowedOptions& options, std::optional<Window>& window) {
  try {
    window.emplace(static_cast<int>(options.width), static_cast<int>(options.height),
                   "antumbra edit");
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "antumbra edit: %s (without a display, use --headless)\n", e.what());
    return false;
  }
  return true;
}

// The session's options but the window's (its surface extensions, the viewport).
runtime::SessionOptions session_options_for(const WindowedOptions& options) {
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.present = true;
  session_options.shader_dirs = options.shader_dirs;
  session_options.register_passes = options.register_passes;
  return session_options;
}

// --select: false (after saying why) when the scene has no light of that name.
bool select_light(EditorState& state, const std::string& name) {
  const int light = state.scene().find_light(name);
  if (light < 0) {
    std::fprintf(stderr, "antumbra edit: --select: the scene has no light named '%s'\n",
                 name.c_str());
    return false;
  }
  state.scene().select(light);
  return true;
}

// The editor's frames, from the window's first frame until it closes or --frames were
// presented. Everything it refers to outlives it.
class FrameLoop {
 public:
  FrameLoop(const WindowedOptions& options, Window& window, runtime::RenderSession& session,
            Presenter& presenter, ImguiLayer& ui, LayoutView& layout, EditorState& state,
            fs::path scene_file, fs::path graph_file)
      : options_(options),
        window_(window),
        session_(session),
        presenter_(presenter),
        ui_(ui),
        layout_(layout),
        state_(state),
        scene_file_(std::move(scene_file)),
        graph_file_(std::move(graph_file)) {
    state_.set_log_targets(options.frame_log);
  }

  void run() {
    while (!quit_) {
      window_.poll_events();
      const bool close_requested = window_.should_close();
      if (close_requested) {
        window_.set_should_close(false);
        if (!state_.dirty()) break;
        prompt_ = true;  // ask first; the modal decides
      }
      if (!presenter_.ready()) {
        wait_while_minimised();
        continue;
      }
      if (paused_) std::printf("editor: window restored, rendering resumed\n");
      paused_ = false;
      follow_content_scale();
      gpu::CpuTimer frame_clock;
      build_ui(close_requested);
      follow_window_size(state_, extent_of(layout_.viewport_pixels()), resize_);
      render_and_present(frame_clock);
      finish_frame();
    }
  }

  [[nodiscard]] int presented() const { return presented_; }
  // Where the last frame put the graph's image (framebuffer pixels).
  [[nodiscard]] editor::PixelRect shown_rect() const {
    const fgvk::BoundImage* shown = session_.executor().image(state_.shown_resource());
    const VkExtent2D extent = shown != nullptr ? shown->extent : session_.viewport();
    return editor::fit_image(size_of(extent), layout_.viewport_pixels());
  }
  [[nodiscard]] bool presented_all_frames() const {
    return options_.frames > 0 && presented_ >= options_.frames;
  }
  // UI + edits + render + present, per presented frame.
  [[nodiscard]] const std::vector<double>& frame_ms() const { return frame_ms_; }

 private:
  void wait_while_minimised() {
    if (!paused_) std::printf("editor: window minimised, rendering paused\n");
    paused_ = true;
    window_.wait_events();  // nothing to draw until it is restored
  }

  // A window moved to a screen of another density: the UI follows (not under --ui-scale).
  void follow_content_scale() {
    if (!window_.take_content_scale_change() || options_.ui_scale > 0.0f) return;
    const float scale = window_.content_scale();
    if (scale == ui_.scale()) return;
    ui_.set_scale(scale);
    layout_.set_scale(scale);
    std::printf("editor: UI scale %.2f\n", scale);
  }

  void build_ui(bool close_requested) {
    ui_.begin_frame(window_);
    layout_.begin_frame();
    const std::vector<KeyPress> presses = window_.take_key_presses();
    handle_shortcuts(state_, presses, window_, layout_);
    for (const KeyPress& press : presses) shot_requested_ |= press.key == GLFW_KEY_F12;
    update_viewport(presses);
    draw_lights_panel(state_, layout_.slot(editor::Panel::lights));
    draw_layers_panel(state_, layout_.slot(editor::Panel::layers));
    draw_graph_panel(state_, layout_.slot(editor::Panel::graph));
    draw_node_view();
    draw_status_bar(state_, layout_.layout().status, layout_);
    switch (draw_close_prompt(state_, close_requested && prompt_)) {
      case CloseChoice::close:
        quit_ = true;
        break;
      case CloseChoice::cancel:
        prompt_ = false;
        break;
      case CloseChoice::none:
        break;
    }
    state_.end_frame(ImGui::IsAnyItemActive() || viewport_.dragging());
    layout_.end_frame();
    ui_.end_frame();
  }

  // The node view fills its strip below the strip's splitter.
  void draw_node_view() {
    const editor::EditorLayout& l = layout_.layout();
    if (l.node_view.empty()) return;
    const float grab = l.node_view_handle.height;
    node_view_.draw(state_, {l.node_view.x, l.node_view.y + grab, l.node_view.width,
                             l.node_view.height - grab});
  }

  void update_viewport(const std::vector<KeyPress>& presses) {
    const fgvk::BoundImage* shown = session_.executor().image(state_.shown_resource());
    const VkExtent2D view = session_.viewport();
    const VkExtent2D shown_extent = shown != nullptr ? shown->extent : view;
    viewport_.update(state_, presses, size_of(view), size_of(shown_extent),
                     layout_.viewport_pixels());
  }

  void render_and_present(const gpu::CpuTimer& frame_clock) {
    const bool last = options_.frames > 0 && presented_ + 1 >= options_.frames;
    // Under a graphics debugger (RenderDoc) the last of --frames is captured whole: graph,
    // UI and present, with no key to press in the window.
    if (last) session_.gpu().begin_debugger_capture();
    session_.render(1, nullptr);
    // The window as presented where the swapchain can be read, else the graph's image.
    const bool from_window = presenter_.swapchain().readable();
    const fgvk::BoundImage* shown = session_.executor().image(state_.shown_resource());
    if (presenter_.present(
            shown, layout_.viewport_pixels(), [&](VkCommandBuffer cmd) { ui_.draw(cmd); },
            last && from_window ? options_.screenshot : take_shot())) {
      if (last && !from_window && !options_.screenshot.empty()) {
        session_.write_image(state_.shown_resource(), options_.screenshot);
      }
      ++presented_;
      frame_ms_.push_back(frame_clock.elapsed_ms());
      state_.frame_presented();
      if (presented_ == 1) std::printf("editor: first frame presented\n");
      if (options_.frame_log) std::printf("editor: frame %d\n", presented_);
      // Scripts that drive the window wait for these lines.
      if (presented_ == 1 || options_.frame_log) std::fflush(stdout);
    }
    if (last) session_.gpu().end_debugger_capture();
  }

  // F12 (with --shots): the next presented frame is written to the shots folder.
  std::string take_shot() {
    if (!shot_requested_ || options_.shots.empty()) return {};
    shot_requested_ = false;
    std::string path = options_.shots + "/shot-" + std::to_string(++shots_) + ".png";
    std::printf("editor: screenshot %s\n", path.c_str());
    return path;
  }

  void finish_frame() {
    state_.autosave();
    state_.poll_files();
    if (presented_ % kTimingWindowFrames == 5) state_.refresh_timings();  // first after warm-up
    if (const auto now = window_title(state_, scene_file_, graph_file_); now != title_) {
      title_ = now;
      window_.set_title(title_);
    }
    if (presented_all_frames()) quit_ = true;
  }

  const WindowedOptions& options_;
  Window& window_;
  runtime::RenderSession& session_;
  Presenter& presenter_;
  ImguiLayer& ui_;
  LayoutView& layout_;
  NodeViewPanel node_view_{options_.frame_log};
  bool shot_requested_ = false;
  int shots_ = 0;
  EditorState& state_;
  fs::path scene_file_;
  fs::path graph_file_;
  ViewportView viewport_;
  PendingResize resize_;
  std::string title_;
  int presented_ = 0;
  bool prompt_ = false;
  bool quit_ = false;
  bool paused_ = false;
  std::vector<double> frame_ms_;
};

// A run that stopped after --frames keeps unsaved edits for a later session (and says
// so); a run the user closed has already decided about them in the prompt.
void close_documents(EditorState& state, const FrameLoop& loop) {
  if (loop.presented_all_frames()) {
    for (const auto& line : state.close_keeping_unsaved()) {
      std::printf("editor: warning: %s\n", line.c_str());
    }
  } else {
    state.close();
  }
}

// The device is gone, the documents are not (docs/robustness.md, "Device loss"): unsaved
// edits go to recovery files, which the editor offers when it opens the files again; the
// window closes.
int keep_work_after_device_loss(EditorState& state, const std::exception& e) {
  std::fprintf(stderr, "editor: error: %s\n", e.what());
  const std::vector<std::string> kept = state.close_keeping_unsaved();
  for (const auto& line : kept) std::fprintf(stderr, "editor: %s\n", line.c_str());
  if (kept.empty()) std::fprintf(stderr, "editor: there were no unsaved changes\n");
  return runtime::kExitRuntime;
}

void print_summary(runtime::RenderSession& session, const Presenter& presenter,
                   const FrameLoop& loop, const WindowedOptions& options) {
  std::printf("editor: %d frame(s) presented, %u swapchain rebuild(s)\n", loop.presented(),
              presenter.recreations());
  std::vector<double> frame_ms = loop.frame_ms();
  if (!frame_ms.empty()) {
    std::sort(frame_ms.begin(), frame_ms.end());
    std::printf("editor frame (%ux%u graph): %.2f ms wall median (UI + render + present)\n",
                session.viewport().width, session.viewport().height, frame_ms[frame_ms.size() / 2]);
  }
  if (!options.screenshot.empty() && loop.presented_all_frames()) {
    std::printf("screenshot: %s\n", options.screenshot.c_str());
  }
}

}  // namespace

int run_windowed_editor(const WindowedOptions& options) {
  runtime::SessionOptions session_options = session_options_for(options);
  // The pass types the session runs (built-in and the host's): the documents, read before
  // the device starts, take their parameters' reflection from the same registration.
  const fgvk::PassRegistry registry = runtime::pass_registry(session_options);
  auto documents = load_documents(options, registry);
  if (!documents) return runtime::kExitDiagnostics;
  const fs::path scene_file = documents->scene.file();
  const fs::path graph_file = documents->graph.file();

  std::optional<Window> window;
  if (!open_window(options, window)) return runtime::kExitRuntime;
  LayoutView layout({options.layout_file, options.ui_scale}, *window);
  session_options.instance_extensions = window->required_instance_extensions();
  session_options.viewport = layout.initial_viewport(*window);
  runtime::RenderSession session(runtime::find_data_paths(), session_options);
  std::printf("device: %s%s\n", session.gpu().device_name().c_str(),
              options.validation ? " (validation + synchronization validation on)" : "");

  // Declared after the session, so destroyed before its device and instance.
  Surface surface(session.gpu().instance(), *window);
  Presenter presenter(session.gpu(), *window, surface.handle());
  ImguiLayer ui(session.gpu(), *window, presenter.swapchain(), layout.scale());
  layout.restore_imgui_state();
  SessionRenderer renderer(session);
  EditorState state(renderer, std::move(documents->scene), std::move(documents->graph),
                    editor::lookup_in(session.pass_registry().reflection()));
  const bool started = state.start(documents->images.get());
  print_diagnostics(state.diagnostics());
  if (!started) return runtime::kExitDiagnostics;
  documents->images.reset();  // the scene holds the images it uses; the rest can go
  if (!options.select.empty() && !select_light(state, options.select)) {
    return runtime::kExitUsage;
  }

  FrameLoop loop(options, *window, session, presenter, ui, layout, state, scene_file, graph_file);
  try {
    loop.run();
  } catch (const std::exception& e) {
    if (!session.gpu().device_lost()) throw;
    return keep_work_after_device_loss(state, e);
  }
  layout.save();
  if (!options.layout_report.empty() && loop.presented() > 0 &&
      !layout.write_report(options.layout_report, session.viewport(), loop.shown_rect())) {
    return runtime::kExitRuntime;
  }
  close_documents(state, loop);
  session.gpu().wait_idle();
  print_summary(session, presenter, loop, options);
  if (options.validation) {
    const std::size_t errors = session.gpu().validation_error_count();
    std::printf("validation: %zu error(s), %zu warning(s)\n", errors,
                session.gpu().validation_warning_count());
    if (errors > 0) return runtime::kExitDiagnostics;
  }
  return runtime::kExitOk;
}

}  // namespace antumbra::editor_app
