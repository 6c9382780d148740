#pragma once
// The editor's window around its viewport: the side column of panels on the right with
// a splitter on its left edge, the status bar along the bottom with one on its top edge,
// and the viewport in what is left (editor::EditorLayout does the maths). The layout is
// read from the per-user layout file at start and written back when it changes and on
// exit, ImGui's own window state included; --layout-report writes the rectangles as
// drawn, for tests that check nothing covers the image.

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

#include "antumbra/editor/editor_layout.hpp"
#include "antumbra/gpu/timing.hpp"
#include "panels.hpp"
#include "window.hpp"

namespace antumbra::editor_app {

struct LayoutOptions {
  std::string file;       // empty: the per-user default (editor::default_layout_file)
  float ui_scale = 0.0f;  // > 0: this scale instead of the window's content scale
};

class LayoutView {
 public:
  // Reads the layout file (a missing or damaged one is the defaults, with a message).
  LayoutView(const LayoutOptions& options, const Window& window);

  // The UI scale: the override, else the window's content scale.
  [[nodiscard]] float scale() const { return scale_; }
  void set_scale(float scale) { scale_ = scale; }
  // The viewport's size in framebuffer pixels before the UI exists: the graph's first size.
  [[nodiscard]] VkExtent2D initial_viewport(const Window& window) const;
  // Hands ImGui its saved window state: after its context exists, before its first frame.
  void restore_imgui_state() const;

  // After ImGui::NewFrame: lays the frame out and draws the splitters (dragging one
  // changes the layout from the next frame on). Then draw the panels into slot().
  void begin_frame();
  [[nodiscard]] PanelSlot& slot(editor::Panel panel) {
    return slots_[static_cast<std::size_t>(panel)];
  }
  [[nodiscard]] const editor::EditorLayout& layout() const { return layout_; }
  // The node view under the viewport (F2 or the status bar's button): opening it shrinks
  // the viewport, so nothing covers the image.
  [[nodiscard]] bool node_view_open() const { return settings_.node_view_open; }
  void toggle_node_view() {
    settings_.node_view_open = !settings_.node_view_open;
    dirty_ = true;
  }
  // The viewport in framebuffer pixels: where the graph's image goes, and its size.
  [[nodiscard]] editor::PixelRect viewport_pixels() const;
  // After the panels: keeps what their title bars collapsed, saves a changed layout once
  // no button is held (at most once a second).
  void end_frame();
  // Saves now (on exit); a failure is a message, never fatal.
  void save();
  // The layout as drawn in the last frame, as JSON; false (after saying why) on failure.
  bool write_report(const std::string& path, VkExtent2D image, editor::PixelRect shown) const;

 private:
  enum class Handle { column, bar, node_view };
  void draw_handle(const char* id, const editor::Rect& rect, Handle handle);

  std::optional<std::filesystem::path> file_;
  editor::LayoutSettings settings_;
  editor::EditorLayout layout_;
  std::array<PanelSlot, editor::kPanelCount> slots_;
  float scale_ = 1.0f;
  bool dirty_ = false;
  bool save_failed_ = false;  // said once; later saves stay quiet
  gpu::CpuTimer since_save_;
};

}  // namespace antumbra::editor_app
