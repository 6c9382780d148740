// The editor's layout around its viewport: the rectangles from the window's size, the
// column's width and the UI scale; clamping of absurd saved values; the layout file's
// text both ways; where it is kept; reading a missing or corrupt file.

#include "antumbra/editor/editor_layout.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace antumbra::editor {
namespace {

namespace fs = std::filesystem;

constexpr float kTitle = 19.0f;

bool inside(const Rect& inner, const Rect& outer) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

// Nothing overlaps the viewport or another part, and everything is inside the window.
void expect_disjoint(const EditorLayout& layout) {
  std::vector<Rect> parts{layout.column_handle, layout.bar_handle, layout.status};
  // The node view's handle lies on its top edge, inside it: they are one part.
  parts.push_back(layout.node_view);
  EXPECT_TRUE(layout.node_view_handle.empty() || inside(layout.node_view_handle, layout.node_view));
  for (const Rect& panel : layout.panels) parts.push_back(panel);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    EXPECT_FALSE(parts[i].intersects(layout.viewport)) << "part " << i;
    EXPECT_TRUE(parts[i].empty() || inside(parts[i], layout.window)) << "part " << i;
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      EXPECT_FALSE(parts[i].intersects(parts[j])) << "parts " << i << " and " << j;
    }
  }
  EXPECT_TRUE(inside(layout.viewport, layout.window));
}

TEST(EditorLayout, ColumnOnTheRightAndBarAtTheBottom) {
  const LayoutSettings settings;
  const EditorLayout layout = compute_layout({1280.0f, 800.0f}, 1.0f, settings, kTitle);
  EXPECT_FLOAT_EQ(layout.column.width, LayoutSettings::kDefaultColumn);
  EXPECT_FLOAT_EQ(layout.column.x, 1280.0f - LayoutSettings::kDefaultColumn);
  EXPECT_FLOAT_EQ(layout.bar.height, LayoutSettings::kDefaultBar);
  EXPECT_FLOAT_EQ(layout.viewport.x, 0.0f);
  EXPECT_FLOAT_EQ(layout.viewport.y, 0.0f);
  EXPECT_FLOAT_EQ(layout.viewport.width, 1280.0f - LayoutSettings::kDefaultColumn);
  EXPECT_FLOAT_EQ(layout.viewport.height, 800.0f - LayoutSettings::kDefaultBar);
  // The panels fill the column below each other, down to the bar.
  EXPECT_FLOAT_EQ(layout.panel(Panel::lights).y, 0.0f);
  EXPECT_FLOAT_EQ(layout.panel(Panel::graph).y + layout.panel(Panel::graph).height, layout.bar.y);
  expect_disjoint(layout);
}

TEST(EditorLayout, ScaleMultipliesTheSavedSizes) {
  const LayoutSettings settings;
  const EditorLayout one = compute_layout({2560.0f, 1600.0f}, 1.0f, settings, kTitle);
  const EditorLayout two = compute_layout({2560.0f, 1600.0f}, 2.0f, settings, 2.0f * kTitle);
  EXPECT_FLOAT_EQ(two.column.width, 2.0f * one.column.width);
  EXPECT_FLOAT_EQ(two.bar.height, 2.0f * one.bar.height);
  EXPECT_FLOAT_EQ(two.column_handle.width, 2.0f * one.column_handle.width);
  expect_disjoint(two);
}

TEST(EditorLayout, SmallWindowsKeepAViewport) {
  LayoutSettings settings;
  settings.column_width = LayoutSettings::kMaxColumn;
  for (const glm::vec2 size : {glm::vec2(320, 180), glm::vec2(100, 60), glm::vec2(1, 1),
                               glm::vec2(0, 0), glm::vec2(4000, 90)}) {
    const EditorLayout layout = compute_layout(size, 1.0f, settings, kTitle);
    SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
    EXPECT_GE(layout.viewport.width, std::min(size.x, 0.4f * size.x));
    EXPECT_GE(layout.viewport.height, std::min(size.y, 0.4f * size.y));
    expect_disjoint(layout);
  }
}

TEST(EditorLayout, CollapsedPanelsKeepTheirTitleAndTheOthersGrow) {
  LayoutSettings settings;
  settings.collapsed[static_cast<std::size_t>(Panel::lights)] = true;
  const EditorLayout layout = compute_layout({1280.0f, 800.0f}, 1.0f, settings, kTitle);
  EXPECT_FLOAT_EQ(layout.panel(Panel::lights).height, kTitle);
  EXPECT_FLOAT_EQ(layout.panel(Panel::layers).y, kTitle);
  const float rest = layout.column.height - kTitle;
  EXPECT_NEAR(layout.panel(Panel::layers).height, rest / 2.0f, 1.0f);
  expect_disjoint(layout);
  settings.collapsed.fill(true);
  const EditorLayout all = compute_layout({1280.0f, 800.0f}, 1.0f, settings, kTitle);
  for (const Rect& panel : all.panels) EXPECT_FLOAT_EQ(panel.height, kTitle);
  expect_disjoint(all);
}

TEST(EditorLayout, AbsurdValuesAreClamped) {
  LayoutSettings settings;
  settings.column_width = 1e9f;
  settings.bar_height = -5.0f;
  LayoutSettings c = settings.clamped();
  EXPECT_FLOAT_EQ(c.column_width, LayoutSettings::kMaxColumn);
  EXPECT_FLOAT_EQ(c.bar_height, LayoutSettings::kMinBar);
  settings.column_width = std::numeric_limits<float>::quiet_NaN();
  settings.bar_height = std::numeric_limits<float>::infinity();
  c = settings.clamped();
  EXPECT_FLOAT_EQ(c.column_width, LayoutSettings::kDefaultColumn);
  EXPECT_FLOAT_EQ(c.bar_height, LayoutSettings::kDefaultBar);
  const EditorLayout layout =
      compute_layout({1280.0f, std::numeric_limits<float>::quiet_NaN()}, 1e6f, settings, kTitle);
  expect_disjoint(layout);
}

TEST(EditorLayout, DraggingTheHandlesChangesTheSizes) {
  const LayoutSettings settings;
  const EditorLayout layout = compute_layout({2560.0f, 1600.0f}, 2.0f, settings, kTitle);
  // 100 window units left at scale 2: 50 unscaled units wider.
  EXPECT_FLOAT_EQ(column_after_drag(layout, -100.0f), LayoutSettings::kDefaultColumn + 50.0f);
  EXPECT_FLOAT_EQ(column_after_drag(layout, 1e7f), LayoutSettings::kMinColumn);
  EXPECT_FLOAT_EQ(bar_after_drag(layout, -20.0f), LayoutSettings::kDefaultBar + 10.0f);
  EXPECT_FLOAT_EQ(bar_after_drag(layout, 500.0f), LayoutSettings::kMinBar);
}

TEST(EditorLayout, TheNodeViewSitsUnderTheViewportAndNeverTakesItsShare) {
  LayoutSettings settings;
  EXPECT_TRUE(compute_layout({1280.0f, 800.0f}, 1.0f, settings, kTitle).node_view.empty());
  settings.node_view_open = true;
  EditorLayout layout = compute_layout({1280.0f, 800.0f}, 1.0f, settings, kTitle);
  EXPECT_FLOAT_EQ(layout.node_view.height, LayoutSettings::kDefaultNodeView);
  EXPECT_FLOAT_EQ(layout.node_view.y, layout.viewport.height);
  EXPECT_FLOAT_EQ(layout.node_view.y + layout.node_view.height, layout.bar.y);
  EXPECT_FLOAT_EQ(layout.node_view.width, layout.viewport.width);
  EXPECT_FLOAT_EQ(layout.viewport.height,
                  800.0f - LayoutSettings::kDefaultBar - LayoutSettings::kDefaultNodeView);
  expect_disjoint(layout);
  // A tall saved view in a short window: the viewport keeps 40 % of the height.
  settings.node_view_height = 3000.0f;
  settings.bar_height = 100.0f;
  layout = compute_layout({1280.0f, 500.0f}, 1.0f, settings, kTitle);
  EXPECT_FLOAT_EQ(layout.viewport.height, 200.0f);
  EXPECT_FLOAT_EQ(layout.node_view.height, 200.0f);
  expect_disjoint(layout);
  // Dragging its handle up by 40 units at scale 2 makes it 20 unscaled units taller.
  settings = LayoutSettings{};
  settings.node_view_open = true;
  layout = compute_layout({2560.0f, 1600.0f}, 2.0f, settings, kTitle);
  EXPECT_FLOAT_EQ(node_view_after_drag(layout, -40.0f), LayoutSettings::kDefaultNodeView + 20.0f);
  EXPECT_FLOAT_EQ(node_view_after_drag(layout, 1e6f), LayoutSettings::kMinNodeView);
}

TEST(EditorLayout, PixelsAndTheImageInTheViewport) {
  const PixelRect px = to_pixels({10.0f, 0.0f, 100.5f, 50.0f}, {2.0f, 2.0f});
  EXPECT_EQ(px.x, 20);
  EXPECT_EQ(px.width, 201);
  EXPECT_EQ(px.height, 100);
  const PixelRect fitted = fit_image({200, 100}, {100, 50, 400, 400});
  EXPECT_EQ(fitted.x, 100);
  EXPECT_EQ(fitted.y, 150);
  EXPECT_EQ(fitted.width, 400);
  EXPECT_EQ(fitted.height, 200);
}

TEST(EditorLayoutFile, RoundTrip) {
  LayoutSettings settings;
  settings.column_width = 512.0f;
  settings.bar_height = 44.0f;
  settings.collapsed[static_cast<std::size_t>(Panel::graph)] = true;
  settings.node_view_open = true;
  settings.node_view_height = 250.0f;
  settings.imgui_state = "[Window][Unsaved changes]\nPos=60,60\nSize=300,80\n";
  const ParsedLayout parsed = parse_layout(serialise(settings));
  EXPECT_TRUE(parsed.problems.empty()) << parsed.problems.front();
  EXPECT_EQ(parsed.settings, settings);
}

TEST(EditorLayoutFile, BadLinesAreNamedAndTheRestIsRead) {
  const ParsedLayout parsed = parse_layout(
      "[antumbra]\nversion=1\ncolumn_width=wide\nbar_height=1e30\ncollapsed=lights,bogus\n"
      "colour=red\nnode_view=ajar\n[Window][X]\nPos=1,1\n");
  ASSERT_EQ(parsed.problems.size(), 5u);
  EXPECT_EQ(parsed.problems[4], "line 7: node_view: 'ajar' is neither open nor closed");
  EXPECT_EQ(parsed.problems[0], "line 3: column_width: 'wide' is not a number");
  EXPECT_NE(parsed.problems[1].find("line 4: bar_height"), std::string::npos);
  EXPECT_EQ(parsed.problems[2], "line 5: collapsed: no panel 'bogus'");
  EXPECT_EQ(parsed.problems[3], "line 6: unknown key 'colour'");
  EXPECT_FLOAT_EQ(parsed.settings.column_width, LayoutSettings::kDefaultColumn);
  EXPECT_FLOAT_EQ(parsed.settings.bar_height, LayoutSettings::kMaxBar);
  EXPECT_TRUE(parsed.settings.collapsed_panel(Panel::lights));
  EXPECT_TRUE(parsed.settings.imgui_state.empty());  // not trusted from a damaged file
}

TEST(EditorLayoutFile, GarbageIsTheDefaults) {
  // Binary bytes, NULs included (the literal would stop at its first NUL).
  std::string garbage =
      "\x7f"
      "ELF\x01\x02\xff\xfe[[[]\n==\n";
  garbage += std::string(1000, '\0');
  garbage += "\x01\x02";
  const ParsedLayout parsed = parse_layout(garbage);
  EXPECT_FALSE(parsed.problems.empty());
  LayoutSettings defaults;
  EXPECT_EQ(parsed.settings, defaults);
}

TEST(EditorLayoutFile, WhereItIsKept) {
  std::map<std::string, std::string> env;
  const EnvLookup lookup = [&](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  };
  EXPECT_FALSE(default_layout_file(lookup).has_value());
  env["HOME"] = "/home/u";
  EXPECT_EQ(default_layout_file(lookup), fs::path("/home/u/.config/antumbra/editor.ini"));
  env["XDG_CONFIG_HOME"] = "relative/ignored";
  EXPECT_EQ(default_layout_file(lookup), fs::path("/home/u/.config/antumbra/editor.ini"));
  env["XDG_CONFIG_HOME"] = "/xdg";
  EXPECT_EQ(default_layout_file(lookup), fs::path("/xdg/antumbra/editor.ini"));
  env["ANTUMBRA_CONFIG_DIR"] = "/tmp/t";
  EXPECT_EQ(default_layout_file(lookup), fs::path("/tmp/t/editor.ini"));
}

TEST(EditorLayoutFile, MissingCorruptAndSavedFiles) {
  const fs::path dir =
      fs::temp_directory_path() / ("antumbra-layout-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path file = dir / "sub" / "editor.ini";
  LoadedLayout loaded = load_layout(file);
  EXPECT_NE(loaded.message.find("no saved layout"), std::string::npos);
  EXPECT_EQ(loaded.settings, LayoutSettings{});
  LayoutSettings settings;
  settings.column_width = 300.0f;
  save_layout(file, settings);  // creates the folder
  loaded = load_layout(file);
  EXPECT_TRUE(loaded.message.empty()) << loaded.message;
  EXPECT_EQ(loaded.settings, settings);
  std::ofstream(file, std::ios::trunc) << "column_width=17\n\x01\x02";
  loaded = load_layout(file);
  EXPECT_NE(loaded.message.find("defaults used"), std::string::npos);
  EXPECT_EQ(loaded.settings, LayoutSettings{});
  fs::remove_all(dir);
}

}  // namespace
}  // namespace antumbra::editor
