#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <imgui.h>

#include "antumbra/editor/fix_suggestion.hpp"
#include "antumbra/layering/layer_cap.hpp"
#include "layer_colours.hpp"
#include "panels.hpp"

namespace antumbra::editor_app {
namespace {

void draw_cap_control(EditorState& state) {
  const std::string pass = state.layering_pass();
  if (pass.empty()) {
    ImGui::TextDisabled("this graph has no light-layering pass: no cap to edit");
    return;
  }
  const auto param = state.graph().param(pass, layering::kLayerCap.name);
  int cap = state.graph_cap();
  // Typed digits commit on Enter (one undo step and one graph reload per value, not per
  // keystroke); the +/- buttons commit at once.
  if (ImGui::InputInt("cap k", &cap, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue)) {
    if (param && param->min) cap = std::max(cap, static_cast<int>(*param->min));
    if (param && param->max) cap = std::min(cap, static_cast<int>(*param->max));
    state.set_param(pass, layering::kLayerCap.name, cap);  // reloads the graph
  }
}

// World (x, z) -> canvas: the bounds of every finite circle, uniformly scaled.
struct MapTransform {
  ImVec2 origin;
  float scale = 1.0f;
  glm::vec2 world_min{0.0f};
  [[nodiscard]] ImVec2 to_canvas(glm::vec2 p) const {
    return {origin.x + (p.x - world_min.x) * scale, origin.y + (p.y - world_min.y) * scale};
  }
};

MapTransform fit(const editor::LayerReport& report, ImVec2 origin, ImVec2 size) {
  glm::vec2 lo(std::numeric_limits<float>::max());
  glm::vec2 hi(std::numeric_limits<float>::lowest());
  for (const auto& c : report.circles) {
    if (!std::isfinite(c.range)) continue;
    lo = glm::min(lo, c.centre - glm::vec2(c.range));
    hi = glm::max(hi, c.centre + glm::vec2(c.range));
  }
  if (lo.x > hi.x) {
    lo = glm::vec2(-10.0f);
    hi = glm::vec2(10.0f);
  }
  const glm::vec2 extent = glm::max(hi - lo, glm::vec2(0.01f));
  MapTransform t;
  t.scale = std::min(size.x / extent.x, size.y / extent.y);
  t.origin = {origin.x + (size.x - extent.x * t.scale) * 0.5f,
              origin.y + (size.y - extent.y * t.scale) * 0.5f};
  t.world_min = lo;
  return t;
}

// The seed's figure: spheres from above, coloured by layer, conflict edges between
// lights that overlap, a warning's pairs and over-cap lights in red.
void draw_map(EditorState& state, const editor::LayerReport& report) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size{std::max(ImGui::GetContentRegionAvail().x, 50.0f), 200.0f};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, {origin.x + size.x, origin.y + size.y}, IM_COL32(20, 20, 24, 255));
  ImGui::InvisibleButton("##map", size);
  const bool clicked = ImGui::IsItemClicked();
  draw->PushClipRect(origin, {origin.x + size.x, origin.y + size.y}, true);
  const MapTransform t = fit(report, {origin.x + 4, origin.y + 4}, {size.x - 8, size.y - 8});
  for (const auto& edge : report.edges) {
    const ImVec2 a = t.to_canvas(report.circles[edge.a].centre);
    const ImVec2 b = t.to_canvas(report.circles[edge.b].centre);
    draw->AddLine(a, b, edge.witness ? kWarningColour : IM_COL32(160, 160, 160, 120),
                  edge.witness ? 2.5f : 1.0f);
  }
  const int selected = state.scene().selected();
  for (const auto& c : report.circles) {
    if (!std::isfinite(c.range)) continue;  // the sun owns its layer: listed, not drawn
    const ImVec2 centre = t.to_canvas(c.centre);
    const float radius = c.range * t.scale;
    const ImU32 colour = layer_colour(c.layer);
    draw->AddCircleFilled(centre, radius, with_alpha(colour, 40));
    draw->AddCircle(centre, radius, colour, 0, 1.5f);
    if (c.over_cap) draw->AddCircle(centre, radius + 2.0f, kWarningColour, 0, 3.0f);
    if (static_cast<int>(c.light) == selected) {
      draw->AddCircle(centre, radius + 4.0f, IM_COL32_WHITE, 0, 1.0f);
    }
    draw->AddCircleFilled(centre, 3.0f, colour);
  }
  draw->PopClipRect();
  if (clicked) {
    // Click to select the light whose centre is nearest the cursor.
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    float best = 12.0f * 12.0f;
    int pick = -1;
    for (const auto& c : report.circles) {
      if (!std::isfinite(c.range)) continue;
      const ImVec2 p = t.to_canvas(c.centre);
      const float d = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
      if (d < best) {
        best = d;
        pick = static_cast<int>(c.light);
      }
    }
    if (pick >= 0) state.scene().select(pick);
  }
}

void draw_fix(EditorState& state) {
  const editor::FixSuggestion fix = state.status().suggestion(state.scene());  // a copy
  if (!fix.needed) return;
  if (fix.multi_fix) {  // several lights: why, then a line per light
    ImGui::TextWrapped("Suggested fix: no change to one light is enough; change %zu lights:",
                       fix.multi_fix->changes.size());
    for (const editor::LayerFix& change : fix.multi_fix->changes)
      ImGui::BulletText("%s", change.description.c_str());
  } else {
    ImGui::TextWrapped("Suggested fix: %s", fix.message.c_str());
  }
  if (fix.changes().empty()) return;
  // One undo step, however many lights it changes.
  if (ImGui::Button("Apply fix")) state.scene_edited(editor::apply_fix(state.scene(), fix));
}

}  // namespace

void draw_layers_panel(EditorState& state, PanelSlot& slot) {
  if (!begin_panel("Layers", slot)) {
    ImGui::End();
    return;
  }
  draw_cap_control(state);
  const editor::LayerReport report = state.report();  // a copy: a fix may change it
  ImGui::Text("layers needed %d, used %d, cap %d", report.layers_needed, report.layers_used,
              report.cap);
  if (report.over_cap()) {
    draw_fix(state);  // first: the one-click answer to the warnings below
    for (const auto& w : report.warnings) {
      ImGui::PushStyleColor(ImGuiCol_Text, kWarningColour);
      ImGui::TextWrapped("%s: %s", w.code.c_str(), w.message.c_str());
      ImGui::PopStyleColor();
    }
  } else {
    ImGui::TextDisabled("no warnings: the layout fits the cap");
  }
  draw_map(state, report);
  for (int layer = 0; layer < report.cap; ++layer) {
    if (layer > 0) ImGui::SameLine();
    ImGui::ColorButton(("layer " + std::to_string(layer)).c_str(),
                       ImGui::ColorConvertU32ToFloat4(layer_colour(layer)),
                       ImGuiColorEditFlags_NoTooltip, {14, 14});
  }
  ImGui::End();
}

}  // namespace antumbra::editor_app
