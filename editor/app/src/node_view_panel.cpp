#include "node_view_panel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

#include <imgui.h>

#include "antumbra/fg/plan_io.hpp"
#include "antumbra/fg/plan_schedule.hpp"

namespace antumbra::editor_app {
namespace {

using editor::NodeHit;
using editor::PortSide;

ImVec2 im(glm::vec2 v) {
  return {v.x, v.y};
}

glm::vec2 gv(ImVec2 v) {
  return {v.x, v.y};
}

constexpr ImU32 kImageWire = IM_COL32(110, 170, 255, 255);
constexpr ImU32 kBufferWire = IM_COL32(240, 200, 90, 255);
constexpr ImU32 kError = IM_COL32(235, 70, 60, 255);
constexpr ImU32 kAccept = IM_COL32(90, 220, 120, 255);

ImU32 wire_colour(fg::ResourceKind kind, bool faint) {
  const ImU32 c = kind == fg::ResourceKind::buffer ? kBufferWire : kImageWire;
  return faint ? (c & 0x00FFFFFFu) | (110u << 24u) : c;
}

// Green (cheap) to red (the most expensive pass of the frame), by the share of the
// slowest pass's time: where the frame's time goes, at a glance.
ImU32 heat_colour(double ms, double slowest) {
  const float t = slowest > 0.0 ? static_cast<float>(std::clamp(ms / slowest, 0.0, 1.0)) : 0.0f;
  const auto mix = [t](int a, int b) {
    return static_cast<int>(static_cast<float>(a) + t * static_cast<float>(b - a));
  };
  return IM_COL32(mix(45, 190), mix(110, 60), mix(70, 45), 255);
}

std::map<std::string, double, std::less<>> time_table(const EditorState& state) {
  std::map<std::string, double, std::less<>> out;
  for (const auto& t : state.timings())
    if (!t.gpu_samples.empty()) out[t.name] = t.gpu_ms;
  return out;
}

// The diagnostics of a node or port, one per line, for its hover.
std::string diagnostic_lines(const std::vector<base::Diagnostic>& list) {
  std::string out;
  for (const auto& d : list) {
    out +=
        (d.severity == base::Severity::error ? "error[" : "warning[") + d.code + "] " + d.message;
    out += "\n";
  }
  return out;
}

// Text that scales with the view (ImGui's font at the zoom), clipped to `clip`; none when
// too small to read.
void scaled_text(ImDrawList* draw, glm::vec2 at, ImU32 colour, const std::string& text, float zoom,
                 glm::vec2 clip_min, glm::vec2 clip_max) {
  const float size = ImGui::GetFontSize() * zoom;
  if (size < 6.0f) return;
  const ImVec4 clip(clip_min.x, clip_min.y, clip_max.x, clip_max.y);
  draw->AddText(ImGui::GetFont(), size, im(at), colour, text.c_str(), nullptr, 0.0f, &clip);
}

float scaled_width(const std::string& text, float zoom) {
  return ImGui::CalcTextSize(text.c_str()).x * zoom;
}

bool has_error(const std::vector<base::Diagnostic>& list) {
  return std::any_of(list.begin(), list.end(),
                     [](const auto& d) { return d.severity == base::Severity::error; });
}

// The plan's JSON with its schedule: over the measured GPU times once every pass has one
// (the live frame's critical path and async-compute bound), else over unit weights.
base::Json plan_with_schedule(const fg::Plan& plan,
                              const std::map<std::string, double, std::less<>>& times) {
  std::vector<double> weights;
  for (const fg::PlanPass& pass : plan.passes) {
    const auto it = times.find(pass.name);
    if (it == times.end()) break;
    weights.push_back(it->second);
  }
  const bool measured = weights.size() == plan.passes.size();
  if (!measured) weights = fg::unit_weights(plan);
  base::Json json = fg::plan_to_json(plan);
  try {
    const fg::Schedule schedule = fg::analyse_schedule(fg::schedule_input(plan, weights));
    json["schedule"] =
        fg::schedule_to_json(plan, schedule, measured ? "GPU ms, this session" : "unit");
  } catch (const std::invalid_argument&) {
    // A plan is acyclic by construction; without a schedule the tab shows the rest.
  }
  return json;
}

// The pass the last add_pass appended: the document's last pass.
std::string graph_after_add(const EditorState& state) {
  const base::Json& passes = state.graph().json()["passes"];
  return passes.empty() ? std::string() : passes.back().value("name", std::string());
}

}  // namespace

void NodeViewPanel::draw(EditorState& state, const editor::Rect& area) {
  if (area.empty()) return;
  ImGui::SetNextWindowPos({area.x, area.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({area.width, area.height}, ImGuiCond_Always);
  ImGui::Begin("Node view", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar |
                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  refresh(state);
  // Two buttons, not an ImGui tab bar: a button takes a click pressed and released within
  // one frame (ImGui 1.86's backend latches it), a tab does not, and lavapipe frames are slow.
  for (const bool plan : {false, true}) {
    if (plan) ImGui::SameLine();
    const bool current = show_plan_ == plan;
    if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetColorU32(ImGuiCol_TabActive));
    if (ImGui::SmallButton(plan ? "Plan" : "Nodes")) show_plan_ = plan;
    if (current) ImGui::PopStyleColor();
  }
  ImGui::Separator();
  if (show_plan_) {
    draw_plan(state);
  } else {
    draw_toolbar(state);
    draw_canvas(state);
  }
  ImGui::End();
}

// The node graph follows the document (every edit, undo and reload) and the compile's
// verdict; the layout keeps stored positions and places new nodes beside their neighbours.
void NodeViewPanel::refresh(EditorState& state) {
  const fg::Plan* plan = state.renderer().plan();
  const std::uint64_t revision = state.graph().revision();
  const std::size_t diagnostics = state.diagnostics().size();
  const bool refused = state.graph_refused();
  if (revision == revision_ && plan == plan_source_ && diagnostics == diagnostics_seen_ &&
      refused == refused_seen_) {
    auto times = time_table(state);
    if (times != plan_times_) {
      if (plan != nullptr) {
        plan_ = editor::build_plan_view(plan_with_schedule(*plan, times));
        set_pass_times(plan_, times);
      }
      plan_times_ = std::move(times);  // the nodes' heat colours and hovers read them too
    }
    return;
  }
  revision_ = revision;
  plan_source_ = plan;
  diagnostics_seen_ = diagnostics;
  refused_seen_ = refused;
  editor::CompileOutcome outcome;
  // A refused document's nodes carry its errors; the running plan is another graph's.
  outcome.plan = refused ? nullptr : plan;
  outcome.diagnostics = &state.diagnostics();
  const std::size_t nodes = graph_.nodes.size();
  const std::size_t edges = graph_.edges.size();
  graph_ = editor::build_node_graph(state.graph().json(), state.lookup(), outcome);
  // A pass added, removed or wired differently may move nodes: show the whole graph again.
  if (graph_.nodes.size() != nodes || graph_.edges.size() != edges) fit_pending_ = true;
  layout_ = editor::place_nodes(graph_, editor::layout_from_json(state.graph().json()));
  plan_times_ = time_table(state);
  plan_ = plan != nullptr ? editor::build_plan_view(plan_with_schedule(*plan, plan_times_))
                          : editor::PlanView{};
  set_pass_times(plan_, plan_times_);
}

void NodeViewPanel::draw_toolbar(EditorState& state) {
  if (ImGui::SmallButton("Fit")) fit_pending_ = true;
  ImGui::SameLine();
  add_button_ = gv(ImGui::GetCursorScreenPos()) + glm::vec2(20.0f, 6.0f);
  if (ImGui::SmallButton("Add pass")) {
    palette_filter_.clear();
    ImGui::OpenPopup("##palette");
  }
  draw_palette(state);
  ImGui::SameLine();
  if (ImGui::SmallButton("Auto layout")) {
    layout_ = editor::auto_layout(graph_);
    store_positions(state);
    fit_pending_ = true;
  }
  ImGui::SameLine();
  ImGui::TextDisabled(
      "zoom %.0f %%  |  drag from an output to an input to connect; right-click "
      "for more",
      view_.zoom() * 100.0f);
  if (!refusal_.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.95f, 0.4f, 0.35f, 1.0f), "%s", refusal_.c_str());
  }
}

// A searchable list of every registered pass type: a click adds one (one undo step).
void NodeViewPanel::draw_palette(EditorState& state) {
  if (!ImGui::BeginPopup("##palette")) return;
  std::array<char, 128> filter{};
  std::strncpy(filter.data(), palette_filter_.c_str(), filter.size() - 1);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  // Enter takes the first type that matches.
  const bool enter = ImGui::InputTextWithHint("##filter", "search pass types", filter.data(),
                                              filter.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  palette_filter_ = filter.data();
  bool first = true;
  const fg::Registry& registry = state.session().pass_registry().reflection();
  for (const std::string& type : registry.types()) {
    if (!palette_filter_.empty() && type.find(palette_filter_) == std::string::npos) continue;
    const bool take = enter && first;
    first = false;
    if (ImGui::Selectable(type.c_str()) || take) {
      const editor::EditResult r = state.edit_structure([&](auto& e) { return e.add_pass(type); });
      refusal_ = r.ok ? "" : r.message;
      if (r.ok) state.select_pass(graph_after_add(state));
      ImGui::CloseCurrentPopup();
    }
    if (ImGui::IsItemHovered()) {
      const fg::PassDesc* desc = registry.find(type);
      if (desc != nullptr && !desc->description.empty())
        ImGui::SetTooltip("%s", desc->description.c_str());
    }
  }
  ImGui::EndPopup();
}

void NodeViewPanel::draw_canvas(EditorState& state) {
  const glm::vec2 origin = gv(ImGui::GetCursorScreenPos());
  const glm::vec2 size = glm::max(gv(ImGui::GetContentRegionAvail()), glm::vec2(1.0f));
  canvas_size_ = size;
  ImGui::InvisibleButton("##canvas", im(size),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  if (fit_pending_) {
    view_ = editor::fit_to_view(layout_.bounds(), editor::WorldRect{glm::vec2(0.0f), size});
    fit_pending_ = false;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(im(origin), im(origin + size), true);
  draw->AddRectFilled(im(origin), im(origin + size), IM_COL32(24, 26, 30, 255));
  draw_edges(origin);
  draw_nodes(state, origin);
  handle_mouse(state, origin, hovered);
  draw->PopClipRect();
  if (log_targets_) log_targets(origin);
  draw_context_menu(state);
  // Errors the compiler located at no pass: over the canvas's corner.
  std::string graph_level = diagnostic_lines(graph_.graph_diagnostics);
  if (!graph_level.empty()) {
    draw->AddText(im(origin + glm::vec2(8.0f, 6.0f)), kError, graph_level.c_str());
  }
}

void NodeViewPanel::draw_edges(glm::vec2 origin) const {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const editor::NodeEdge& edge : graph_.edges) {
    const editor::NodePort* port = graph_.port(edge.from);
    const editor::Bezier c = view_.to_screen(editor::edge_curve(layout_, edge));
    const ImU32 colour =
        wire_colour(port != nullptr ? port->kind : fg::ResourceKind::image, edge.previous_frame);
    draw->AddBezierCubic(im(origin + c.p0), im(origin + c.p1), im(origin + c.p2), im(origin + c.p3),
                         colour, std::max(1.0f, 2.0f * view_.zoom()));
    if (view_.zoom() >= 0.8f) {
      draw->AddText(im(origin + c.at(0.5f) + glm::vec2(4.0f, -16.0f)), IM_COL32(200, 200, 200, 200),
                    edge.resource.c_str());
    }
  }
  // Ends that lead nowhere: a short line with the resource's name.
  for (const editor::DanglingEnd& end : graph_.dangling) {
    const glm::vec2 a = origin + view_.to_screen(editor::port_anchor(layout_, end.port));
    const float dx = (end.port.side == PortSide::output ? 30.0f : -30.0f) * view_.zoom();
    const ImU32 colour =
        end.graph_output ? IM_COL32(255, 255, 255, 220) : IM_COL32(160, 160, 160, 160);
    draw->AddLine(im(a), im(a + glm::vec2(dx, 0.0f)), colour, 2.0f);
    if (view_.zoom() >= 0.6f) {
      const std::string label = end.graph_output ? end.resource + " (output)" : end.resource;
      const float w = ImGui::CalcTextSize(label.c_str()).x;
      draw->AddText(im(a + glm::vec2(dx > 0 ? dx + 4.0f : dx - 4.0f - w, -8.0f)), colour,
                    label.c_str());
    }
  }
}

void NodeViewPanel::draw_nodes(EditorState& state, glm::vec2 origin) const {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto& times = plan_times_;  // this frame's, from refresh()
  double slowest = 0.0;
  for (const auto& [name, ms] : times) slowest = std::max(slowest, ms);
  const float z = view_.zoom();
  for (std::size_t n = 0; n < graph_.nodes.size(); ++n) {
    const editor::Node& node = graph_.nodes[n];
    const auto box = view_.to_screen(layout_.boxes[n].rect());
    const glm::vec2 lo = origin + box.min;
    const glm::vec2 hi = origin + box.max;
    const float header = layout_.metrics.header_height * z;
    const bool inactive = node.culled || !node.enabled || !node.known_type;
    const auto time = times.find(node.name);
    const ImU32 head = inactive              ? IM_COL32(70, 70, 70, 255)
                       : time != times.end() ? heat_colour(time->second, slowest)
                                             : IM_COL32(60, 80, 110, 255);
    draw->AddRectFilled(im(lo), im(hi),
                        inactive ? IM_COL32(40, 40, 42, 235) : IM_COL32(48, 52, 60, 245), 4.0f);
    draw->AddRectFilled(im(lo), im({hi.x, lo.y + header}), head, 4.0f, ImDrawFlags_RoundCornersTop);
    const bool selected = state.selected_pass() == node.name;
    const ImU32 border = node.has_errors() ? kError
                         : selected        ? IM_COL32(255, 255, 255, 255)
                                           : IM_COL32(90, 90, 100, 255);
    draw->AddRect(im(lo), im(hi), border, 4.0f, 0, selected || node.has_errors() ? 2.5f : 1.0f);
    std::string title = node.name;
    if (time != times.end()) {
      std::array<char, 32> ms{};
      std::snprintf(ms.data(), ms.size(), "  %.3f ms", time->second);
      title += ms.data();
    }
    if (node.culled) title += "  (culled)";
    if (!node.enabled) title += "  (disabled)";
    scaled_text(draw, lo + glm::vec2(6.0f, 6.0f) * z, IM_COL32(240, 240, 240, 255), title, z, lo,
                {hi.x, lo.y + header});
    for (const PortSide side : {PortSide::input, PortSide::output}) {
      const auto& ports = node.ports(side);
      for (std::size_t p = 0; p < ports.size(); ++p) {
        const editor::NodePort& port = ports[p];
        const glm::vec2 a =
            origin +
            view_.to_screen(editor::port_anchor(
                layout_, editor::NodePortRef{static_cast<int>(n), side, static_cast<int>(p)}));
        const ImU32 colour = has_error(port.diagnostics) ? kError : wire_colour(port.kind, false);
        if (port.bound()) {
          draw->AddCircleFilled(im(a), 5.0f * std::max(z, 0.6f), colour);
        } else {
          draw->AddCircle(im(a), 5.0f * std::max(z, 0.6f), colour, 0, port.optional ? 1.0f : 2.0f);
        }
        const std::string label = port.declared ? port.name : port.name + "?";
        // Inputs label the left half of the row, outputs the right half.
        const float w = scaled_width(label, z);
        const glm::vec2 at = side == PortSide::input ? a + glm::vec2(9.0f, -8.0f) * z
                                                     : a + glm::vec2(-9.0f * z - w, -8.0f * z);
        const float mid = (lo.x + hi.x) * 0.5f;
        scaled_text(draw, at, port.declared ? IM_COL32(215, 215, 215, 255) : kError, label, z,
                    {side == PortSide::input ? lo.x : mid, lo.y},
                    {side == PortSide::input ? mid : hi.x, hi.y});
      }
    }
  }
}

void NodeViewPanel::handle_mouse(EditorState& state, glm::vec2 origin, bool hovered) {
  ImGuiIO& io = ImGui::GetIO();
  const glm::vec2 mouse = gv(io.MousePos) - origin;
  const NodeHit hit = editor::hit_test(graph_, layout_, view_, mouse);
  if (hovered && io.MouseWheel != 0.0f) view_.zoom_about(mouse, std::pow(1.15f, io.MouseWheel));
  const glm::vec2 delta = gv(io.MouseDelta);
  if (ImGui::IsItemActive() && (ImGui::IsMouseDragging(ImGuiMouseButton_Middle) ||
                                ImGui::IsMouseDragging(ImGuiMouseButton_Right))) {
    view_.pan_by(delta);
  }
  if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    if (hit.kind == NodeHit::Kind::output_port) {
      wire_ = {{hit.node, PortSide::output, hit.port}, true};
    } else if (hit.kind == NodeHit::Kind::node || hit.kind == NodeHit::Kind::input_port) {
      state.select_pass(graph_.nodes[static_cast<std::size_t>(hit.node)].name);
      node_drag_ = {
          hit.node,
          view_.to_world(mouse) - layout_.boxes[static_cast<std::size_t>(hit.node)].position,
          false};
    } else if (hit.kind == NodeHit::Kind::edge) {
      state.set_view_resource(graph_.edges[static_cast<std::size_t>(hit.edge)].resource);
    } else {
      node_drag_ = {};
    }
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    if (node_drag_.node >= 0) {
      layout_.boxes[static_cast<std::size_t>(node_drag_.node)].position =
          view_.to_world(mouse) - node_drag_.grab;
      node_drag_.moved = true;
    } else if (!wire_.active) {
      view_.pan_by(delta);
    }
  }
  if (wire_.active) draw_wire(state, origin, mouse);
  if (ImGui::IsItemDeactivated()) {
    if (wire_.active) finish_wire(state, hit);
    if (node_drag_.moved) store_positions(state);
    wire_ = {};
    node_drag_ = {};
  }
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) &&
      !ImGui::IsMouseDragging(ImGuiMouseButton_Right, 2.0f) && hit.kind != NodeHit::Kind::none) {
    menu_target_ = hit;
    rename_text_ = hit.node >= 0 ? graph_.nodes[static_cast<std::size_t>(hit.node)].name : "";
    ImGui::OpenPopup("##node menu");
  }
  if (hovered && !wire_.active && node_drag_.node < 0) draw_hover(hit);
  if (hovered && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete)) &&
      !state.selected_pass().empty()) {
    const std::string pass = state.selected_pass();
    const editor::EditResult r = state.edit_structure([&](auto& e) { return e.remove_pass(pass); });
    refusal_ = r.ok ? "" : r.message;
  }
}

// While a wire is dragged, the input under the cursor is asked first: a target the
// compiler would refuse is drawn red with its code and reason.
void NodeViewPanel::draw_wire(EditorState& state, glm::vec2 origin, glm::vec2 mouse) {
  const glm::vec2 from = view_.to_screen(editor::port_anchor(layout_, wire_.from));
  const NodeHit hit = editor::hit_test(graph_, layout_, view_, mouse);
  ImU32 colour = IM_COL32(230, 230, 230, 255);
  if (hit.kind == NodeHit::Kind::input_port) {
    const auto& src = graph_.nodes[static_cast<std::size_t>(wire_.from.node)];
    const auto& dst = graph_.nodes[static_cast<std::size_t>(hit.node)];
    const editor::EditResult check =
        state.check_connect({src.name, src.outputs[static_cast<std::size_t>(wire_.from.port)].name},
                            {dst.name, dst.inputs[static_cast<std::size_t>(hit.port)].name});
    colour = check.ok ? kAccept : kError;
    if (!check.ok) ImGui::SetTooltip("%s", check.message.c_str());
  }
  const editor::Bezier c = editor::wire_curve(from, mouse);
  ImGui::GetWindowDrawList()->AddBezierCubic(im(origin + c.p0), im(origin + c.p1),
                                             im(origin + c.p2), im(origin + c.p3), colour, 2.5f);
}

void NodeViewPanel::finish_wire(EditorState& state, const NodeHit& hit) {
  if (hit.kind != NodeHit::Kind::input_port) return;
  const auto& src = graph_.nodes[static_cast<std::size_t>(wire_.from.node)];
  const auto& dst = graph_.nodes[static_cast<std::size_t>(hit.node)];
  const editor::PortRef from{src.name, src.outputs[static_cast<std::size_t>(wire_.from.port)].name};
  const editor::PortRef to{dst.name, dst.inputs[static_cast<std::size_t>(hit.port)].name};
  const editor::EditResult r = state.edit_structure([&](auto& e) { return e.connect(from, to); });
  refusal_ = r.ok ? "" : r.message;
}

void NodeViewPanel::draw_hover(const NodeHit& hit) const {
  const auto& times = plan_times_;  // this frame's, from refresh()
  switch (hit.kind) {
    case NodeHit::Kind::input_port:
    case NodeHit::Kind::output_port: {
      const PortSide side =
          hit.kind == NodeHit::Kind::input_port ? PortSide::input : PortSide::output;
      const editor::NodePort* port = graph_.port({hit.node, side, hit.port});
      if (port == nullptr) return;
      ImGui::SetTooltip("%s%s", port->hover_text().c_str(),
                        ("\n" + diagnostic_lines(port->diagnostics)).c_str());
      return;
    }
    case NodeHit::Kind::node: {
      const editor::Node& node = graph_.nodes[static_cast<std::size_t>(hit.node)];
      std::string text =
          node.name + " (" + node.type + (node.known_type ? "" : ", unknown type") + ")";
      const auto t = times.find(node.name);
      if (t != times.end()) text += "\nGPU " + std::to_string(t->second) + " ms";
      if (node.culled) text += "\nculled: " + node.culled_reason;
      std::vector<base::Diagnostic> all = node.diagnostics;
      for (const auto& list : {&node.inputs, &node.outputs})
        for (const auto& p : *list)
          all.insert(all.end(), p.diagnostics.begin(), p.diagnostics.end());
      const std::string diags = diagnostic_lines(all);
      if (!diags.empty()) text += "\n" + diags;
      ImGui::SetTooltip("%s", text.c_str());
      return;
    }
    case NodeHit::Kind::edge: {
      const editor::NodeEdge& edge = graph_.edges[static_cast<std::size_t>(hit.edge)];
      const editor::NodePort* port = graph_.port(edge.from);
      ImGui::SetTooltip("%s%s\n%s\nclick: show it in the viewport", edge.resource.c_str(),
                        edge.previous_frame ? " (last frame's)" : "",
                        port != nullptr ? port->resource_text.c_str() : "");
      return;
    }
    case NodeHit::Kind::none:
      return;
  }
}

void NodeViewPanel::draw_context_menu(EditorState& state) {
  if (!ImGui::BeginPopup("##node menu")) return;
  const NodeHit hit = menu_target_;
  if (hit.node < 0 || static_cast<std::size_t>(hit.node) >= graph_.nodes.size()) {
    ImGui::EndPopup();
    return;
  }
  const editor::Node& node = graph_.nodes[static_cast<std::size_t>(hit.node)];
  editor::EditResult r;
  bool acted = false;
  if (hit.kind == NodeHit::Kind::input_port) {
    const auto& port = node.inputs[static_cast<std::size_t>(hit.port)];
    if (port.bound() && ImGui::MenuItem(("Disconnect " + port.name).c_str())) {
      r = state.edit_structure([&](auto& e) { return e.disconnect({node.name, port.name}); });
      acted = true;
    }
  } else if (hit.kind == NodeHit::Kind::output_port) {
    const auto& port = node.outputs[static_cast<std::size_t>(hit.port)];
    if (!port.bound() && ImGui::MenuItem(("New resource for " + port.name).c_str())) {
      r = state.edit_structure([&](auto& e) { return e.create_resource({node.name, port.name}); });
      acted = true;
    }
    if (port.bound() && ImGui::MenuItem(("Show " + port.resource + " in the viewport").c_str())) {
      state.set_view_resource(port.resource);
    }
  }
  std::array<char, 128> name{};
  std::strncpy(name.data(), rename_text_.c_str(), name.size() - 1);
  if (ImGui::InputText("name", name.data(), name.size(), ImGuiInputTextFlags_EnterReturnsTrue)) {
    const std::string to = name.data();
    r = state.edit_structure([&](auto& e) { return e.rename_pass(node.name, to); });
    acted = true;
  } else {
    rename_text_ = name.data();
  }
  if (ImGui::MenuItem(("Delete " + node.name).c_str())) {
    r = state.edit_structure([&](auto& e) { return e.remove_pass(node.name); });
    acted = true;
  }
  if (acted) {
    refusal_ = r.ok ? "" : r.message;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void NodeViewPanel::log_targets(glm::vec2 origin) {
  const auto at = [](glm::vec2 p) {
    return "node view: at " + std::to_string(static_cast<int>(std::lround(p.x))) + " " +
           std::to_string(static_cast<int>(std::lround(p.y))) + ": ";
  };
  std::string text = at(add_button_) + "button Add pass\n";
  for (std::size_t n = 0; n < graph_.nodes.size(); ++n) {
    for (const PortSide side : {PortSide::input, PortSide::output}) {
      const auto& ports = graph_.nodes[n].ports(side);
      for (std::size_t p = 0; p < ports.size(); ++p) {
        const editor::NodePortRef ref{static_cast<int>(n), side, static_cast<int>(p)};
        text += at(origin + view_.to_screen(editor::port_anchor(layout_, ref))) + "port " +
                graph_.nodes[n].name + "." + ports[p].name +
                (side == PortSide::input ? " in\n" : " out\n");
      }
    }
  }
  if (text == logged_) return;
  logged_ = text;
  std::fputs(text.c_str(), stdout);
  std::fflush(stdout);
}

// Moved nodes are kept in the graph file's "editor" block (the compiler ignores it), as
// one undo step.
void NodeViewPanel::store_positions(EditorState& state) {
  const base::Json& root = state.graph().json();
  const auto it = root.find("editor");
  const base::Json block = it != root.end() && it->is_object() ? *it : base::Json::object();
  const base::Json stored = editor::layout_to_json(graph_, layout_, block);
  const editor::EditResult r =
      state.edit_structure([&](auto& e) { return e.set_editor_block(stored); });
  refusal_ = r.ok ? "" : r.message;
}

}  // namespace antumbra::editor_app
