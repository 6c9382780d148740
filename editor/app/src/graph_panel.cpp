#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <limits>
#include <string>

#include <imgui.h>

#include "panels.hpp"

namespace antumbra::editor_app {
namespace {

using base::Json;

// A float control's value as the shortest decimal that reads back as the same float
// (5.8, not 5.800000190734863), so saved files stay as an artist would write them.
Json tidy(float value) {
  std::array<char, 32> text{};
  const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
  double shortest = value;
  if (ec == std::errc()) std::from_chars(text.data(), end, shortest);
  return shortest;
}

// One control per parameter, of the reflected type and within the reflected range. The
// edit is applied at once (the graph reloads), a drag being one undo step.
void draw_param(EditorState& state, const editor::PassView& pass, const editor::ParamView& p) {
  const std::string label = p.name + "##" + pass.name;
  if (!p.declared) {
    ImGui::TextDisabled("%s = %s (not in the reflection: kept)", p.name.c_str(),
                        p.value.dump().c_str());
    return;
  }
  Json value;
  bool changed = false;
  switch (p.type) {
    case fg::ParamType::boolean: {
      bool v = p.value.is_boolean() && p.value.get<bool>();
      changed = ImGui::Checkbox(label.c_str(), &v);
      value = v;
      break;
    }
    case fg::ParamType::integer: {
      int v = p.value.is_number() ? p.value.get<int>() : 0;
      const int lo = p.min ? static_cast<int>(*p.min) : 0;
      const int hi = p.max ? static_cast<int>(*p.max) : 0;  // 0, 0: unbounded
      changed = ImGui::DragInt(label.c_str(), &v, 0.1f, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
      value = v;
      break;
    }
    case fg::ParamType::number: {
      float v = p.value.is_number() ? p.value.get<float>() : 0.0f;
      const float lo = p.min ? static_cast<float>(*p.min) : -std::numeric_limits<float>::max();
      const float hi = p.max ? static_cast<float>(*p.max) : std::numeric_limits<float>::max();
      const float speed = p.min && p.max ? static_cast<float>(*p.max - *p.min) / 200.0f : 0.01f;
      changed =
          ImGui::DragFloat(label.c_str(), &v, speed, lo, hi, "%.3f", ImGuiSliderFlags_AlwaysClamp);
      value = tidy(v);
      break;
    }
    case fg::ParamType::enumeration: {
      const std::string current = p.value.is_string() ? p.value.get<std::string>() : "";
      if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (const auto& choice : p.choices) {
          if (ImGui::Selectable(choice.c_str(), choice == current) && choice != current) {
            changed = true;
            value = choice;
          }
        }
        ImGui::EndCombo();
      }
      break;
    }
    case fg::ParamType::string: {
      std::array<char, 256> text{};
      const std::string current = p.value.is_string() ? p.value.get<std::string>() : "";
      std::strncpy(text.data(), current.c_str(), text.size() - 1);
      changed = ImGui::InputText(label.c_str(), text.data(), text.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue);
      value = std::string(text.data());
      break;
    }
  }
  if (p.type != fg::ParamType::enumeration && p.type != fg::ParamType::boolean) {
    track_gesture(state, DocKind::graph);
  }
  if (!p.description.empty() && ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", p.description.c_str());
  }
  const ImVec2 field = ImGui::GetItemRectMin();
  state.log_target("graph panel", "param " + pass.name + "." + p.name, field.x + 30.0f,
                   field.y + 8.0f);
  if (changed) state.set_param(pass.name, p.name, value);
}

// The graph's image resources (as written in the file), any of which the window can show.
void draw_view_combo(EditorState& state) {
  const Json& root = state.graph().json();
  const std::string shown = state.shown_resource();
  if (!ImGui::BeginCombo("viewport", shown.c_str())) return;
  const std::string declared = root.value("output", std::string());
  if (root.contains("resources") && root["resources"].is_object()) {
    for (const auto& [name, desc] : root["resources"].items()) {
      if (!desc.is_object() || desc.value("kind", std::string("image")) != "image") continue;
      if (ImGui::Selectable(name.c_str(), name == shown)) {
        state.set_view_resource(name == declared ? std::string() : name);
      }
    }
  }
  ImGui::EndCombo();
}

void draw_passes(EditorState& state) {
  const auto& plan = state.session().executor().plan();
  const auto& timings = state.timings();
  double total = 0.0;
  bool measured = false;
  for (const auto& t : timings) {
    total += t.gpu_ms;
    measured = measured || !t.gpu_samples.empty();
  }
  if (measured) {
    ImGui::Text("%zu passes, %.3f ms GPU", plan.passes.size(), total);
  } else {
    ImGui::Text("%zu passes, GPU time not measured yet", plan.passes.size());
  }
  const auto views = state.graph().passes();
  for (const auto& view : views) {
    const auto* planned = plan.find_pass(view.name);
    const bool culled = std::find(plan.culled_passes.begin(), plan.culled_passes.end(),
                                  view.name) != plan.culled_passes.end();
    std::string title = view.name + " (" + view.type + ")";
    if (planned == nullptr) {
      title += culled ? "  [culled]" : "  [disabled]";
    } else {
      title += "  " + state.pass_time_text(view.name);
    }
    if (planned == nullptr) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(140, 140, 140, 255));
    // The node view's selection opens its pass here (once per new selection), highlighted.
    const bool selected = state.selected_pass() == view.name;
    if (selected && state.take_selection_reveal()) {
      ImGui::SetNextItemOpen(true);
      ImGui::SetScrollHereY(0.2f);
    }
    const ImGuiTreeNodeFlags flags = selected ? ImGuiTreeNodeFlags_Selected : 0;
    const bool open = ImGui::TreeNodeEx(view.name.c_str(), flags, "%s", title.c_str());
    if (ImGui::IsItemClicked()) state.select_pass(view.name);
    if (planned == nullptr) ImGui::PopStyleColor();
    if (!open) continue;
    for (const auto& p : view.params) draw_param(state, view, p);
    ImGui::TreePop();
  }
}

// Each realised resource: its lifetime in execution order and where it lives (its own
// memory, or an offset in the shared transient heap it aliases with others).
void draw_resources(EditorState& state) {
  const auto& plan = state.session().executor().plan();
  const std::string label = "resources (" + std::to_string(plan.resources.size()) + ", " +
                            std::to_string(plan.aliasing.bytes_saved() >> 10) +
                            " KiB saved by aliasing)";
  if (!ImGui::TreeNode("##resources", "%s", label.c_str())) return;
  for (const auto& r : plan.resources) {
    const std::string kind = r.kind == fg::ResourceKind::image
                                 ? std::string(fg::to_string(r.format))
                                 : std::to_string(r.buffer_size) + " B";
    std::string where = r.persistent ? "persistent" : "own memory";
    if (r.aliased) where = "heap @" + std::to_string(r.heap_offset >> 10) + " KiB";
    ImGui::Text("%s  %s  passes %d..%d  %s", r.name.c_str(), kind.c_str(), r.first_use, r.last_use,
                where.c_str());
  }
  ImGui::TreePop();
}

void draw_diagnostics(const EditorState& state) {
  for (const auto& d : state.diagnostics()) {
    if (d.severity == base::Severity::note) continue;
    ImGui::TextWrapped("%s", base::format_text(d).c_str());
  }
}

// The graph the document describes does not compile: its errors first, where they are
// seen without scrolling, then the passes that do run, the last good graph's, read-only.
void draw_refused(EditorState& state) {
  ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 120, 100, 255));
  ImGui::TextWrapped("The graph file is refused; the frame is the last good graph's.");
  draw_diagnostics(state);
  ImGui::PopStyleColor();
  ImGui::Separator();
  const auto& plan = state.session().executor().plan();
  ImGui::Text("running (last good graph): %zu passes", plan.passes.size());
  for (const auto& pass : plan.passes) {
    ImGui::BulletText("%s (%s)  %s", pass.name.c_str(), pass.type.c_str(),
                      state.pass_time_text(pass.name).c_str());
  }
}

}  // namespace

void draw_graph_panel(EditorState& state, PanelSlot& slot) {
  if (!begin_panel("Frame graph", slot)) {
    ImGui::End();
    return;
  }
  if (state.graph_refused()) {
    draw_refused(state);
    draw_resources(state);
    ImGui::End();
    return;
  }
  draw_view_combo(state);
  draw_passes(state);
  draw_resources(state);
  ImGui::Separator();
  ImGui::TextWrapped("last reload: %s", state.reload_summary().c_str());
  draw_diagnostics(state);
  ImGui::End();
}

}  // namespace antumbra::editor_app
