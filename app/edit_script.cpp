#include "edit_script.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/edit_script_check.hpp"
#include "antumbra/editor/edit_session.hpp"
#include "antumbra/editor/fix_suggestion.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "antumbra/editor/layer_status.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/editor/viewport.hpp"
#include "antumbra/editor_app/session_renderer.hpp"
#include "antumbra/editor_app/windowed_editor.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "commands.hpp"
#include "device_memory_use.hpp"

namespace antumbra::app {
namespace {

namespace fs = std::filesystem;
using base::Json;

void print(const base::Diagnostics& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note) std::printf("  %s\n", base::format_text(d).c_str());
  }
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A script step failed: which one, where in the script, and why.
struct StepError {
  std::string message;
};

// The script's steps over the edit session the window runs (antumbra/editor/
// edit_session.hpp): a step does what a panel or the viewport does with the same input,
// then renders the frame that shows it, so the scripted tests test the window's logic.
// What is left here is the script's own: reading steps, checking expectations, timing.
class ScriptRun {
 public:
  ScriptRun(runtime::RenderSession& session, editor::EditSession& edit, fs::path script_dir)
      : session_(session), edit_(edit), script_dir_(std::move(script_dir)) {}

  // The first frame: the documents as loaded.
  bool start() {
    const bool started = edit_.start();
    print(edit_.diagnostics());
    if (!started) return false;
    render(1);
    return true;
  }

  void run_step(const Json& step) {
    if (step.contains("do")) {
      refusal_.reset();
      act(step.at("do").get<std::string>(), step);
    } else if (step.contains("expect")) {
      check(step.at("expect").get<std::string>(), step);
    } else {
      throw StepError{"a step needs \"do\" or \"expect\""};
    }
  }

  // The next step is {"expect": "refused"}: a refused edit is what it checks, not a failure.
  void expect_refusal_next(bool expected) { refusal_expected_ = expected; }

  void render(int frames) {
    gpu::CpuTimer wall;
    const std::clock_t cpu = std::clock();
    session_.render(frames, nullptr);
    frame_ms_.push_back(wall.elapsed_ms() / std::max(frames, 1));
    // The process's CPU time, lavapipe's threads included: on a busy machine the wall clock
    // measures the other programs too; this measures the frame's own work.
    frame_cpu_ms_.push_back(1000.0 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC /
                            std::max(frames, 1));
  }

  // The documents with edits no step saved: said at the end, so nothing is lost silently.
  [[nodiscard]] std::vector<std::string> unsaved() const {
    std::vector<std::string> files;
    if (edit_.scene().dirty()) files.push_back(edit_.scene().file().string());
    if (edit_.graph().dirty()) files.push_back(edit_.graph().file().string());
    return files;
  }

  [[nodiscard]] double median_frame_ms() const { return median_ms(frame_ms_, 0, frame_ms_.size()); }

  // The first and the last tenth of the frames' wall-clock medians: a long script (the
  // soak) shows whether frames grew slower as it went. Empty for fewer than 20 frames.
  [[nodiscard]] std::optional<std::pair<double, double>> frame_ms_trend() const {
    const std::size_t tenth = frame_ms_.size() / 10;
    if (tenth < 2) return std::nullopt;
    return std::make_pair(median_ms(frame_ms_, 0, tenth),
                          median_ms(frame_ms_, frame_ms_.size() - tenth, tenth));
  }

  // The medians of each tenth of the frames, in order, of the wall clock or (cpu) of the
  // process's CPU time; empty for fewer than 20 frames.
  [[nodiscard]] std::vector<double> frame_ms_tenths(bool cpu) const {
    const std::vector<double>& samples = cpu ? frame_cpu_ms_ : frame_ms_;
    const std::size_t tenth = samples.size() / 10;
    std::vector<double> medians;
    if (tenth < 2) return medians;
    for (std::size_t i = 0; i < 10; ++i) medians.push_back(median_ms(samples, i * tenth, tenth));
    return medians;
  }

 private:
  static double median_ms(const std::vector<double>& samples, std::size_t first,
                          std::size_t count) {
    if (count == 0) return 0.0;
    std::vector<double> sorted(samples.begin() + static_cast<std::ptrdiff_t>(first),
                               samples.begin() + static_cast<std::ptrdiff_t>(first + count));
    std::sort(sorted.begin(), sorted.end());
    return sorted[sorted.size() / 2];
  }

  fs::path resolve(const std::string& name) const {
    if (name == "$graph") return edit_.graph().file();
    if (name == "$scene") return edit_.scene().file();
    const fs::path p(name);
    return p.is_absolute() ? p : script_dir_ / p;
  }

  std::size_t light_index(const Json& step) const {
    return light_named(step.at("light").get<std::string>());
  }

  std::size_t light_named(const std::string& name) const {
    const int index = edit_.scene().find_light(name);
    if (index < 0) throw StepError{"no light named '" + name + "'"};
    return static_cast<std::size_t>(index);
  }

  static glm::vec2 vec2_of(const Json& v) {
    if (!v.is_array() || v.size() != 2) throw StepError{"expected [dx, dy]"};
    return {v[0].get<float>(), v[1].get<float>()};
  }

  static glm::vec3 vec3_of(const Json& v) {
    if (!v.is_array() || v.size() != 3) throw StepError{"expected [x, y, z]"};
    return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
  }

  // A reload as the window does it with files changed on disk, the graph file and every
  // shader taken as changed: a transaction that keeps the last good plan (and unsaved
  // edits of the graph).
  void reload() {
    edit_.reload_from_disk();
    last_reload_ = edit_.diagnostics();
    reload_ok_ = !last_reload_.has_errors();
    if (reload_ok_) {
      render(1);
      std::printf("  %s\n", edit_.reload_summary().c_str());
      print(session_.frame_diagnostics());  // a warning that still holds is said again
    } else {
      print(last_reload_);
      render(1);  // the last good plan keeps running
      std::printf("  reload refused; the last good frame keeps running\n");
    }
  }

  void act(const std::string& what, const Json& step) {
    if (act_on_view(what, step) || act_on_files(what, step) || act_on_graph(what, step)) return;
    if (what == "undo" || what == "redo") {
      const std::uint64_t graph_revision = edit_.graph().revision();
      if (!(what == "undo" ? edit_.undo() : edit_.redo())) throw StepError{"nothing to " + what};
      if (edit_.graph().revision() != graph_revision) note_graph_reload();
    } else if (what == "set-param") {
      set_param(step);
    } else {
      const editor::EditResult result = edit_scene(what, step);
      if (!result) throw StepError{"edit refused: " + result.message};
      edit_.scene_edited(result);
    }
    render(1);
  }

  // Steps that edit no document: frames, the camera, selection, a viewport drag.
  bool act_on_view(const std::string& what, const Json& step) {
    if (what == "frames") {
      render(step.value("count", 1));
    } else if (what == "camera") {
      navigate(step);
    } else if (what == "click") {
      edit_.scene().select(pick(step.at("at")));
      std::printf("  selected %s\n", selected_name().c_str());
    } else if (what == "viewport-drag") {
      viewport_drag(step);
    } else {
      return false;
    }
    return true;
  }

  // Steps on files: saves, another tool's write, a reload.
  bool act_on_files(const std::string& what, const Json& step) {
    if (what == "save" || what == "save-graph") {
      if (!edit_.save(what == "save" ? editor::DocKind::scene : editor::DocKind::graph)) {
        throw StepError{edit_.message()};
      }
    } else if (what == "write-file") {
      // Another tool (an editor, a script) replaces a file on disk.
      const fs::path target = resolve(step.at("path").get<std::string>());
      const std::string text = step.contains("text")
                                   ? step["text"].get<std::string>()
                                   : read_text(resolve(step.at("from").get<std::string>()));
      std::ofstream(target, std::ios::binary | std::ios::trunc) << text;
    } else if (what == "reload") {
      reload();
    } else if (what == "mark-memory") {
      memory_mark_ = settle_and_measure(session_.gpu());
      std::printf("  device memory: %s\n", describe(*memory_mark_).c_str());
    } else {
      return false;
    }
    return true;
  }

  // Structural graph edits (add-pass, connect, ...) as the node view makes them: one undo
  // step each, then a reload, whose outcome reload-ok and reload-failed check. False for
  // any other action.
  bool act_on_graph(const std::string& what, const Json& step) {
    const std::uint64_t revision = edit_.graph().revision();
    bool known = true;
    const editor::EditResult result = edit_.edit_graph([&](editor::GraphDocument& graph) {
      fg::CompileOptions options;
      options.viewport = {session_.viewport().width, session_.viewport().height};
      editor::GraphEdits edits(graph, session_.pass_registry().reflection(), options);
      auto made = editor::run_graph_step(edits, what, step);
      known = made.has_value();
      return made.value_or(editor::EditResult{});
    });
    if (!known) return false;
    if (!result) {
      refused(result, revision);
      return true;
    }
    if (!result.message.empty()) std::printf("  %s\n", result.message.c_str());
    if (result.changed) note_graph_reload();
    render(1);
    return true;
  }

  // A refused edit fails the step, unless the next step expects it (then it records what
  // refused it, and whether the graph stayed as it was).
  void refused(const editor::EditResult& result, std::uint64_t graph_revision) {
    const std::string why = (result.code.empty() ? "" : "[" + result.code + "] ") + result.message;
    refusal_ = Refusal{result.code, why, edit_.graph().revision() == graph_revision};
    if (!refusal_expected_) throw StepError{"edit refused: " + why};
    std::printf("  refused: %s\n", why.c_str());
  }

  // After a graph edit, or its undo or redo: the reload it made.
  void note_graph_reload() {
    last_reload_ = edit_.diagnostics();
    reload_ok_ = !last_reload_.has_errors();
    if (reload_ok_) {
      std::printf("  %s\n", edit_.reload_summary().c_str());
      return;
    }
    print(last_reload_);
    std::printf("  the graph does not compile; the last good frame keeps running\n");
  }

  // A parameter through the graph's reflection (range clamped), as the graph panel sets it.
  void set_param(const Json& step) {
    const std::uint64_t revision = edit_.graph().revision();
    const auto result = edit_.set_param(step.at("pass").get<std::string>(),
                                        step.at("name").get<std::string>(), step.at("value"));
    if (!result) {
      refused(result, revision);
      return;
    }
    if (!result.changed) return;
    print(edit_.diagnostics());
    if (edit_.diagnostics().has_errors()) throw StepError{"the edited graph was refused"};
  }

  // One undoable scene edit, as the lights and layers panels make them.
  editor::EditResult edit_scene(const std::string& what, const Json& step) {
    auto& scene = edit_.scene();
    if (what == "set-light") return scene.apply(light_index(step), light_changes(step));
    if (what == "add-light") {
      return scene.add_light(scene::LightType::point,
                             step.contains("position") ? vec3_of(step["position"])
                                                       : editor::SceneDocument::kNewLightPosition);
    }
    if (what == "duplicate-light") return scene.duplicate_light(light_index(step));
    if (what == "delete-light") return scene.delete_light(light_index(step));
    if (what == "apply-fix") {
      const editor::FixSuggestion fix = edit_.status().suggestion(scene);  // a copy
      if (fix.changes().empty()) throw StepError{"no fix to apply: " + fix.message};
      if (fix.changes().size() == 1) {
        std::printf("  fix: %s\n", fix.description().c_str());
      } else {  // several lights, one undo step: a line per light
        std::printf("  fix: change %zu lights (one undo step)\n", fix.changes().size());
        for (const editor::LayerFix& change : fix.changes())
          std::printf("    %s\n", change.description.c_str());
      }
      return editor::apply_fix(scene, fix);
    }
    throw StepError{"unknown action '" + what + "'"};
  }

  static editor::LightChanges light_changes(const Json& step) {
    editor::LightChanges c;
    if (step.contains("position")) c.position = vec3_of(step["position"]);
    if (step.contains("color")) c.color = vec3_of(step["color"]);
    if (step.contains("intensity")) c.intensity = step["intensity"].get<float>();
    if (step.contains("range")) c.range = step["range"].get<float>();
    if (step.contains("size")) c.size = step["size"].get<float>();
    if (step.contains("castsShadows")) c.casts_shadows = step["castsShadows"].get<bool>();
    if (step.contains("direction")) c.direction = vec3_of(step["direction"]);
    if (step.contains("angle")) c.spot_outer = step["angle"].get<float>();
    if (step.contains("innerAngle")) c.spot_inner = step["innerAngle"].get<float>();
    return c;
  }

  // The viewport as the window drives it: image pixels of the graph's viewport.
  [[nodiscard]] glm::ivec2 view_size() const {
    return {static_cast<int>(session_.viewport().width),
            static_cast<int>(session_.viewport().height)};
  }

  [[nodiscard]] const scene::Camera& camera() const { return edit_.camera().camera(); }

  // A pixel [x, y]; a light's name: where its centre is on screen; {"over": [x, y, z]}:
  // where that world point is on screen.
  [[nodiscard]] glm::vec2 pixel_of(const Json& at) const {
    if (at.is_object() && at.contains("over")) {
      const auto p = editor::project(camera(), view_size(), vec3_of(at["over"]));
      if (!p) throw StepError{"that point is behind the camera"};
      return *p;
    }
    if (at.is_string()) {
      const auto index = light_named(at.get<std::string>());
      const auto p = editor::project(camera(), view_size(), edit_.scene().lights()[index].position);
      if (!p) throw StepError{"'" + at.get<std::string>() + "' is behind the camera"};
      return *p;
    }
    if (!at.is_array() || at.size() != 2)
      throw StepError{"expected [x, y], a light's name or {\"over\": [x, y, z]}"};
    return {at[0].get<float>(), at[1].get<float>()};
  }

  [[nodiscard]] int pick(const Json& at) const {
    return editor::pick_light(edit_.scene().lights(), camera(), view_size(), pixel_of(at));
  }

  [[nodiscard]] std::string selected_name() const {
    const int s = edit_.scene().selected();
    return s >= 0 && s < static_cast<int>(edit_.scene().lights().size())
               ? "'" + edit_.scene().lights()[static_cast<std::size_t>(s)].name + "'"
               : std::string("nothing");
  }

  // The viewport's navigation, as the mouse and keys drive it in the window.
  void navigate(const Json& step) {
    if (step.value("reset", false)) edit_.reset_camera();
    editor::ViewportCamera view = edit_.camera();
    if (step.contains("pivot")) {
      view.set_pivot(
          edit_.scene().lights()[light_named(step["pivot"].get<std::string>())].position);
    }
    if (step.contains("orbit")) view.orbit(vec2_of(step["orbit"]));
    if (step.contains("look")) view.look(vec2_of(step["look"]));
    if (step.contains("dolly")) view.dolly(step["dolly"].get<float>());
    if (step.contains("move")) view.move(vec3_of(step["move"]), step.value("metres", 1.0f));
    edit_.set_camera(view);
    const auto& c = camera();
    std::printf("  camera at (%.2f, %.2f, %.2f) looking at (%.2f, %.2f, %.2f)\n", c.position.x,
                c.position.y, c.position.z, c.target.x, c.target.y, c.target.z);
    render(1);
  }

  // Press on a light, move in `steps` increments, release: one undoable gesture, as the
  // viewport's drag (editor_app's ViewportView). The grabbed point must end under the
  // cursor: within a pixel of `to` on screen and, for {"over": P}, within `tolerance`
  // metres (default 0.05) of P.
  void viewport_drag(const Json& step) {
    const int hit = pick(step.at("from"));
    if (hit < 0) throw StepError{"no light under the cursor where the drag starts"};
    const auto index = static_cast<std::size_t>(hit);
    edit_.scene().select(hit);
    const glm::vec2 from = pixel_of(step["from"]);
    const glm::vec2 to = pixel_of(step.at("to"));
    const std::string plane = step.value("plane", std::string("horizontal"));
    if (plane != "horizontal" && plane != "vertical") {
      throw StepError{"plane must be \"horizontal\" or \"vertical\""};
    }
    const editor::LightDrag drag(
        edit_.scene().lights()[index].position, camera(), view_size(), from,
        plane == "vertical" ? editor::DragPlane::vertical : editor::DragPlane::horizontal,
        edit_.drag_limit());
    std::printf("  %s\n", drag.describe().c_str());
    const int steps = std::max(1, step.value("steps", 4));
    edit_.open_gesture(editor::DocKind::scene);
    for (int i = 1; i <= steps; ++i) {
      const glm::vec2 cursor =
          from + (to - from) * (static_cast<float>(i) / static_cast<float>(steps));
      const auto position = drag.update(cursor);
      if (!position) continue;  // off the plane: the light stays where it was last put
      const auto result = edit_.scene().set_position(index, *position);
      if (!result) {
        edit_.end_frame(false);
        throw StepError{"edit refused: " + result.message};
      }
      edit_.scene_edited(result);
      render(1);
    }
    edit_.end_frame(false);  // the button is released
    const glm::vec3 p = edit_.scene().lights()[index].position;
    std::printf("  dragged '%s' to (%.3f, %.3f, %.3f)\n",
                edit_.scene().lights()[index].name.c_str(), p.x, p.y, p.z);
    check_drag_landed(step, drag, p, to);
  }

  void check_drag_landed(const Json& step, const editor::LightDrag& drag, glm::vec3 position,
                         glm::vec2 to) const {
    char text[320];
    const glm::vec3 grabbed = position - drag.offset();
    const auto on_screen = editor::project(camera(), view_size(), grabbed);
    if (!on_screen || glm::distance(*on_screen, to) > 1.0f) {
      char where[64] = "behind the camera";
      if (on_screen) {
        std::snprintf(where, sizeof where, "on screen %.1f px from the cursor",
                      glm::distance(*on_screen, to));
      }
      std::snprintf(text, sizeof text,
                    "the light did not end under the cursor: it is at (%.3f, %.3f, %.3f), %s; "
                    "the cursor's ray leaves the %s plane or the drag's limits "
                    "(far plane, %.1f m from its start)",
                    position.x, position.y, position.z, where,
                    std::string(editor::to_string(drag.plane())).c_str(), edit_.drag_limit());
      throw StepError{text};
    }
    const Json& target = step.at("to");
    if (!target.is_object() || !target.contains("over")) return;
    const glm::vec3 want = vec3_of(target["over"]);
    const float tolerance = step.value("tolerance", 0.05f);
    const float miss = glm::distance(grabbed, want);
    if (miss > tolerance) {
      std::snprintf(text, sizeof text,
                    "the light ended at (%.3f, %.3f, %.3f), %.3f m from the target (tolerance "
                    "%.3f m): the target is not on the %s drag plane",
                    position.x, position.y, position.z, miss, tolerance,
                    std::string(editor::to_string(drag.plane())).c_str());
      throw StepError{text};
    }
  }

  [[nodiscard]] bool frame_reports_layer_warning() const {
    const auto& messages = session_.last_report().messages();
    return std::any_of(messages.begin(), messages.end(),
                       [](const auto& m) { return m.code == codes::layering::kOverCap; });
  }

  void check(const std::string& what, const Json& step) {
    const auto& report = edit_.report();
    if (what == "warning" || what == "no-warning") {
      const bool want = what == "warning";
      if (report.over_cap() != want || frame_reports_layer_warning() != want) {
        throw StepError{std::string("expected ") + (want ? "a" : "no") +
                        " layer-cap warning; the model says " + (report.over_cap() ? "yes" : "no") +
                        " (" + std::to_string(report.layers_needed) + " layers needed, cap " +
                        std::to_string(report.cap) + "), this frame's report says " +
                        (frame_reports_layer_warning() ? "yes" : "no")};
      }
      for (const auto& w : report.warnings) std::printf("  warning: %s\n", w.message.c_str());
    } else if (what == "layers-needed") {
      const int want = step.at("value").get<int>();
      if (report.layers_needed != want) {
        throw StepError{"expected " + std::to_string(want) + " layers needed, got " +
                        std::to_string(report.layers_needed)};
      }
    } else if (what == "reload-ok") {
      if (!reload_ok_) throw StepError{"the last reload was refused"};
    } else if (what == "reload-failed") {
      if (reload_ok_) throw StepError{"the last reload succeeded"};
      const auto code = step.value("code", std::string());
      const int line = step.value("line", 0);
      const bool found = std::any_of(last_reload_.begin(), last_reload_.end(), [&](const auto& d) {
        return (code.empty() || d.code == code) && (line == 0 || d.line == line);
      });
      if (!found) {
        std::string seen;
        for (const auto& d : last_reload_) {
          if (d.severity == base::Severity::error) {
            seen += (seen.empty() ? "" : ", ") + d.code + " at line " + std::to_string(d.line);
          }
        }
        throw StepError{"no diagnostic with code '" + code + "' at line " + std::to_string(line) +
                        "; the reload reported " + (seen.empty() ? "no error" : seen)};
      }
    } else if (what == "file-contains" || what == "file-lacks") {
      const auto text = read_text(resolve(step.at("path").get<std::string>()));
      const bool has = text.find(step.at("text").get<std::string>()) != std::string::npos;
      if (has != (what == "file-contains")) {
        throw StepError{"the file " + std::string(has ? "contains" : "lacks") + " \"" +
                        step["text"].get<std::string>() + "\""};
      }
    } else if (what == "selected") {
      const auto& want = step.at("light");
      const std::string name = want.is_null() ? "nothing" : "'" + want.get<std::string>() + "'";
      if (selected_name() != name) throw StepError{"selected " + selected_name() + ", not " + name};
    } else if (what == "light-at") {
      const glm::vec3 want = vec3_of(step.at("position"));
      const glm::vec3 have = edit_.scene().lights()[light_index(step)].position;
      const float tolerance = step.value("tolerance", 1e-3f);
      if (glm::distance(want, have) > tolerance) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "the light is at (%.4f, %.4f, %.4f), %.4f m from the expected (%.4f, %.4f, "
                      "%.4f) (tolerance %.4f m)",
                      have.x, have.y, have.z, glm::distance(want, have), want.x, want.y, want.z,
                      tolerance);
        throw StepError{text};
      }
    } else if (what == "refused") {
      check_refused(step);
    } else if (what == "memory-within") {
      check_memory(step.value("percent", 1.0), step.value("extraAllocations", -1));
    } else if (what == "dirty") {
      if (edit_.scene().dirty() != step.at("value").get<bool>()) {
        throw StepError{std::string("the scene is ") + (edit_.scene().dirty() ? "" : "not ") +
                        "dirty"};
      }
    } else {
      throw StepError{"unknown expectation '" + what + "'"};
    }
  }

  // Device memory in use against the last mark-memory step's (docs/robustness.md, "Soak").
  // extra_allocations >= 0: at most that many more live allocations than at the mark (a
  // leak of small buffers hides in the bytes of a large atlas, not in the count).
  void check_memory(double percent, int extra_allocations) {
    if (!memory_mark_) throw StepError{"no mark-memory step came before"};
    const DeviceMemoryUse now = settle_and_measure(session_.gpu());
    std::printf("  device memory: %s (at the mark: %s)\n", describe(now).c_str(),
                describe(*memory_mark_).c_str());
    if (auto problem = memory_growth_problem(*memory_mark_, now, percent)) {
      throw StepError{*problem};
    }
    if (extra_allocations >= 0 &&
        now.allocations > memory_mark_->allocations + static_cast<std::size_t>(extra_allocations)) {
      throw StepError{"there are " + std::to_string(now.allocations - memory_mark_->allocations) +
                      " more device memory allocations than at the mark (at most " +
                      std::to_string(extra_allocations) + " allowed)"};
    }
  }

  void check_refused(const Json& step) const {
    if (!refusal_) throw StepError{"the step before was not refused"};
    const std::string code = step.value("code", std::string());
    if (!code.empty() && refusal_->code != code) {
      throw StepError{"refused with '" + refusal_->code + "', not '" + code +
                      "': " + refusal_->message};
    }
    if (!refusal_->unchanged) throw StepError{"the refused step changed the graph"};
  }

  struct Refusal {
    std::string code;
    std::string message;
    bool unchanged = true;  // the graph document as it was before the step
  };

  runtime::RenderSession& session_;
  editor::EditSession& edit_;
  fs::path script_dir_;
  base::Diagnostics last_reload_;
  bool reload_ok_ = true;
  std::optional<Refusal> refusal_;  // the last step's, for {"expect": "refused"}
  bool refusal_expected_ = false;
  std::vector<double> frame_ms_;
  std::vector<double> frame_cpu_ms_;  // parallel to frame_ms_
  std::optional<DeviceMemoryUse> memory_mark_;
};

std::string describe_step(const Json& step) {
  std::string s = step.contains("do") ? "do " + step["do"].get<std::string>()
                                      : "expect " + step.value("expect", std::string("?"));
  return s;
}

// Without --headless the edit runs in a window, which has no script.
int run_windowed(const EditOptions& options) {
  if (!options.script.empty()) {
    std::fprintf(stderr, "antumbra edit: --script runs headless; add --headless\n");
    return runtime::kExitUsage;
  }
  editor_app::WindowedOptions windowed{
      options.graph,  options.scene,      options.allow_outside_paths,
      options.device, options.validation, options.frames};
  windowed.screenshot = options.out;
  windowed.select = options.select;
  windowed.frame_log = options.frame_log;
  windowed.shots = options.shots;
  windowed.layout_file = options.layout_file;
  windowed.ui_scale = options.ui_scale;
  windowed.layout_report = options.layout_report;
  if (!parse_size(options.size, windowed.width, windowed.height)) {
    std::fprintf(stderr, "antumbra edit: --size must be WxH, got \"%s\"\n", options.size.c_str());
    return runtime::kExitUsage;
  }
  return editor_app::run_windowed_editor(windowed);
}

// The whole script before anything runs: a typo fails here, not silently later. Returns
// the exit code of the failure, or kExitOk with `script` loaded.
int load_script(const std::string& path, std::optional<base::JsonDocument>& script) {
  auto loaded = base::load_json_file(path);
  if (!loaded.ok()) {
    print(loaded.diagnostics());
    return runtime::exit_code_for(loaded.diagnostics());
  }
  const base::Diagnostics problems = editor::check_edit_script(loaded.value());
  if (!problems.empty()) {
    print(problems);
    std::printf("%zu problem(s) in the script; nothing was run\n", problems.size());
    return runtime::kExitDiagnostics;
  }
  script = std::move(loaded.value());
  return runtime::kExitOk;
}

// Every step runs, even after one failed, so one run reports every broken step. Returns
// how many failed.
int run_script_steps(ScriptRun& run, const base::JsonDocument& script,
                     const std::string& script_path) {
  int failures = 0;
  const auto& steps = script.root()["steps"];
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string pointer = "/steps/" + std::to_string(i);
    const auto location = script.position(pointer);
    std::printf("step %zu (%s:%d): %s\n", i, script_path.c_str(), location.line,
                describe_step(steps[i]).c_str());
    try {
      run.expect_refusal_next(i + 1 < steps.size() &&
                              steps[i + 1].value("expect", std::string()) == "refused");
      run.run_step(steps[i]);
    } catch (const StepError& e) {
      ++failures;
      std::printf("%s:%d:%d: error[%s]: step %zu failed: %s (at %s)\n", script_path.c_str(),
                  location.line, location.column, codes::editor::kStepFailed, i, e.message.c_str(),
                  pointer.c_str());
    } catch (const Json::exception& e) {
      ++failures;
      std::printf("%s:%d:%d: error[%s]: step %zu is malformed: %s (at %s)\n", script_path.c_str(),
                  location.line, location.column, codes::editor::kScriptMalformed, i, e.what(),
                  pointer.c_str());
    }
    std::fflush(stdout);
  }
  return failures;
}

void write_graph_output(runtime::RenderSession& session, const std::string& path) {
  session.write_image(session.executor()
                          .plan()
                          .resources.at(static_cast<std::size_t>(session.executor().plan().output))
                          .name,
                      path);
}

void print_edit_summary(const runtime::RenderSession& session, const ScriptRun& run, unsigned width,
                        unsigned height, int failures) {
  const auto timings = session.pass_timings();
  double gpu_ms = 0.0;
  for (const auto& t : timings) gpu_ms += t.gpu_ms;
  std::printf(
      "editor frame (%ux%u): %.2f ms wall median (edit + layer status + render + wait), "
      "%.3f ms GPU (sum of pass medians)\n",
      width, height, run.median_frame_ms(), gpu_ms);
  if (const auto trend = run.frame_ms_trend()) {
    std::printf(
        "editor frame, wall median of the first tenth of frames: %.2f ms; of the last: %.2f ms\n",
        trend->first, trend->second);
    std::printf("editor frame, wall median of each tenth of frames, ms:");
    for (const double ms : run.frame_ms_tenths(false)) std::printf(" %.2f", ms);
    std::printf("\neditor frame, CPU time (all threads) median of each tenth of frames, ms:");
    for (const double ms : run.frame_ms_tenths(true)) std::printf(" %.2f", ms);
    std::printf("\n");
  }
  for (const auto& file : run.unsaved()) {
    std::printf("warning: unsaved changes to %s were not saved (no \"save\" step after them)\n",
                file.c_str());
  }
  std::printf("%d step(s) failed\n", failures);
}

// The device is gone, the documents are not (docs/robustness.md, "Device loss"): unsaved
// edits go to recovery files, which the editor offers when it opens the files again.
int keep_work_after_device_loss(editor::EditSession& edit, const std::exception& e) {
  std::fprintf(stderr, "antumbra edit: error: %s\n", e.what());
  const std::vector<std::string> kept = edit.close_keeping_unsaved();
  for (const auto& line : kept) std::fprintf(stderr, "antumbra edit: %s\n", line.c_str());
  if (kept.empty()) std::fprintf(stderr, "antumbra edit: there were no unsaved changes\n");
  return runtime::kExitRuntime;
}

}  // namespace

int run_edit(const EditOptions& options) {
  if (!options.headless) return run_windowed(options);
  if (options.script.empty() && options.frames <= 0) {
    std::fprintf(stderr, "antumbra edit --headless needs --script FILE or --frames N\n");
    return runtime::kExitUsage;
  }
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(options.size, width, height)) {
    std::fprintf(stderr, "antumbra edit: --size must be WxH, got \"%s\"\n", options.size.c_str());
    return runtime::kExitUsage;
  }
  const runtime::DataPaths paths = runtime::find_data_paths();
  const fs::path graph_path =
      options.graph.empty() ? paths.graphs() / "layered-ssss.json" : fs::path(options.graph);
  const fs::path scene_path =
      options.scene.empty() ? paths.scenes() / "atrium.json" : fs::path(options.scene);

  // User input first: a bad script, scene or graph fails before the device starts.
  std::optional<base::JsonDocument> script;
  if (!options.script.empty()) {
    if (const int code = load_script(options.script, script); code != runtime::kExitOk) {
      return code;
    }
  }
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.viewport = {width, height};
  // The session's pass types, for the documents read before the device starts.
  const fgvk::PassRegistry registry = runtime::pass_registry(session_options);
  auto scene = editor::SceneDocument::open(scene_path, nullptr,
                                           {.allow_outside_paths = options.allow_outside_paths});
  auto graph = editor::GraphDocument::load(graph_path, editor::lookup_in(registry.reflection()));
  print(scene.diagnostics());
  print(graph.diagnostics());
  if (!scene.ok()) return runtime::exit_code_for(scene.diagnostics());
  if (!graph.ok()) return runtime::exit_code_for(graph.diagnostics());

  runtime::RenderSession session(paths, session_options);
  std::printf("device: %s%s\n", session.gpu().device_name().c_str(),
              options.validation ? " (validation + synchronization validation on)" : "");

  editor_app::SessionRenderer renderer(session);
  editor::EditSession edit(renderer, std::move(scene.value()), std::move(graph.value()),
                           editor::lookup_in(session.pass_registry().reflection()));
  ScriptRun run(
      session, edit,
      options.script.empty() ? fs::current_path() : fs::absolute(options.script).parent_path());
  int failures = 0;
  try {
    if (!run.start()) return runtime::kExitDiagnostics;
    failures = script ? run_script_steps(run, *script, options.script) : 0;
    if (options.frames > 0) run.render(options.frames);
    if (!options.out.empty()) write_graph_output(session, options.out);
  } catch (const std::exception& e) {
    if (!session.gpu().device_lost()) throw;
    return keep_work_after_device_loss(edit, e);
  }
  print_edit_summary(session, run, width, height, failures);
  return failures == 0 ? runtime::kExitOk : runtime::kExitDiagnostics;
}

}  // namespace antumbra::app
