#pragma once
// The editor's ImGui panels. Each draws from the EditorState and forwards edits to it;
// none keeps document state of its own.

#include <imgui.h>

#include "antumbra/editor/editor_layout.hpp"
#include "editor_state.hpp"

namespace antumbra::editor_app {

// Call right after the widget that produced an edit, before forwarding it: a widget
// that just became active opens a gesture (one undo step for the whole drag).
inline void track_gesture(EditorState& state, DocKind kind) {
  if (ImGui::IsItemActivated()) state.open_gesture(kind);
}

// A panel's place in the side column this frame (editor::EditorLayout's), and what
// ImGui made of it: the layout report reads the window as drawn.
struct PanelSlot {
  editor::Rect target;     // where the layout puts it, window units
  bool collapsed = false;  // the saved state on first show; then the title bar's
  editor::Rect shown;      // the window as ImGui placed it this frame
  bool drawn = false;
};

// ImGui::Begin for a column panel: at its slot (the layout places and sizes it; it
// cannot be moved by hand), collapsed or expanded from its title bar. Pair with End().
bool begin_panel(const char* title, PanelSlot& slot);

// Lights: list, select, add / duplicate / delete, and the selected light's fields.
void draw_lights_panel(EditorState& state, PanelSlot& slot);
// Layers: the cap k, live warnings, the top-down map and the suggested fix.
void draw_layers_panel(EditorState& state, PanelSlot& slot);
// Frame graph: passes in order (culled marked), GPU time, reflected parameters,
// the viewport's resource and the last reload's diagnostics.
void draw_graph_panel(EditorState& state, PanelSlot& slot);

}  // namespace antumbra::editor_app
