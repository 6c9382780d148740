#include "antumbra/editor/editor_layout.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include "antumbra/editor/atomic_file.hpp"

namespace antumbra::editor {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSection = "[antumbra]";
constexpr int kVersion = 1;
// A layout file is a few hundred bytes; anything this large is not one.
constexpr std::uintmax_t kMaxFileBytes = 1u << 20;
// Of the column's height, what each open panel gets (the layer map and the pass list
// need more room than the light list).
constexpr std::array<float, kPanelCount> kPanelWeights{0.30f, 0.35f, 0.35f};
constexpr std::array<std::string_view, kPanelCount> kPanelKeys{"lights", "layers", "graph"};
constexpr float kMinScale = 0.25f;
constexpr float kMaxScale = 8.0f;
constexpr float kBarHandle = 4.0f;  // unscaled: the bar's grab strip

float finite_or(float value, float fallback) {
  return std::isfinite(value) ? value : fallback;
}

// What the viewport keeps of an extent of `size`: the larger of the minimum and 40 %, so
// the panels never take most of a small window.
float reserved_for_viewport(float size, float scale) {
  return std::max(kMinViewport * scale, 0.4f * size);
}

// The column's or bar's extent: the saved size scaled, within its limits and what the
// window leaves after the viewport's share (which wins), whole window units.
// `whole`: the window's extent the viewport's share is taken of, when `size` is only what
// is left of it.
float fitted(float saved, float min_unscaled, float size, float scale, float whole = -1.0f) {
  const float of = whole < 0.0f ? size : whole;
  const float room = std::max(0.0f, size - reserved_for_viewport(of, scale));
  const float low = std::min(min_unscaled * scale, room);
  return std::round(std::clamp(saved * scale, low, room));
}

void stack_panels(EditorLayout& layout, const Rect& area, const LayoutSettings& settings,
                  float title_height) {
  float weights = 0.0f;
  float titles = 0.0f;
  for (std::size_t i = 0; i < kPanelCount; ++i) {
    if (settings.collapsed[i]) {
      titles += title_height;
    } else {
      weights += kPanelWeights[i];
    }
  }
  const float shared = std::max(0.0f, area.height - titles);
  float y = area.y;
  const float bottom = area.y + area.height;
  for (std::size_t i = 0; i < kPanelCount; ++i) {
    const float wanted =
        settings.collapsed[i] ? title_height : std::round(shared * kPanelWeights[i] / weights);
    // The last open panel takes the rounding's remainder, so the column is filled.
    const bool last = i + 1 == kPanelCount;
    const float height = std::clamp(last && !settings.collapsed[i] ? bottom - y : wanted, 0.0f,
                                    std::max(0.0f, bottom - y));
    layout.panels[i] = {area.x, y, area.width, height};
    y += height;
  }
}

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

std::optional<float> to_float(const std::string& text) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// One size: a number within [low, high]; else a problem and the value as it was.
void read_size(const std::string& key, const std::string& value, float low, float high,
               float& target, std::vector<std::string>& problems, int line) {
  const auto number = to_float(value);
  const std::string where = "line " + std::to_string(line) + ": " + key + ": ";
  if (!number) {
    problems.push_back(where + "'" + value + "' is not a number");
    return;
  }
  target = std::clamp(*number, low, high);
  if (target != *number) {
    std::ostringstream out;
    out << where << *number << " is outside " << low << ".." << high << ", " << target << " used";
    problems.push_back(out.str());
  }
}

void read_collapsed(const std::string& value, LayoutSettings& settings,
                    std::vector<std::string>& problems, int line) {
  std::istringstream list(value);
  std::string name;
  while (std::getline(list, name, ',')) {
    name = trimmed(name);
    if (name.empty()) continue;
    const auto* at = std::find(kPanelKeys.begin(), kPanelKeys.end(), name);
    if (at == kPanelKeys.end()) {
      problems.push_back("line " + std::to_string(line) + ": collapsed: no panel '" + name + "'");
      continue;
    }
    settings.collapsed[static_cast<std::size_t>(at - kPanelKeys.begin())] = true;
  }
}

void read_setting(const std::string& line_text, int line, LayoutSettings& settings,
                  std::vector<std::string>& problems) {
  const auto equals = line_text.find('=');
  if (equals == std::string::npos) {
    problems.push_back("line " + std::to_string(line) + ": not a key=value line");
    return;
  }
  const std::string key = trimmed(std::string_view(line_text).substr(0, equals));
  const std::string value = trimmed(std::string_view(line_text).substr(equals + 1));
  if (key == "version") {
    if (value != std::to_string(kVersion)) {
      problems.push_back("line " + std::to_string(line) + ": version " + value +
                         " is not one this editor writes (" + std::to_string(kVersion) + ")");
    }
  } else if (key == "column_width") {
    read_size(key, value, LayoutSettings::kMinColumn, LayoutSettings::kMaxColumn,
              settings.column_width, problems, line);
  } else if (key == "bar_height") {
    read_size(key, value, LayoutSettings::kMinBar, LayoutSettings::kMaxBar, settings.bar_height,
              problems, line);
  } else if (key == "node_view_height") {
    read_size(key, value, LayoutSettings::kMinNodeView, LayoutSettings::kMaxNodeView,
              settings.node_view_height, problems, line);
  } else if (key == "node_view") {
    if (value == "open" || value == "closed") {
      settings.node_view_open = value == "open";
    } else {
      problems.push_back("line " + std::to_string(line) + ": node_view: '" + value +
                         "' is neither open nor closed");
    }
  } else if (key == "collapsed") {
    read_collapsed(value, settings, problems, line);
  } else {
    problems.push_back("line " + std::to_string(line) + ": unknown key '" + key + "'");
  }
}

}  // namespace

bool Rect::intersects(const Rect& other) const {
  if (empty() || other.empty()) return false;
  return x < other.x + other.width && other.x < x + width && y < other.y + other.height &&
         other.y < y + height;
}

std::string_view panel_title(Panel panel) {
  constexpr std::array<std::string_view, kPanelCount> kTitles{"Lights", "Layers", "Frame graph"};
  return kTitles[static_cast<std::size_t>(panel)];
}

LayoutSettings LayoutSettings::clamped() const {
  LayoutSettings out = *this;
  out.column_width = std::clamp(finite_or(column_width, kDefaultColumn), kMinColumn, kMaxColumn);
  out.bar_height = std::clamp(finite_or(bar_height, kDefaultBar), kMinBar, kMaxBar);
  out.node_view_height =
      std::clamp(finite_or(node_view_height, kDefaultNodeView), kMinNodeView, kMaxNodeView);
  return out;
}

EditorLayout compute_layout(glm::vec2 window_size, float scale, const LayoutSettings& settings,
                            float title_height) {
  const LayoutSettings s = settings.clamped();
  EditorLayout layout;
  layout.scale = std::clamp(finite_or(scale, 1.0f), kMinScale, kMaxScale);
  const float w = std::max(0.0f, std::round(finite_or(window_size.x, 0.0f)));
  const float h = std::max(0.0f, std::round(finite_or(window_size.y, 0.0f)));
  layout.window = {0.0f, 0.0f, w, h};
  const float column = fitted(s.column_width, LayoutSettings::kMinColumn, w, layout.scale);
  const float bar = fitted(s.bar_height, LayoutSettings::kMinBar, h, layout.scale);
  // The node view takes what the bar leaves of the panels' share, never the viewport's.
  const float nodes = s.node_view_open ? fitted(s.node_view_height, LayoutSettings::kMinNodeView,
                                                h - bar, layout.scale, h)
                                       : 0.0f;
  layout.viewport = {0.0f, 0.0f, w - column, h - bar - nodes};
  if (nodes > 0.0f) {
    layout.node_view = {0.0f, layout.viewport.height, w - column, nodes};
    const float grab = std::min(nodes, std::round(kBarHandle * layout.scale));
    layout.node_view_handle = {0.0f, layout.node_view.y, layout.node_view.width, grab};
  }
  layout.column = {w - column, 0.0f, column, h - bar};
  const float handle = std::min(column, std::round(kHandleWidth * layout.scale));
  layout.column_handle = {layout.column.x, 0.0f, handle, layout.column.height};
  layout.bar = {0.0f, h - bar, w, bar};
  const float bar_handle = std::min(bar, std::round(kBarHandle * layout.scale));
  layout.bar_handle = {0.0f, layout.bar.y, w, bar_handle};
  layout.status = {0.0f, layout.bar.y + bar_handle, w, bar - bar_handle};
  const Rect panels{layout.column.x + handle, 0.0f, column - handle, layout.column.height};
  stack_panels(layout, panels, s, std::max(0.0f, finite_or(title_height, 0.0f)));
  return layout;
}

float column_after_drag(const EditorLayout& layout, float dx) {
  const float width = (layout.column.width - finite_or(dx, 0.0f)) / layout.scale;
  return std::clamp(width, LayoutSettings::kMinColumn, LayoutSettings::kMaxColumn);
}

float bar_after_drag(const EditorLayout& layout, float dy) {
  const float height = (layout.bar.height - finite_or(dy, 0.0f)) / layout.scale;
  return std::clamp(height, LayoutSettings::kMinBar, LayoutSettings::kMaxBar);
}

float node_view_after_drag(const EditorLayout& layout, float dy) {
  const float height = (layout.node_view.height - finite_or(dy, 0.0f)) / layout.scale;
  return std::clamp(height, LayoutSettings::kMinNodeView, LayoutSettings::kMaxNodeView);
}

PixelRect to_pixels(const Rect& rect, glm::vec2 framebuffer_scale) {
  const auto snap = [](float v) { return static_cast<int>(std::lround(finite_or(v, 0.0f))); };
  const int x0 = snap(rect.x * framebuffer_scale.x);
  const int y0 = snap(rect.y * framebuffer_scale.y);
  const int x1 = snap((rect.x + rect.width) * framebuffer_scale.x);
  const int y1 = snap((rect.y + rect.height) * framebuffer_scale.y);
  return {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
}

PixelRect fit_image(glm::ivec2 image, const PixelRect& area) {
  PixelRect fitted_rect = letterbox(image, {area.width, area.height});
  fitted_rect.x += area.x;
  fitted_rect.y += area.y;
  return fitted_rect;
}

std::string serialise(const LayoutSettings& settings) {
  const LayoutSettings s = settings.clamped();
  std::ostringstream out;
  out << "# The antumbra editor's layout, saved on exit; delete it for the defaults.\n"
      << kSection << "\nversion=" << kVersion << "\ncolumn_width=" << s.column_width
      << "\nbar_height=" << s.bar_height << "\nnode_view_height=" << s.node_view_height
      << "\nnode_view=" << (s.node_view_open ? "open" : "closed") << "\ncollapsed=";
  bool first = true;
  for (std::size_t i = 0; i < kPanelCount; ++i) {
    if (!s.collapsed[i]) continue;
    out << (first ? "" : ",") << kPanelKeys[i];
    first = false;
  }
  out << "\n";
  if (!s.imgui_state.empty()) out << "\n" << s.imgui_state;
  if (!s.imgui_state.empty() && s.imgui_state.back() != '\n') out << "\n";
  return out.str();
}

ParsedLayout parse_layout(std::string_view text) {
  ParsedLayout parsed;
  std::istringstream in{std::string(text)};
  std::string raw;
  int line = 0;
  // Sections other than ours are Dear ImGui's ([Window][Lights], [Table][...]): kept
  // verbatim for it to read.
  enum class Section { none, ours, imgui };
  Section section = Section::none;
  while (std::getline(in, raw)) {
    ++line;
    const std::string t = trimmed(raw);
    if (!t.empty() && t.front() == '[') {
      section = t == kSection ? Section::ours : Section::imgui;
      if (section == Section::ours) continue;
    }
    if (section == Section::imgui) {
      parsed.settings.imgui_state += raw + "\n";
      continue;
    }
    if (t.empty() || t.front() == '#' || t.front() == ';') continue;
    if (section == Section::none) {
      parsed.problems.push_back("line " + std::to_string(line) + ": outside any section");
      continue;
    }
    read_setting(t, line, parsed.settings, parsed.problems);
  }
  // A file that is not wholly ours is not trusted with ImGui's state either.
  if (!parsed.problems.empty()) parsed.settings.imgui_state.clear();
  return parsed;
}

std::optional<fs::path> default_layout_file(const EnvLookup& getenv) {
  const auto set = [&](const char* name) -> const char* {
    const char* value = getenv(name);
    return value != nullptr && *value != '\0' ? value : nullptr;
  };
  if (const char* dir = set("ANTUMBRA_CONFIG_DIR")) return fs::path(dir) / "editor.ini";
  if (const char* xdg = set("XDG_CONFIG_HOME"); xdg != nullptr && fs::path(xdg).is_absolute()) {
    return fs::path(xdg) / "antumbra" / "editor.ini";
  }
  if (const char* home = set("HOME")) return fs::path(home) / ".config" / "antumbra" / "editor.ini";
  return std::nullopt;
}

LoadedLayout load_layout(const fs::path& file) {
  LoadedLayout loaded;
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    loaded.message = "no saved layout at " + file.string() + " yet: the default layout";
    return loaded;
  }
  const std::uintmax_t bytes = fs::file_size(file, ec);
  std::ifstream in(file, std::ios::binary);
  if (ec || !in || bytes > kMaxFileBytes) {
    loaded.message = file.string() + ": " +
                     (bytes > kMaxFileBytes && !ec ? std::string("too large for a layout file")
                                                   : std::string("cannot be read")) +
                     ": the default layout";
    return loaded;
  }
  std::ostringstream text;
  text << in.rdbuf();
  ParsedLayout parsed = parse_layout(text.str());
  loaded.settings = std::move(parsed.settings);
  if (!parsed.problems.empty()) {
    loaded.message = file.string() + ": " + parsed.problems.front();
    if (parsed.problems.size() > 1) {
      loaded.message += " (and " + std::to_string(parsed.problems.size() - 1) + " more)";
    }
    loaded.message += "; defaults used where it could not be read";
  }
  return loaded;
}

void save_layout(const fs::path& file, const LayoutSettings& settings) {
  std::error_code ec;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
  if (ec) throw SaveError(file, "cannot create its folder: " + ec.message());
  write_file_atomically(file, serialise(settings));
}

}  // namespace antumbra::editor
