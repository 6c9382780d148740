#include <algorithm>
#include <string>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "panels.hpp"

namespace antumbra::editor_app {
namespace {

void draw_light_fields(EditorState& state, std::size_t index) {
  auto& scene = state.scene();
  const scene::PointLight light = scene.lights()[index];  // a copy: edits replace the list
  ImGui::Text("%s", light.name.c_str());
  if (scene.origin(index) != editor::LightOrigin::own) {
    // Imported lights (glTF, instanced scenes) are changed through overrides in the scene
    // file; the artist should know the model itself stays as it is.
    ImGui::TextDisabled(scene.origin(index) == editor::LightOrigin::override
                            ? "from an object, changed here (Revert restores it)"
                            : "from an object: changes are saved as overrides");
  }
  glm::vec3 position = light.position;
  const bool moved = ImGui::DragFloat3("position", &position.x, 0.05f);
  track_gesture(state, DocKind::scene);
  if (moved) state.scene_edited(scene.set_position(index, position));
  glm::vec3 color = light.color;
  const bool recoloured = ImGui::ColorEdit3("colour", &color.x, ImGuiColorEditFlags_Float);
  track_gesture(state, DocKind::scene);
  if (recoloured) state.scene_edited(scene.set_color(index, color));
  float intensity = light.intensity;
  // glTF lights arrive in photometric units (docs/technique.md section 6): a sun can be
  // 30 000, so the step follows the value and nothing clamps it.
  const bool brighter =
      ImGui::DragFloat("intensity", &intensity, std::max(0.1f, intensity * 0.01f), 0.0f, 1e7f);
  track_gesture(state, DocKind::scene);
  if (brighter) state.scene_edited(scene.set_intensity(index, intensity));
  if (light.type != scene::LightType::directional) {
    float range = light.range;
    const bool ranged = ImGui::DragFloat("range", &range, 0.05f, 0.01f, 100.0f);
    track_gesture(state, DocKind::scene);
    if (ranged) state.scene_edited(scene.set_range(index, range));
  }
  if (light.type != scene::LightType::point) {
    glm::vec3 direction = light.direction;
    const bool turned = ImGui::DragFloat3("direction", &direction.x, 0.01f, -1.0f, 1.0f);
    track_gesture(state, DocKind::scene);
    // A drag through (0, 0, 0) is refused by the document and simply not applied.
    if (turned && glm::length(direction) > 1e-3f) {
      state.scene_edited(scene.set_direction(index, direction));
    }
  }
  if (light.type == scene::LightType::spot) {
    float outer = light.spot_outer;
    float inner = light.spot_inner;
    const bool coned = ImGui::DragFloat("cone", &outer, 0.2f, 0.5f, 90.0f, "%.1f deg");
    track_gesture(state, DocKind::scene);
    const bool cored = ImGui::DragFloat("inner cone", &inner, 0.2f, 0.0f, outer, "%.1f deg");
    track_gesture(state, DocKind::scene);
    if (coned || cored) {
      state.scene_edited(scene.set_spot_angles(index, outer, std::min(inner, outer)));
    }
  }
  float size = light.size;
  const bool sized = ImGui::DragFloat("size", &size, 0.01f, 0.0f, 10.0f);
  track_gesture(state, DocKind::scene);
  if (sized) state.scene_edited(scene.set_size(index, size));
  bool casts = light.casts_shadows;
  if (ImGui::Checkbox("casts shadows", &casts)) {
    state.scene_edited(scene.set_casts_shadows(index, casts));
  }
}

}  // namespace

void draw_lights_panel(EditorState& state, PanelSlot& slot) {
  if (!begin_panel("Lights", slot)) {
    ImGui::End();
    return;
  }
  auto& scene = state.scene();
  const auto& report = state.report();
  const int selected = scene.selected();
  const bool has_selection = selected >= 0 && selected < static_cast<int>(scene.lights().size());
  if (ImGui::Button("Add")) state.scene_edited(scene.add_light());
  ImGui::SameLine();
  ImGui::BeginDisabled(!has_selection);
  if (ImGui::Button("Duplicate")) {
    state.scene_edited(scene.duplicate_light(static_cast<std::size_t>(selected)));
  }
  ImGui::SameLine();
  const editor::LightOrigin origin =
      has_selection ? scene.origin(static_cast<std::size_t>(selected)) : editor::LightOrigin::own;
  ImGui::BeginDisabled(origin == editor::LightOrigin::imported);  // set its intensity to 0
  if (ImGui::Button(origin == editor::LightOrigin::override ? "Revert" : "Delete")) {
    state.scene_edited(scene.delete_light(static_cast<std::size_t>(selected)));
  }
  ImGui::EndDisabled();
  ImGui::EndDisabled();

  // As tall as the list, up to six rows: the selected light's fields share the panel.
  const float rows = static_cast<float>(std::clamp<std::size_t>(scene.lights().size(), 2, 6));
  const float list_height = ImGui::GetTextLineHeightWithSpacing() * (rows + 0.4f);
  if (ImGui::BeginListBox("##lights", {-1.0f, list_height})) {
    for (std::size_t i = 0; i < scene.lights().size(); ++i) {
      const bool over = i < report.circles.size() && report.circles[i].over_cap;
      std::string label = scene.lights()[i].name + (over ? "  (over cap)" : "");
      if (scene.origin(i) == editor::LightOrigin::override) label += "  (changed)";
      label += "##" + std::to_string(i);
      if (over) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 120, 90, 255));
      if (ImGui::Selectable(label.c_str(), static_cast<int>(i) == selected)) {
        scene.select(static_cast<int>(i));
      }
      if (over) ImGui::PopStyleColor();
    }
    ImGui::EndListBox();
  }
  const int now_selected = scene.selected();
  if (now_selected >= 0 && now_selected < static_cast<int>(scene.lights().size())) {
    draw_light_fields(state, static_cast<std::size_t>(now_selected));
  }
  ImGui::End();
}

}  // namespace antumbra::editor_app
