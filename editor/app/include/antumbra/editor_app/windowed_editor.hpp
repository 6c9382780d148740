#pragma once
// `antumbra edit` with a window: GLFW + Vulkan swapchain + Dear ImGui over the running
// frame graph (Lights, Layers and Frame graph panels over the editor model).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace antumbra::fgvk {
class PassRegistry;
}

namespace antumbra::editor_app {

struct WindowedOptions {
  std::string graph;                 // empty: the default graph
  std::string scene;                 // empty: the default scene
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
  std::string device = "auto";
  bool validation = false;
  int frames = 0;         // > 0: close after this many presented frames (tests)
  unsigned width = 1280;  // the window; the graph renders at the viewport beside the panels
  unsigned height = 720;
  std::string screenshot;     // PNG of the last presented window image (UI included)
  std::string select;         // a light's name: selected at start (its range sphere shown)
  std::string shots;          // a folder: F12 writes the window as presented to shot-N.png
  bool frame_log = false;     // "editor: frame N" per presented frame, flushed (input scripts)
  std::string layout_file;    // empty: the per-user editor.ini (ANTUMBRA_CONFIG_DIR, XDG, ~)
  float ui_scale = 0.0f;      // > 0: instead of the window's DPI scale
  std::string layout_report;  // JSON of the window's layout as last drawn, written on exit
  // A host's pass types, as runtime::SessionOptions takes them (docs/adding-a-pass.md, "A
  // pass type from outside the tree"): the session runs them and the Frame graph panel
  // edits their parameters like a built-in pass's.
  std::vector<std::filesystem::path> shader_dirs;
  std::function<void(fgvk::PassRegistry&)> register_passes;
};

// Exit codes as the rest of the command line: 0 ok, 1 diagnostics (bad files, or
// validation errors with --validation), 3 runtime failures (no display, no device).
int run_windowed_editor(const WindowedOptions& options);

}  // namespace antumbra::editor_app
