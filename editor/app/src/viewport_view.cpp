#include "viewport_view.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "layer_colours.hpp"

namespace antumbra::editor_app {
namespace {

constexpr float kFlySpeed = 4.0f;  // metres per second; Shift x4
constexpr ImU32 kSelectedColour = IM_COL32(255, 255, 255, 255);
constexpr const char* kHelp =
    "RMB look  WASD/QE move  Alt+LMB/MMB orbit  wheel dolly  F focus  Home reset  "
    "LMB pick/drag light (Shift: height)";

// ImGui works in window coordinates, the swapchain in framebuffer pixels.
glm::vec2 to_framebuffer(ImVec2 p) {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  return {p.x * scale.x, p.y * scale.y};
}

ImVec2 to_window(glm::vec2 p) {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  return {p.x / std::max(scale.x, 1e-3f), p.y / std::max(scale.y, 1e-3f)};
}

bool same_aspect(glm::ivec2 a, glm::ivec2 b) {
  if (a.x <= 0 || a.y <= 0 || b.x <= 0 || b.y <= 0) return false;
  const float ra = static_cast<float>(a.x) / static_cast<float>(a.y);
  const float rb = static_cast<float>(b.x) / static_cast<float>(b.y);
  return std::abs(ra - rb) <= 0.02f * ra;
}

}  // namespace

void ViewportView::update(EditorState& state, const std::vector<KeyPress>& presses, glm::ivec2 view,
                          glm::ivec2 shown, const editor::PixelRect& area) {
  const bool camera_image = same_aspect(view, shown);
  const editor::PixelRect rect = editor::fit_image(shown, area);
  const glm::vec2 mouse_fb = to_framebuffer(ImGui::GetIO().MousePos);
  const bool over_image =
      camera_image && !ImGui::GetIO().WantCaptureMouse && rect.contains(mouse_fb);
  const glm::vec2 mouse_image = editor::to_image(rect, view, mouse_fb);
  navigate(state, presses, over_image);
  if (!camera_image) {
    end_drag(state);  // an atlas on screen: nothing to pick or drag
    return;
  }
  edit_lights(state, view, mouse_image, over_image);
  draw_overlays(state, view, rect, mouse_image, over_image);
}

void ViewportView::navigate(EditorState& state, const std::vector<KeyPress>& presses,
                            bool over_image) {
  if (drag_) return;  // the drag maps the cursor through the view it started in
  const ImGuiIO& io = ImGui::GetIO();
  editor::ViewportCamera camera = state.camera();
  bool changed = false;
  // A button pressed over the image owns the mouse until released, over panels or not.
  if (over_image && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) looking_ = true;
  if (over_image && (ImGui::IsMouseClicked(ImGuiMouseButton_Middle) ||
                     (io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left)))) {
    orbiting_ = true;
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) looking_ = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle) && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    orbiting_ = false;
  }
  const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  const bool moved = (delta.x != 0.0f || delta.y != 0.0f) && std::isfinite(delta.x);
  if (looking_ && moved) {
    camera.look(delta);
    changed = true;
  }
  if (orbiting_ && moved) {
    camera.orbit(delta);
    changed = true;
  }
  if (over_image && io.MouseWheel != 0.0f) {
    camera.dolly(io.MouseWheel);
    changed = true;
  }
  if (!io.WantCaptureKeyboard && !io.KeyCtrl) {
    glm::vec3 axes(0.0f);
    if (ImGui::IsKeyDown(GLFW_KEY_W)) axes.z += 1.0f;
    if (ImGui::IsKeyDown(GLFW_KEY_S)) axes.z -= 1.0f;
    if (ImGui::IsKeyDown(GLFW_KEY_D)) axes.x += 1.0f;
    if (ImGui::IsKeyDown(GLFW_KEY_A)) axes.x -= 1.0f;
    if (ImGui::IsKeyDown(GLFW_KEY_E)) axes.y += 1.0f;
    if (ImGui::IsKeyDown(GLFW_KEY_Q)) axes.y -= 1.0f;
    if (axes != glm::vec3(0.0f)) {
      camera.move(axes, kFlySpeed * (io.KeyShift ? 4.0f : 1.0f) * io.DeltaTime);
      changed = true;
    }
    const int selected = state.scene().selected();
    for (const KeyPress& press : presses) {
      if (press.mods != 0) continue;
      if (press.key == GLFW_KEY_F && selected >= 0 &&
          selected < static_cast<int>(state.scene().lights().size())) {
        camera.set_pivot(state.scene().lights()[static_cast<std::size_t>(selected)].position);
        changed = true;
      } else if (press.key == GLFW_KEY_HOME) {
        state.reset_camera();
        return;
      }
    }
  }
  if (changed) state.set_camera(camera);
}

void ViewportView::edit_lights(EditorState& state, glm::ivec2 view, glm::vec2 mouse_image,
                               bool over_image) {
  const ImGuiIO& io = ImGui::GetIO();
  auto& scene = state.scene();
  const scene::Camera& camera = state.camera().camera();
  if (over_image && !io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const int hit = editor::pick_light(scene.lights(), camera, view, mouse_image);
    scene.select(hit);
    if (hit >= 0) {
      const auto plane = io.KeyShift ? editor::DragPlane::vertical : editor::DragPlane::horizontal;
      drag_.emplace(scene.lights()[static_cast<std::size_t>(hit)].position, camera, view,
                    mouse_image, plane, state.drag_limit());
      drag_light_ = hit;
      state.open_gesture(DocKind::scene);
      state.set_drag_note(drag_->describe());
    }
  }
  if (!drag_) return;
  // Undo, a reload from disk or a delete may have taken the light away mid-drag.
  if (!state.gesture_open() || drag_light_ >= static_cast<int>(scene.lights().size())) {
    end_drag(state);
    return;
  }
  // The release frame still moves the light: a press and release replayed from the
  // queue carry the cursor to where the button came up.
  const auto index = static_cast<std::size_t>(drag_light_);
  if (const auto position = drag_->update(mouse_image)) {
    if (*position != scene.lights()[index].position) {
      state.scene_edited(scene.set_position(index, *position));
    }
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) end_drag(state);
}

void ViewportView::end_drag(EditorState& state) {
  drag_.reset();
  state.set_drag_note({});
}

void ViewportView::draw_overlays(EditorState& state, glm::ivec2 view, const editor::PixelRect& rect,
                                 glm::vec2 mouse_image, bool over_image) {
  const auto& lights = state.scene().lights();
  const editor::LayerReport& report = state.report();
  const scene::Camera& camera = state.camera().camera();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 clip_min = to_window({static_cast<float>(rect.x), static_cast<float>(rect.y)});
  const ImVec2 clip_max = to_window(
      {static_cast<float>(rect.x + rect.width), static_cast<float>(rect.y + rect.height)});
  draw->PushClipRect(clip_min, clip_max, true);
  const auto on_screen = [&](glm::vec3 world) -> std::optional<ImVec2> {
    const auto p = editor::project(camera, view, world);
    if (!p) return std::nullopt;
    return to_window(editor::to_target(rect, view, *p));
  };
  const float focal = editor::focal_pixels(camera, {rect.width, rect.height});
  // A warning's conflicting pairs: why the layout needs more layers than the cap.
  for (const auto& edge : report.edges) {
    if (!edge.witness || edge.a >= lights.size() || edge.b >= lights.size()) continue;
    const auto a = on_screen(lights[edge.a].position);
    const auto b = on_screen(lights[edge.b].position);
    if (a && b) draw->AddLine(*a, *b, kWarningColour, 2.5f);
  }
  const int selected = state.scene().selected();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const auto& light = lights[i];
    if (light.type == scene::LightType::directional) continue;
    float depth = 1.0f;
    const auto projected = editor::project(camera, view, light.position, &depth);
    if (!projected) continue;
    const ImVec2 centre = to_window(editor::to_target(rect, view, *projected));
    // The sphere's size on screen (framebuffer pixels) in ImGui's window units.
    const float scale = std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1e-3f);
    const float radius = std::clamp(light.size * focal / depth / scale, 4.0f, 14.0f);
    const int layer = i < report.layer.size() ? report.layer[i] : editor::kNoShadowLayer;
    const ImU32 colour = layer_colour(layer);
    draw->AddCircleFilled(centre, radius, with_alpha(colour, 170));
    draw->AddCircle(centre, radius, IM_COL32(0, 0, 0, 200), 0, 1.0f);
    if (i < report.circles.size() && report.circles[i].over_cap) {
      draw->AddCircle(centre, radius + 4.0f, kWarningColour, 0, 3.0f);
    }
    if (static_cast<int>(i) != selected) continue;
    draw->AddCircle(centre, radius + 8.0f, kSelectedColour, 0, 1.5f);
    // The range sphere: how far the light reaches (what the layering colours).
    const float range = light.range;
    const glm::vec3 middle = light.position;
    for (const auto& line : editor::sphere_outline(camera, view, middle, range)) {
      std::vector<ImVec2> points;
      points.reserve(line.size());
      for (const glm::vec2 p : line) points.push_back(to_window(editor::to_target(rect, view, p)));
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), with_alpha(colour, 220), 0,
                        1.5f);
    }
    draw->AddText({centre.x + radius + 10.0f, centre.y - 7.0f}, kSelectedColour,
                  light.name.c_str());
  }
  if (over_image && !drag_) {
    const int hover = editor::pick_light(lights, camera, view, mouse_image);
    if (hover >= 0) {
      const auto& light = lights[static_cast<std::size_t>(hover)];
      const int layer = static_cast<std::size_t>(hover) < report.layer.size()
                            ? report.layer[static_cast<std::size_t>(hover)]
                            : editor::kNoShadowLayer;
      const std::string tip =
          light.name + (layer >= 0                        ? ": layer " + std::to_string(layer)
                        : layer == editor::kNoShadowLayer ? ": casts no shadow"
                                                          : ": over the cap (fallback)");
      ImGui::SetTooltip("%s", tip.c_str());
    }
  }
  // Along the image's bottom edge, which the layout keeps clear of the status bar.
  draw->AddText({clip_min.x + 6.0f, clip_max.y - ImGui::GetFontSize() - 5.0f},
                IM_COL32(230, 230, 230, 170), kHelp);
  draw->PopClipRect();
}

}  // namespace antumbra::editor_app
