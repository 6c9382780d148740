#pragma once
// The editor's ImGui panels. Each draws from the EditorState and forwards edits to it;
// none keeps document state of its own.

#include <imgui.h>

#include "editor_state.hpp"

namespace antumbra::editor_app {

// Call right after the widget that produced an edit, before forwarding it: a widget
// that just became active opens a gesture (one undo step for the whole drag).
inline void track_gesture(EditorState& state, DocKind kind) {
  if (ImGui::IsItemActivated()) state.open_gesture(kind);
}

// First-use placement: three columns over the top of the window, whatever its size.
void place_panel(int column, float height);

// Lights: list, select, add / duplicate / delete, and the selected light's fields.
void draw_lights_panel(EditorState& state);
// Layers: the cap k, live warnings, the top-down map and the suggested fix.
void draw_layers_panel(EditorState& state);
// Frame graph: passes in order (culled marked), GPU time, reflected parameters,
// the viewport's resource and the last reload's diagnostics.
void draw_graph_panel(EditorState& state);

}  // namespace antumbra::editor_app
