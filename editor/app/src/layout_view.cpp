#include "layout_view.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <imgui.h>

#include "antumbra/editor/atomic_file.hpp"

namespace antumbra::editor_app {
namespace {

constexpr double kSaveIntervalMs = 1000.0;  // a splitter drag saves once, not every frame

glm::vec2 framebuffer_scale() {
  const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
  return {s.x > 0.0f ? s.x : 1.0f, s.y > 0.0f ? s.y : 1.0f};
}

void write_rect(std::FILE* out, const char* name, const editor::PixelRect& r) {
  std::fprintf(out, "  \"%s\": {\"x\": %d, \"y\": %d, \"width\": %d, \"height\": %d},\n", name, r.x,
               r.y, r.width, r.height);
}

}  // namespace

bool begin_panel(const char* title, PanelSlot& slot) {
  ImGui::SetNextWindowPos({slot.target.x, slot.target.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({slot.target.width, slot.target.height}, ImGuiCond_Always);
  ImGui::SetNextWindowCollapsed(slot.collapsed, ImGuiCond_Appearing);
  const bool open = ImGui::Begin(
      title, nullptr,
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
  const ImVec2 pos = ImGui::GetWindowPos();
  const ImVec2 size = ImGui::GetWindowSize();
  slot.shown = {pos.x, pos.y, size.x, size.y};
  slot.collapsed = ImGui::IsWindowCollapsed();
  slot.drawn = true;
  return open;
}

LayoutView::LayoutView(const LayoutOptions& options, const Window& window) {
  scale_ = options.ui_scale > 0.0f ? options.ui_scale : window.content_scale();
  if (!options.file.empty()) {
    file_ = options.file;
  } else {
    file_ = editor::default_layout_file([](const char* name) { return std::getenv(name); });
  }
  if (!file_) {
    std::printf("editor: no HOME or config folder: the layout is not saved\n");
    return;
  }
  const editor::LoadedLayout loaded = editor::load_layout(*file_);
  settings_ = loaded.settings;
  std::printf("editor: layout %s\n", loaded.message.empty() ? ("from " + file_->string()).c_str()
                                                            : loaded.message.c_str());
  for (std::size_t i = 0; i < editor::kPanelCount; ++i)
    slots_[i].collapsed = settings_.collapsed[i];
}

VkExtent2D LayoutView::initial_viewport(const Window& window) const {
  const VkExtent2D size = window.window_size();
  const VkExtent2D pixels = window.framebuffer_size();
  const glm::vec2 units(static_cast<float>(size.width), static_cast<float>(size.height));
  const glm::vec2 fb_scale =
      size.width > 0 && size.height > 0
          ? glm::vec2(static_cast<float>(pixels.width), static_cast<float>(pixels.height)) / units
          : glm::vec2(1.0f);
  const editor::EditorLayout layout = editor::compute_layout(units, scale_, settings_, 0.0f);
  const editor::PixelRect rect = editor::to_pixels(layout.viewport, fb_scale);
  return {static_cast<std::uint32_t>(rect.width), static_cast<std::uint32_t>(rect.height)};
}

void LayoutView::restore_imgui_state() const {
  if (settings_.imgui_state.empty()) return;
  ImGui::LoadIniSettingsFromMemory(settings_.imgui_state.c_str(), settings_.imgui_state.size());
}

void LayoutView::begin_frame() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  layout_ = editor::compute_layout({size.x, size.y}, scale_, settings_, ImGui::GetFrameHeight());
  for (std::size_t i = 0; i < editor::kPanelCount; ++i) {
    slots_[i].target = layout_.panels[i];
    slots_[i].drawn = false;
  }
  draw_handle("##column splitter", layout_.column_handle, Handle::column);
  draw_handle("##bar splitter", layout_.bar_handle, Handle::bar);
  draw_handle("##node view splitter", layout_.node_view_handle, Handle::node_view);
}

// A splitter: a bare window over its grab strip. Dragging it resizes the column (or the
// bar); the strip lights up under the cursor so it can be found.
void LayoutView::draw_handle(const char* id, const editor::Rect& rect, Handle handle) {
  const bool column = handle == Handle::column;
  if (rect.empty()) return;  // a window too small for one
  ImGui::SetNextWindowPos({rect.x, rect.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({rect.width, rect.height}, ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0.0f, 0.0f});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::InvisibleButton("##grab", {rect.width, rect.height});
  const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
  const ImGuiCol colour = ImGui::IsItemActive()    ? ImGuiCol_SeparatorActive
                          : ImGui::IsItemHovered() ? ImGuiCol_SeparatorHovered
                                                   : ImGuiCol_Separator;
  ImGui::GetWindowDrawList()->AddRectFilled(
      {rect.x, rect.y}, {rect.x + rect.width, rect.y + rect.height}, ImGui::GetColorU32(colour));
  if (hot) ImGui::SetMouseCursor(column ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
  const ImVec2 delta = ImGui::GetIO().MouseDelta;
  if (ImGui::IsItemActive() && (delta.x != 0.0f || delta.y != 0.0f)) {
    switch (handle) {
      case Handle::column:
        settings_.column_width = editor::column_after_drag(layout_, delta.x);
        break;
      case Handle::bar:
        settings_.bar_height = editor::bar_after_drag(layout_, delta.y);
        break;
      case Handle::node_view:
        settings_.node_view_height = editor::node_view_after_drag(layout_, delta.y);
        break;
    }
    dirty_ = true;
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

editor::PixelRect LayoutView::viewport_pixels() const {
  return editor::to_pixels(layout_.viewport, framebuffer_scale());
}

void LayoutView::end_frame() {
  for (std::size_t i = 0; i < editor::kPanelCount; ++i) {
    if (!slots_[i].drawn || slots_[i].collapsed == settings_.collapsed[i]) continue;
    settings_.collapsed[i] = slots_[i].collapsed;
    dirty_ = true;
  }
  ImGuiIO& io = ImGui::GetIO();
  if (io.WantSaveIniSettings) {
    io.WantSaveIniSettings = false;
    dirty_ = true;
  }
  if (dirty_ && !ImGui::IsAnyMouseDown() && since_save_.elapsed_ms() >= kSaveIntervalMs) save();
}

void LayoutView::save() {
  dirty_ = false;
  since_save_.restart();
  if (!file_) return;
  settings_.imgui_state = ImGui::SaveIniSettingsToMemory();
  try {
    editor::save_layout(*file_, settings_);
  } catch (const editor::SaveError& e) {
    if (!save_failed_) std::printf("editor: the layout is not saved: %s\n", e.what());
    save_failed_ = true;
  }
}

bool LayoutView::write_report(const std::string& path, VkExtent2D image,
                              editor::PixelRect shown) const {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) {
    std::printf("editor: cannot write the layout report %s\n", path.c_str());
    return false;
  }
  const glm::vec2 fb = framebuffer_scale();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  std::fprintf(out, "{\n  \"window\": {\"width\": %.0f, \"height\": %.0f},\n", size.x, size.y);
  std::fprintf(out, "  \"framebuffer_scale\": [%g, %g],\n  \"ui_scale\": %g,\n", fb.x, fb.y,
               scale_);
  std::fprintf(out, "  \"column_width\": %g,\n  \"bar_height\": %g,\n", settings_.column_width,
               settings_.bar_height);
  write_rect(out, "viewport", viewport_pixels());
  write_rect(out, "shown", shown);
  std::fprintf(out, "  \"image\": {\"width\": %u, \"height\": %u},\n", image.width, image.height);
  write_rect(out, "status", editor::to_pixels(layout_.status, fb));
  write_rect(out, "column_handle", editor::to_pixels(layout_.column_handle, fb));
  if (!layout_.node_view.empty())
    write_rect(out, "node_view", editor::to_pixels(layout_.node_view, fb));
  std::fprintf(out, "  \"panels\": [");
  for (std::size_t i = 0; i < editor::kPanelCount; ++i) {
    const editor::PixelRect r = editor::to_pixels(slots_[i].shown, fb);
    std::fprintf(out,
                 "%s\n    {\"name\": \"%s\", \"x\": %d, \"y\": %d, \"width\": %d, \"height\": %d, "
                 "\"collapsed\": %s}",
                 i == 0 ? "" : ",", std::string(editor::panel_title(editor::Panel(i))).c_str(), r.x,
                 r.y, r.width, r.height, slots_[i].collapsed ? "true" : "false");
  }
  std::fprintf(out, "\n  ]\n}\n");
  const bool ok = std::fclose(out) == 0;
  if (!ok) std::printf("editor: cannot write the layout report %s\n", path.c_str());
  return ok;
}

}  // namespace antumbra::editor_app
