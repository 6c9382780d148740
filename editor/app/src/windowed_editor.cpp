#include "antumbra/editor_app/windowed_editor.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
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
#include "editor_state.hpp"
#include "imgui_layer.hpp"
#include "panels.hpp"
#include "presenter.hpp"
#include "register_builtin_passes.hpp"
#include "viewport_view.hpp"
#include "window.hpp"

namespace antumbra::editor_app {
namespace {

namespace fs = std::filesystem;

constexpr int kTimingWindowFrames = 30;  // per-pass GPU times: medians over this many

void print(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
}

std::string window_title(const EditorState& state, const fs::path& scene, const fs::path& graph) {
  return std::string(state.dirty() ? "* " : "") + "antumbra edit - " + scene.filename().string() +
         ", " + graph.filename().string();
}

// Ctrl+Z, Ctrl+Shift+Z, Ctrl+S; Ctrl+Q closes like the window's close button (with the
// prompt when there are unsaved changes). A text field that has the keyboard keeps its
// own undo.
void handle_shortcuts(EditorState& state, const std::vector<KeyPress>& presses, Window& window) {
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& press : presses) {
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

void draw_status_bar(EditorState& state) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->Pos.x, viewport->Pos.y + viewport->Size.y - 26});
  ImGui::SetNextWindowSize({viewport->Size.x, 26});
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
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
  ImGui::Text("%s %s", state.dirty() ? "unsaved changes." : "",
              state.drag_note().empty() ? state.message().c_str() : state.drag_note().c_str());
  ImGui::End();
}

glm::ivec2 size_of(VkExtent2D extent) {
  return {static_cast<int>(extent.width), static_cast<int>(extent.height)};
}

// The graph follows the window's size once it has stopped changing for a moment, so a
// drag of the window's border reallocates the graph's images once, not every frame. A
// size that failed is not retried until the window's size changes again.
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
  if (state.resize(window)) {
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
};

// `registry` must outlive the documents: the graph's lookup reads its reflection.
std::optional<Documents> load_documents(const WindowedOptions& options,
                                        const fgvk::PassRegistry& registry) {
  const runtime::DataPaths paths = runtime::find_data_paths();
  const fs::path graph_path =
      options.graph.empty() ? paths.graphs() / "layered-ssss.json" : fs::path(options.graph);
  const fs::path scene_path =
      options.scene.empty() ? paths.scenes() / "atrium.json" : fs::path(options.scene);
  auto scene = editor::SceneDocument::load(scene_path);
  auto graph = editor::GraphDocument::load(graph_path, editor::lookup_in(registry.reflection()));
  print(scene.diagnostics());
  print(graph.diagnostics());
  if (!scene.ok() || !graph.ok()) return std::nullopt;
  if (scene->recovery_available() || graph->recovery_available()) {
    std::printf("note: a recovery file with unsaved edits exists beside the scene or graph\n");
  }
  return Documents{std::move(scene.value()), std::move(graph.value())};
}

}  // namespace

int run_windowed_editor(const WindowedOptions& options) {
  const fgvk::PassRegistry registry = passes::builtin_pass_registry();
  auto documents = load_documents(options, registry);
  if (!documents) return runtime::kExitDiagnostics;
  const fs::path scene_file = documents->scene.file();
  const fs::path graph_file = documents->graph.file();

  std::optional<Window> window;
  try {
    window.emplace(static_cast<int>(options.width), static_cast<int>(options.height),
                   "antumbra edit");
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "antumbra edit: %s (without a display, use --headless)\n", e.what());
    return runtime::kExitRuntime;
  }
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.viewport = {options.width, options.height};
  session_options.instance_extensions = window->required_instance_extensions();
  session_options.present = true;
  runtime::RenderSession session(runtime::find_data_paths(), session_options);
  std::printf("device: %s%s\n", session.gpu().device_name().c_str(),
              options.validation ? " (validation + synchronization validation on)" : "");

  // Declared after the session, so destroyed before its device and instance.
  Surface surface(session.gpu().instance(), *window);
  Presenter presenter(session.gpu(), *window, surface.handle());
  ImguiLayer ui(session.gpu(), *window, presenter.swapchain());
  EditorState state(session, std::move(documents->scene), std::move(documents->graph),
                    editor::lookup_in(registry.reflection()));
  if (!state.start()) return runtime::kExitDiagnostics;
  if (!options.select.empty()) {
    const int light = state.scene().find_light(options.select);
    if (light < 0) {
      std::fprintf(stderr, "antumbra edit: --select: the scene has no light named '%s'\n",
                   options.select.c_str());
      return runtime::kExitUsage;
    }
    state.scene().select(light);
  }

  ViewportView viewport;
  PendingResize resize;
  std::string title;
  int presented = 0;
  bool prompt = false;
  bool quit = false;
  bool paused = false;
  std::vector<double> frame_ms;  // UI + edits + render + present, per presented frame
  while (!quit) {
    window->poll_events();
    const bool close_requested = window->should_close();
    if (close_requested) {
      window->set_should_close(false);
      if (!state.dirty()) break;
      prompt = true;  // ask first; the modal decides
    }
    if (!presenter.ready()) {
      if (!paused) std::printf("editor: window minimised, rendering paused\n");
      paused = true;
      window->wait_events();  // nothing to draw until it is restored
      continue;
    }
    if (paused) std::printf("editor: window restored, rendering resumed\n");
    paused = false;
    follow_window_size(state, presenter.swapchain().extent(), resize);
    gpu::CpuTimer frame_clock;
    ui.begin_frame(*window);
    const std::vector<KeyPress> presses = window->take_key_presses();
    handle_shortcuts(state, presses, *window);
    {
      const fgvk::BoundImage* shown = session.executor().image(state.shown_resource());
      const VkExtent2D view = session.viewport();
      const VkExtent2D window_extent = presenter.swapchain().extent();
      const VkExtent2D shown_extent = shown != nullptr ? shown->extent : view;
      viewport.update(state, presses, size_of(view), size_of(shown_extent), size_of(window_extent));
    }
    draw_lights_panel(state);
    draw_layers_panel(state);
    draw_graph_panel(state);
    draw_status_bar(state);
    switch (draw_close_prompt(state, close_requested && prompt)) {
      case CloseChoice::close:
        quit = true;
        break;
      case CloseChoice::cancel:
        prompt = false;
        break;
      case CloseChoice::none:
        break;
    }
    state.end_frame(ImGui::IsAnyItemActive() || viewport.dragging());
    ui.end_frame();

    session.render(1, nullptr);
    const bool last = options.frames > 0 && presented + 1 >= options.frames;
    // The window as presented where the swapchain can be read, else the graph's image.
    const bool from_window = presenter.swapchain().readable();
    const fgvk::BoundImage* shown = session.executor().image(state.shown_resource());
    if (presenter.present(
            shown, [&](VkCommandBuffer cmd) { ui.draw(cmd); },
            last && from_window ? options.screenshot : std::string())) {
      if (last && !from_window && !options.screenshot.empty()) {
        session.write_image(state.shown_resource(), options.screenshot);
      }
      ++presented;
      frame_ms.push_back(frame_clock.elapsed_ms());
      state.frame_presented();
      if (presented == 1) std::printf("editor: first frame presented\n");
      if (options.frame_log) std::printf("editor: frame %d\n", presented);
      // Scripts that drive the window wait for these lines.
      if (presented == 1 || options.frame_log) std::fflush(stdout);
    }
    state.autosave();
    state.poll_files();
    if (presented % kTimingWindowFrames == 5) state.refresh_timings();  // first after warm-up
    if (const auto now = window_title(state, scene_file, graph_file); now != title) {
      title = now;
      window->set_title(title);
    }
    if (options.frames > 0 && presented >= options.frames) quit = true;
  }
  if (options.frames > 0 && presented >= options.frames) {
    for (const auto& line : state.close_keeping_unsaved()) {
      std::printf("editor: warning: %s\n", line.c_str());
    }
  } else {
    state.close();
  }
  session.gpu().wait_idle();
  std::printf("editor: %d frame(s) presented, %u swapchain rebuild(s)\n", presented,
              presenter.recreations());
  if (!frame_ms.empty()) {
    std::sort(frame_ms.begin(), frame_ms.end());
    std::printf("editor frame (%ux%u graph): %.2f ms wall median (UI + render + present)\n",
                session.viewport().width, session.viewport().height, frame_ms[frame_ms.size() / 2]);
  }
  if (!options.screenshot.empty() && options.frames > 0 && presented >= options.frames) {
    std::printf("screenshot: %s\n", options.screenshot.c_str());
  }
  if (options.validation) {
    const std::size_t errors = session.gpu().validation_error_count();
    std::printf("validation: %zu error(s), %zu warning(s)\n", errors,
                session.gpu().validation_warning_count());
    if (errors > 0) return runtime::kExitDiagnostics;
  }
  return runtime::kExitOk;
}

}  // namespace antumbra::editor_app
