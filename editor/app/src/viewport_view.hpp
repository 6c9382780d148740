#pragma once
// The 3D viewport's input and overlays. Input the panels do not take drives the
// navigation camera (right mouse looks, WASD/QE move, Alt+left or middle mouse orbit, wheel
// dolly, F focus on the selected light, Home back to the scene's camera) and the lights
// (click selects, dragging a light moves it on its horizontal plane, with Shift up and
// down; one undo step per drag). Overlays on the graph's image: every light's marker in
// its layer colour, over-cap lights and a warning's conflicting pairs in red, the
// selected light's range sphere. The geometry is editor::viewport's, tested without a window.

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/editor/editor_layout.hpp"
#include "antumbra/editor/viewport.hpp"
#include "editor_state.hpp"
#include "window.hpp"

namespace antumbra::editor_app {

class ViewportView {
 public:
  // `view`: the extent the camera renders (the graph's viewport); `shown`: the extent of
  // the image on screen; `area`: the viewport's rectangle in the window (framebuffer
  // pixels, beside the panels), where the image is fitted. Overlays and picking are off
  // when the shown image is not a camera view of the same aspect (an atlas, say).
  // `presses`: this frame's key presses (F, Home), taken from the window.
  void update(EditorState& state, const std::vector<KeyPress>& presses, glm::ivec2 view,
              glm::ivec2 shown, const editor::PixelRect& area);
  // A light drag holds the scene gesture open across frames.
  [[nodiscard]] bool dragging() const { return drag_.has_value(); }

 private:
  void navigate(EditorState& state, const std::vector<KeyPress>& presses, bool over_image);
  void edit_lights(EditorState& state, glm::ivec2 view, glm::vec2 mouse_image, bool over_image);
  void end_drag(EditorState& state);
  void draw_overlays(EditorState& state, glm::ivec2 view, const editor::PixelRect& rect,
                     glm::vec2 mouse_image, bool over_image);

  std::optional<editor::LightDrag> drag_;
  int drag_light_ = -1;
  bool looking_ = false;
  bool orbiting_ = false;
};

}  // namespace antumbra::editor_app
