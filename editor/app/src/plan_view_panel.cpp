// The node view's "Plan" tab: the running graph's compiled plan as a timeline. One column
// per pass in execution order (as wide as its GPU time once measured, else equal), a row
// per resource with a bar over the passes that use it, bars of resources that share memory
// in one colour, barriers as ticks before the pass that waits on them, and the schedule's
// critical path and async-compute bound in the summary line.

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>

#include <imgui.h>

#include "node_view_panel.hpp"

namespace antumbra::editor_app {
namespace {

constexpr float kRow = 18.0f;
constexpr float kLabelWidth = 150.0f;
constexpr float kMinColumn = 28.0f;

// A colour per group of resources sharing memory, so that the eye links them.
ImU32 group_colour(std::size_t group) {
  constexpr std::array<ImU32, 6> kColours{
      IM_COL32(230, 150, 60, 255), IM_COL32(120, 200, 110, 255), IM_COL32(200, 110, 210, 255),
      IM_COL32(90, 200, 210, 255), IM_COL32(220, 210, 90, 255),  IM_COL32(240, 120, 130, 255)};
  return kColours[group % kColours.size()];
}

// Column edges: GPU time shares of the canvas once every pass was measured, equal before.
std::vector<float> column_edges(const editor::PlanView& plan, float x0, float width) {
  std::vector<float> edges{x0};
  const std::size_t n = plan.passes.size();
  if (n == 0) return edges;
  double total = 0.0;
  bool timed = true;
  for (const auto& p : plan.passes) {
    timed = timed && p.gpu_ms.has_value();
    if (p.gpu_ms) total += *p.gpu_ms;
  }
  const float free = std::max(0.0f, width - kMinColumn * static_cast<float>(n));
  for (const auto& p : plan.passes) {
    const float share =
        timed && total > 0.0 ? static_cast<float>(*p.gpu_ms / total) : 1.0f / static_cast<float>(n);
    edges.push_back(edges.back() + kMinColumn + free * share);
  }
  return edges;
}

// Group index per resource: resources linked by shares_with get one group.
std::map<std::string, std::size_t> memory_groups(const editor::PlanView& plan) {
  std::map<std::string, std::size_t> group;
  std::size_t next = 0;
  for (const auto& life : plan.lifetimes) {
    if (life.shares_with.empty() || group.count(life.resource) != 0) continue;
    std::vector<std::string> stack{life.resource};
    while (!stack.empty()) {
      const std::string name = stack.back();
      stack.pop_back();
      if (!group.emplace(name, next).second) continue;
      const auto it = std::find_if(plan.lifetimes.begin(), plan.lifetimes.end(),
                                   [&](const auto& l) { return l.resource == name; });
      if (it != plan.lifetimes.end())
        stack.insert(stack.end(), it->shares_with.begin(), it->shares_with.end());
    }
    ++next;
  }
  return group;
}

void summary_line(const editor::PlanView& plan) {
  ImGui::Text(
      "%zu passes, %zu culled, %zu disabled | transient heap %s (%s without aliasing, %s saved)",
      plan.passes.size(), plan.culled.size(), plan.disabled.size(),
      editor::byte_text(plan.heap_bytes).c_str(),
      editor::byte_text(plan.bytes_without_aliasing).c_str(),
      editor::byte_text(plan.bytes_saved).c_str());
  if (plan.schedule) {
    const auto& s = *plan.schedule;
    std::string path;
    for (const auto& name : s.critical_path) path += (path.empty() ? "" : " > ") + name;
    ImGui::Text(
        "critical path %.3f of %.3f ms serial (%s weights): async compute saves at most "
        "%.3f ms | %s",
        s.critical_ms, s.serial_ms, s.weights.c_str(), s.overlap_bound_ms, path.c_str());
  }
}

}  // namespace

void NodeViewPanel::draw_plan(EditorState& state) {
  (void)state;
  if (plan_.passes.empty()) {
    ImGui::TextDisabled("no plan yet: the graph has not compiled");
    return;
  }
  summary_line(plan_);
  ImGui::BeginChild("##plan timeline", {0.0f, 0.0f}, false, ImGuiWindowFlags_HorizontalScrollbar);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x - kLabelWidth, 200.0f);
  const std::vector<float> edges = column_edges(plan_, origin.x + kLabelWidth, width);
  const auto groups = memory_groups(plan_);
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  std::string hover;
  // The pass row: a box per pass, the critical path's outlined.
  for (std::size_t p = 0; p < plan_.passes.size(); ++p) {
    const auto& pass = plan_.passes[p];
    const ImVec2 lo{edges[p] + 1.0f, origin.y};
    const ImVec2 hi{edges[p + 1] - 1.0f, origin.y + 2.0f * kRow};
    draw->AddRectFilled(lo, hi, IM_COL32(60, 80, 110, 255), 3.0f);
    if (pass.critical) draw->AddRect(lo, hi, IM_COL32(255, 220, 120, 255), 3.0f, 0, 2.0f);
    draw->PushClipRect(lo, hi, true);
    draw->AddText({lo.x + 3.0f, lo.y + 1.0f}, IM_COL32(240, 240, 240, 255), pass.name.c_str());
    if (pass.gpu_ms) {
      std::array<char, 24> ms{};
      std::snprintf(ms.data(), ms.size(), "%.3f ms", *pass.gpu_ms);
      draw->AddText({lo.x + 3.0f, lo.y + kRow}, IM_COL32(200, 200, 200, 255), ms.data());
    }
    draw->PopClipRect();
    // Barriers before the pass: a tick per barrier on its left edge.
    for (std::size_t b = 0; b < pass.barriers.size(); ++b) {
      const float y = hi.y + 2.0f + static_cast<float>(b) * 3.0f;
      draw->AddLine({edges[p], y}, {edges[p] + 6.0f, y}, IM_COL32(255, 120, 90, 255), 2.0f);
    }
    if (mouse.x >= lo.x && mouse.x < hi.x && mouse.y >= lo.y && mouse.y < hi.y + 8.0f) {
      hover = pass.name + " (" + pass.type + ")" + (pass.critical ? ", on the critical path" : "");
      for (const auto& b : pass.barriers) hover += "\nbarrier " + b.text();
    }
  }
  // A row per resource: its lifetime over the passes.
  float y = origin.y + 2.0f * kRow + 12.0f;
  for (const auto& life : plan_.lifetimes) {
    draw->AddText({origin.x, y}, IM_COL32(210, 210, 210, 255), life.resource.c_str());
    if (life.first >= 0 && life.last >= life.first &&
        static_cast<std::size_t>(life.last) < plan_.passes.size()) {
      const auto g = groups.find(life.resource);
      const ImU32 colour = g != groups.end() ? group_colour(g->second)
                           : life.persistent ? IM_COL32(150, 150, 170, 255)
                                             : IM_COL32(110, 140, 180, 255);
      const ImVec2 lo{edges[static_cast<std::size_t>(life.first)] + 2.0f, y + 2.0f};
      const ImVec2 hi{edges[static_cast<std::size_t>(life.last) + 1] - 2.0f, y + kRow - 3.0f};
      draw->AddRectFilled(lo, hi, colour, 3.0f);
      if (mouse.x >= lo.x && mouse.x < hi.x && mouse.y >= lo.y && mouse.y < hi.y) {
        hover = life.resource + ": " + life.detail + ", passes " + std::to_string(life.first) +
                ".." + std::to_string(life.last) + (life.persistent ? ", persistent" : "") +
                (life.imported ? ", imported" : "");
        if (life.aliased)
          hover += "\nheap offset " + editor::byte_text(life.offset) + ", " +
                   editor::byte_text(life.bytes);
        for (const auto& other : life.shares_with) hover += "\nshares memory with " + other;
      }
    }
    y += kRow;
  }
  ImGui::Dummy({kLabelWidth + width, y - origin.y});
  ImGui::EndChild();
  if (!hover.empty()) ImGui::SetTooltip("%s", hover.c_str());
}

}  // namespace antumbra::editor_app
