#pragma once
// The node view (docs/architecture.md, "The node view"): the strip under the viewport with
// two tabs. "Nodes" draws the graph file as passes with typed ports and resources as
// edges (the model is editor::NodeGraph with its layout and hit tests; this file only
// draws it with ImGui's draw lists and turns the mouse into the edit session's structural
// edits). "Plan" shows what the compiler decided for the running graph: passes on a
// timeline, lifetimes, shared memory, barriers and the schedule (editor::PlanView).

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "antumbra/editor/editor_layout.hpp"
#include "antumbra/editor/node_graph.hpp"
#include "antumbra/editor/node_layout.hpp"
#include "antumbra/editor/node_view.hpp"
#include "antumbra/editor/plan_view.hpp"
#include "editor_state.hpp"

namespace antumbra::editor_app {

class NodeViewPanel {
 public:
  // `log_targets`: print where the buttons and ports are on the screen whenever that
  // changes ("node view: at X Y: port lighting.hdr out"), for input scripts (--frame-log).
  explicit NodeViewPanel(bool log_targets = false) : log_targets_(log_targets) {}

  // Draws the strip in `area` (window units, below its splitter); nothing when empty.
  void draw(EditorState& state, const editor::Rect& area);

 private:
  struct WireDrag {
    editor::NodePortRef from;  // an output port
    bool active = false;
  };
  struct NodeDrag {
    int node = -1;
    glm::vec2 grab{0.0f};  // world offset of the cursor from the node's corner
    bool moved = false;
  };

  void refresh(EditorState& state);
  void draw_toolbar(EditorState& state);
  void draw_palette(EditorState& state);
  void draw_canvas(EditorState& state);
  void handle_mouse(EditorState& state, glm::vec2 origin, bool hovered);
  void finish_wire(EditorState& state, const editor::NodeHit& hit);
  void draw_edges(glm::vec2 origin) const;
  void draw_nodes(EditorState& state, glm::vec2 origin) const;
  void draw_wire(EditorState& state, glm::vec2 origin, glm::vec2 mouse);
  void draw_hover(const editor::NodeHit& hit) const;
  void draw_context_menu(EditorState& state);
  void store_positions(EditorState& state);
  void draw_plan(EditorState& state);
  void log_targets(glm::vec2 origin);

  editor::NodeGraph graph_;
  editor::GraphLayout layout_;
  editor::ViewTransform view_;
  editor::PlanView plan_;
  std::map<std::string, double, std::less<>> plan_times_;  // the GPU times plan_ was built with
  // What the model was built from: rebuilt when any of these changes.
  std::uint64_t revision_ = ~std::uint64_t{0};
  const void* plan_source_ = nullptr;
  std::size_t diagnostics_seen_ = ~std::size_t{0};
  bool refused_seen_ = false;
  bool fit_pending_ = true;
  bool show_plan_ = false;  // which of the two views the strip shows
  glm::vec2 canvas_size_{0.0f};
  WireDrag wire_;
  NodeDrag node_drag_;
  editor::NodeHit menu_target_;
  std::string palette_filter_;
  std::string rename_text_;
  std::string refusal_;  // the last refused structural edit, shown until the next edit
  bool log_targets_ = false;
  std::string logged_;  // what log_targets printed last
  glm::vec2 add_button_{0.0f};
};

}  // namespace antumbra::editor_app
