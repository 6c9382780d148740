#pragma once
// The windowed editor's layout, without a window: a side column of panels on the right
// and a status bar along the bottom around the 3D viewport, so no panel covers the
// rendered image. Sizes are saved in unscaled units (pixels at UI scale 1) and scaled by
// the DPI scale when laid out, so a layout moves between screens of different density.
// The layout file (editor.ini) lives per user outside any repository; it holds these
// settings and, verbatim, Dear ImGui's own window state.

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/editor/viewport.hpp"

namespace antumbra::editor {

// A rectangle in window units (ImGui's), origin top-left.
struct Rect {
  float x = 0.0f;
  float y = 0.0f;
  float width = 0.0f;
  float height = 0.0f;
  [[nodiscard]] bool empty() const { return width <= 0.0f || height <= 0.0f; }
  // Sharing an edge is not overlapping: only a common area of positive size counts.
  [[nodiscard]] bool intersects(const Rect& other) const;
};

// The panels stacked in the side column, top to bottom.
enum class Panel : std::size_t { lights, layers, graph };
constexpr std::size_t kPanelCount = 3;
std::string_view panel_title(Panel panel);  // "Lights", "Layers", "Frame graph"

// What the user changes and the layout file keeps.
struct LayoutSettings {
  static constexpr float kDefaultColumn = 400.0f;
  static constexpr float kMinColumn = 160.0f;  // narrower, the panels' fields are unusable
  static constexpr float kMaxColumn = 4000.0f;
  static constexpr float kDefaultBar = 30.0f;
  static constexpr float kMinBar = 26.0f;  // one line of buttons and the message
  static constexpr float kMaxBar = 600.0f;

  // The node view: a strip under the viewport (the graph's passes as nodes and its plan).
  static constexpr float kDefaultNodeView = 320.0f;
  static constexpr float kMinNodeView = 120.0f;  // lower, a node's ports do not fit
  static constexpr float kMaxNodeView = 4000.0f;

  float column_width = kDefaultColumn;        // the side column, unscaled
  float bar_height = kDefaultBar;             // the bottom status bar, unscaled
  float node_view_height = kDefaultNodeView;  // unscaled, kept while the view is closed
  bool node_view_open = false;  // closed: the viewport keeps the height (toggled with F2)
  std::array<bool, kPanelCount> collapsed{};
  std::string imgui_state;  // Dear ImGui's own .ini text (its windows and tables)

  [[nodiscard]] bool collapsed_panel(Panel p) const {
    return collapsed[static_cast<std::size_t>(p)];
  }
  // Every value within its limits; NaN or infinite values become the defaults.
  [[nodiscard]] LayoutSettings clamped() const;
  bool operator==(const LayoutSettings&) const = default;
};

// The rectangles of one frame, in window units.
struct EditorLayout {
  Rect window;
  Rect viewport;          // where the graph's image goes: nothing else is drawn over it
  Rect column;            // the side column: the splitter and the panels
  Rect column_handle;     // the column's left edge: dragging it sets the column's width
  Rect bar;               // the bottom strip: its handle above the status bar
  Rect bar_handle;        // the bar's top edge: dragging it sets the bar's height
  Rect status;            // the status bar window (buttons and messages)
  Rect node_view;         // under the viewport, left of the column; empty while closed
  Rect node_view_handle;  // its top edge: dragging it sets the node view's height
  std::array<Rect, kPanelCount> panels;
  float scale = 1.0f;
  [[nodiscard]] const Rect& panel(Panel p) const { return panels[static_cast<std::size_t>(p)]; }
};

// Lays the editor out in a window of `window_size` (window units) at UI `scale`.
// `title_height`: a panel's title bar (what a collapsed panel keeps), in window units.
// The column and bar give way to keep a viewport at least kMinViewport wide and high
// where the window allows it; nothing overlaps, and every rectangle lies in the window.
EditorLayout compute_layout(glm::vec2 window_size, float scale, const LayoutSettings& settings,
                            float title_height);
constexpr float kMinViewport = 64.0f;  // unscaled
constexpr float kHandleWidth = 6.0f;   // the splitters' grab strips, unscaled

// The column's new unscaled width when its handle is dragged by `dx` window units from
// `layout` (left is wider), or the bar's new height for a drag of `dy` (up is taller).
// From the sizes on screen, which the window may have clamped, so a drag never starts
// with a dead zone; the result is within the settings' limits.
float column_after_drag(const EditorLayout& layout, float dx);
float bar_after_drag(const EditorLayout& layout, float dy);
float node_view_after_drag(const EditorLayout& layout, float dy);

// A window-unit rectangle in framebuffer pixels (`framebuffer_scale`: pixels per window
// unit), snapped to whole pixels; at least 1x1.
PixelRect to_pixels(const Rect& rect, glm::vec2 framebuffer_scale);
// Where an image of `image` pixels is shown inside `area` (framebuffer pixels): the
// largest rectangle of the image's aspect, centred in the area.
PixelRect fit_image(glm::ivec2 image, const PixelRect& area);

// The layout file's text. Unknown keys and sections are kept out of the settings;
// `problems` names each line that could not be read (the default is used for it).
std::string serialise(const LayoutSettings& settings);
struct ParsedLayout {
  LayoutSettings settings;
  std::vector<std::string> problems;  // "line 3: column_width: not a number", ...
};
ParsedLayout parse_layout(std::string_view text);

// Where the layout is kept: $ANTUMBRA_CONFIG_DIR/editor.ini, else
// $XDG_CONFIG_HOME/antumbra/editor.ini (an absolute XDG_CONFIG_HOME only, as the XDG
// specification says), else ~/.config/antumbra/editor.ini; nullopt when none of these
// is set (nothing is saved). `getenv` is the environment (a seam for tests).
using EnvLookup = std::function<const char*(const char*)>;
std::optional<std::filesystem::path> default_layout_file(const EnvLookup& getenv);

// Reads a layout file. A missing file is the defaults with a note; an unreadable or
// corrupt one is the defaults (for what could not be read) with a message saying so.
struct LoadedLayout {
  LayoutSettings settings;
  std::string message;  // empty when the file was read whole
};
LoadedLayout load_layout(const std::filesystem::path& file);
// Writes atomically, creating the folder; throws SaveError when it cannot.
void save_layout(const std::filesystem::path& file, const LayoutSettings& settings);

}  // namespace antumbra::editor
