// The edit session (antumbra/editor/edit_session.hpp), the logic the windowed editor and
// `edit --headless` both run, over a renderer that compiles through the one load path
// without a device: edits reach the renderer and the layer status, one undo order, a
// refused edit keeps itself and the last good graph, files changed on disk reload as
// transactions that never drop unsaved edits, a size the renderer refuses is not kept.

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/editor/edit_session.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "antumbra/editor/recovery_file.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::fixture;
namespace fs = std::filesystem;

// The RenderSession's part without a device: the one load path's read and compile, a
// plan swapped in only when nothing refused it, and what the session handed over.
class CompilingRenderer final : public Renderer {
 public:
  explicit CompilingRenderer(const fg::Registry& registry) : registry_(registry) {}

  base::Diagnostics load_graph(const fg::GraphSource& source, const fg::GraphEdit& edit) override {
    ++loads;
    fg::CompileOptions options;
    options.viewport = viewport_;
    auto plan = fg::compile_graph(source, registry_, options, edit);
    base::Diagnostics diagnostics = plan.diagnostics();
    if (!plan.ok()) return diagnostics;
    if (refuse) diagnostics.append(refuse(plan.value(), viewport_));
    if (!diagnostics.has_errors()) plan_ = std::move(plan.value());
    return diagnostics;
  }
  [[nodiscard]] const fg::Plan* plan() const override { return plan_ ? &*plan_ : nullptr; }
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shaders; }
  [[nodiscard]] std::vector<std::string> passes_reading(
      const std::vector<std::string>& files) const override {
    return files.empty() || !plan_ ? std::vector<std::string>{}
                                   : std::vector<std::string>{"tonemap"};
  }
  void set_scene(scene::Scene scene) override {
    ++scene_uploads;
    lights = scene.lights;
  }
  void set_lights(std::vector<scene::PointLight> l) override { lights = std::move(l); }
  void set_camera(const scene::Camera& c) override { camera = c; }
  [[nodiscard]] fg::Extent2D viewport() const override { return viewport_; }
  void set_viewport(fg::Extent2D v) override { viewport_ = v; }

  // What the device would refuse after the compile (a broken shader, FG100).
  std::function<base::Diagnostics(const fg::Plan&, fg::Extent2D)> refuse;
  std::vector<std::string> shaders;
  int loads = 0;
  int scene_uploads = 0;
  std::vector<scene::PointLight> lights;
  scene::Camera camera;

 private:
  const fg::Registry& registry_;
  std::optional<fg::Plan> plan_;
  fg::Extent2D viewport_{64, 36};
};

base::Diagnostics broken_shader(const std::string& why) {
  base::Diagnostics out;
  out.add({codes::shader::kCompile, base::Severity::error, why, "tonemap.frag", "", 3, 1});
  return out;
}

// The maxLayers the running plan's light-layering pass was compiled with.
int running_cap(const Renderer& renderer) {
  const fg::Plan* plan = renderer.plan();
  if (plan == nullptr) return -1;
  for (const auto& pass : plan->passes) {
    if (pass.type == "light-layering") return pass.params.at("maxLayers").get<int>();
  }
  return -1;
}

class EditSessionTest : public ::testing::Test {
 protected:
  // The lamps (cap 3 fits, lamp c at 1.5 needs 4) and the live fixture with a cap of 3.
  EditSessionTest() {
    scene_file_ = dir_.copy(fixture("lamps.json"), "scene.json");
    graph_file_ = dir_.path() / "graph.json";
    std::string graph = testing::read(fixture("live_graph.json"));
    graph.replace(graph.find("\"maxLayers\": 4"), 14, "\"maxLayers\": 3");
    testing::write(graph_file_, graph);
    session_.emplace(renderer_, testing::take(SceneDocument::load(scene_file_)),
                     testing::take(GraphDocument::load(graph_file_, lookup_in(registry_))),
                     lookup_in(registry_), /*poll_interval_ms=*/0.0);
  }

  EditSession& edit() { return *session_; }
  std::size_t light(const std::string& name) {
    return static_cast<std::size_t>(edit().scene().find_light(name));
  }
  void move_lamp_c_between_a_and_b() {
    edit().scene_edited(edit().scene().set_position(light("lamp c"), {1.5f, 2.0f, 0.0f}));
  }
  // A file changed by another tool: a later modification time, so the watcher sees it.
  void change_on_disk(const fs::path& file, const std::string& text) {
    testing::write(file, text);
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  }

  testing::ScratchDir dir_;
  fg::Registry registry_ = testing::make_fake_registry();
  CompilingRenderer renderer_{registry_};
  fs::path scene_file_;
  fs::path graph_file_;
  std::optional<EditSession> session_;
};

TEST_F(EditSessionTest, StartLoadsTheGraphAndTheSceneIntoTheRenderer) {
  ASSERT_TRUE(edit().start()) << edit().diagnostics().to_text();
  EXPECT_EQ(renderer_.loads, 1);
  EXPECT_EQ(running_cap(renderer_), 3);
  EXPECT_EQ(renderer_.scene_uploads, 1);
  EXPECT_EQ(renderer_.lights.size(), edit().scene().lights().size());
  EXPECT_EQ(renderer_.camera.position, edit().camera().camera().position);
  EXPECT_EQ(edit().graph_cap(), 3);
  EXPECT_EQ(edit().reload_summary(), "none yet");
  EXPECT_EQ(edit().shown_resource(), "ldr");
  EXPECT_FALSE(edit().report().over_cap());
}

TEST_F(EditSessionTest, AGraphThatDoesNotCompileFailsTheStartLocated) {
  std::string text = testing::read(graph_file_);
  text.replace(text.find("\"type\": \"lighting\""), 18, "\"type\": \"lightin\"");
  testing::write(graph_file_, text);
  session_.emplace(renderer_, testing::take(SceneDocument::load(scene_file_)),
                   testing::take(GraphDocument::load(graph_file_, lookup_in(registry_))),
                   lookup_in(registry_), 0.0);
  EXPECT_FALSE(edit().start());
  const base::Diagnostic* d = edit().diagnostics().find(codes::graph::kUnknownPassType);
  ASSERT_NE(d, nullptr) << edit().diagnostics().to_text();
  EXPECT_EQ(d->file, graph_file_.string());
  EXPECT_EQ(d->pointer, "/passes/1/type");
  EXPECT_GT(d->line, 0);
  EXPECT_EQ(renderer_.plan(), nullptr);
}

TEST_F(EditSessionTest, ALightEditReachesTheRendererAndTheLayerStatus) {
  ASSERT_TRUE(edit().start());
  move_lamp_c_between_a_and_b();
  EXPECT_EQ(renderer_.lights[light("lamp c")].position.x, 1.5f);
  EXPECT_EQ(renderer_.scene_uploads, 1) << "a light edit must not upload the scene again";
  EXPECT_EQ(renderer_.loads, 1) << "a light edit must not reload the graph";
  EXPECT_TRUE(edit().report().over_cap());
  // The cap is the graph's: raised through its reflection, it reaches plan and status.
  const EditResult raised = edit().set_param("layers", "maxLayers", 4);
  ASSERT_TRUE(raised.changed);
  EXPECT_EQ(running_cap(renderer_), 4);
  EXPECT_EQ(edit().graph_cap(), 4);
  EXPECT_FALSE(edit().report().over_cap());
  EXPECT_NE(edit().reload_summary().find("reloaded in"), std::string::npos);
}

TEST_F(EditSessionTest, UndoFollowsOneOrderAcrossSceneAndGraph) {
  ASSERT_TRUE(edit().start());
  move_lamp_c_between_a_and_b();
  edit().set_param("layers", "maxLayers", 4);
  ASSERT_TRUE(edit().undo());  // the cap, the later edit
  EXPECT_EQ(running_cap(renderer_), 3);
  EXPECT_EQ(renderer_.lights[light("lamp c")].position.x, 1.5f);
  ASSERT_TRUE(edit().undo());  // then the light
  EXPECT_EQ(renderer_.lights[light("lamp c")].position.x, 6.0f);
  EXPECT_FALSE(edit().report().over_cap());
  EXPECT_FALSE(edit().undo());
  ASSERT_TRUE(edit().redo());
  ASSERT_TRUE(edit().redo());
  EXPECT_EQ(running_cap(renderer_), 4);
  EXPECT_FALSE(edit().redo());
  EXPECT_TRUE(edit().dirty());
}

TEST_F(EditSessionTest, RemovingAPassOthersReadKeepsTheLastGoodGraphAndUndoRestoresIt) {
  ASSERT_TRUE(edit().start()) << edit().diagnostics().to_text();
  const std::string original = edit().graph().to_text();
  const auto remove = [&](GraphDocument& graph) {
    return GraphEdits(graph, registry_).remove_pass("lighting");
  };
  ASSERT_TRUE(edit().edit_graph(remove).changed);
  // tonemap reads hdr, which nobody writes now: located, and the running plan stays.
  EXPECT_TRUE(edit().graph_refused());
  const base::Diagnostic* error = edit().diagnostics().find(codes::graph::kReadNeverWritten);
  ASSERT_NE(error, nullptr) << edit().diagnostics().to_text();
  EXPECT_GT(error->line, 0);
  ASSERT_NE(renderer_.plan(), nullptr);
  EXPECT_EQ(renderer_.plan()->passes.size(), 3u);
  EXPECT_TRUE(edit().graph().dirty());

  ASSERT_TRUE(edit().undo());
  EXPECT_FALSE(edit().graph_refused()) << edit().diagnostics().to_text();
  EXPECT_EQ(edit().graph().to_text(), original);
  EXPECT_FALSE(edit().graph().dirty());
  ASSERT_TRUE(edit().redo());
  EXPECT_TRUE(edit().graph_refused());

  ASSERT_TRUE(edit().undo());

  // A refused connection changes nothing and reloads nothing.
  const int loads = renderer_.loads;
  const auto into_buffer = [&](GraphDocument& graph) {
    return GraphEdits(graph, registry_).connect({"lighting", "hdr"}, {"lighting", "assignment"});
  };
  EXPECT_EQ(edit().edit_graph(into_buffer).code, codes::graph::kPortKind);
  EXPECT_EQ(renderer_.loads, loads);
  EXPECT_EQ(edit().graph().to_text(), original);
}

TEST_F(EditSessionTest, AGestureIsOneUndoStepUntilReleased) {
  ASSERT_TRUE(edit().start());
  const auto a = light("lamp a");
  edit().open_gesture(DocKind::scene);
  for (int i = 1; i <= 3; ++i) {
    edit().scene_edited(edit().scene().set_position(a, {0.5f * static_cast<float>(i), 2.0f, 0}));
    edit().end_frame(true);  // the drag still holds it
    EXPECT_TRUE(edit().gesture_open());
  }
  edit().end_frame(false);
  EXPECT_FALSE(edit().gesture_open());
  ASSERT_TRUE(edit().undo());
  EXPECT_EQ(renderer_.lights[a].position.x, 0.0f);
  EXPECT_FALSE(edit().can_undo());
}

// Nothing is lost: the refused edit stays in the document (undoable, saved when asked)
// while the last good graph keeps running, and the diagnostics say why.
TEST_F(EditSessionTest, AnEditTheRendererRefusesKeepsTheEditAndTheLastGoodGraph) {
  ASSERT_TRUE(edit().start());
  renderer_.refuse = [](const fg::Plan& plan, fg::Extent2D) {
    for (const auto& pass : plan.passes) {
      if (pass.type == "light-layering" && pass.params.at("maxLayers") == 2)
        return broken_shader("no layer table for 2 layers");
    }
    return base::Diagnostics{};
  };
  const EditResult lowered = edit().set_param("layers", "maxLayers", 2);
  EXPECT_TRUE(lowered.changed);
  ASSERT_NE(edit().diagnostics().find(codes::shader::kCompile), nullptr);
  EXPECT_NE(edit().reload_summary().find("refused"), std::string::npos);
  EXPECT_EQ(running_cap(renderer_), 3) << "the last good graph keeps running";
  EXPECT_EQ(edit().graph_cap(), 2) << "the edit is kept in the document";
  EXPECT_TRUE(edit().graph().dirty());
  ASSERT_TRUE(edit().undo());
  EXPECT_FALSE(edit().diagnostics().has_errors());
  EXPECT_EQ(edit().graph_cap(), 3);
  EXPECT_FALSE(edit().graph().dirty());
}

TEST_F(EditSessionTest, AGraphFileChangedOnDiskReloadsAsATransaction) {
  ASSERT_TRUE(edit().start());
  const std::string good = testing::read(graph_file_);
  change_on_disk(graph_file_, "{ \"version\": 1,\n  \"passes\": [");
  edit().poll_files();
  const base::Diagnostic* syntax = edit().diagnostics().find("FG001");
  ASSERT_NE(syntax, nullptr) << edit().diagnostics().to_text();
  EXPECT_EQ(syntax->file, graph_file_.string());
  EXPECT_EQ(syntax->line, 2);
  EXPECT_GT(syntax->column, 0);
  EXPECT_EQ(running_cap(renderer_), 3);
  std::string unknown = good;
  unknown.replace(unknown.find("\"type\": \"lighting\""), 18, "\"type\": \"lightin\"");
  change_on_disk(graph_file_, unknown);
  edit().poll_files();
  const base::Diagnostic* type = edit().diagnostics().find(codes::graph::kUnknownPassType);
  ASSERT_NE(type, nullptr) << edit().diagnostics().to_text();
  EXPECT_EQ(type->pointer, "/passes/1/type");
  EXPECT_NE(renderer_.plan(), nullptr);
  // The status says it was refused, why first, and where; never "reloaded".
  EXPECT_TRUE(edit().graph_refused());
  const std::string refused =
      "the graph on disk is refused (1 error): FG030 unknown pass type "
      "'lightin'";
  EXPECT_EQ(edit().message().rfind(refused, 0), 0u) << edit().message();
  EXPECT_NE(edit().message().find(graph_file_.filename().string() + ":" +
                                  std::to_string(type->line) + ":" + std::to_string(type->column) +
                                  "); the last good graph keeps running"),
            std::string::npos)
      << edit().message();
  EXPECT_EQ(running_cap(renderer_), 3) << "the last good graph keeps running";
  std::string two = good;
  two.replace(two.find("\"maxLayers\": 3"), 14, "\"maxLayers\": 2");
  change_on_disk(graph_file_, two);
  edit().poll_files();
  EXPECT_FALSE(edit().diagnostics().has_errors()) << edit().diagnostics().to_text();
  EXPECT_EQ(running_cap(renderer_), 2);
  EXPECT_EQ(edit().graph_cap(), 2);
  EXPECT_EQ(edit().message(), "graph reloaded from disk");
  EXPECT_FALSE(edit().graph_refused());
  EXPECT_TRUE(edit().take_change_latency_ms().has_value());
  EXPECT_FALSE(edit().take_change_latency_ms().has_value()) << "a latency is reported once";
}

TEST_F(EditSessionTest, UnsavedEditsWinOverTheFileOnDiskAndShadersStillReload) {
  renderer_.shaders = {(dir_.path() / "tonemap.frag").string()};
  testing::write(renderer_.shaders[0], "void main() {}\n");
  ASSERT_TRUE(edit().start());
  edit().set_param("layers", "maxLayers", 5);
  const int loads = renderer_.loads;
  change_on_disk(graph_file_, testing::read(fixture("live_graph.json")));
  edit().reload_files({graph_file_, renderer_.shaders[0]});
  EXPECT_EQ(edit().graph_cap(), 5) << "the unsaved edit was dropped";
  EXPECT_TRUE(edit().graph().dirty());
  EXPECT_EQ(renderer_.loads, loads + 1) << "the shader change reloads the graph once";
  EXPECT_EQ(edit().message(), "shader change reloaded");
  EXPECT_NE(edit().reload_summary().find("passes rebuilt from edited shaders: tonemap"),
            std::string::npos)
      << edit().reload_summary();
  renderer_.refuse = [](const fg::Plan&, fg::Extent2D) { return broken_shader("syntax error"); };
  edit().reload_files({renderer_.shaders[0]});
  EXPECT_EQ(edit().message(), "shader change refused: the last good frame keeps running");
  EXPECT_EQ(running_cap(renderer_), 5);
}

// A script's reload: the graph file is read again even where the watcher could not see
// the write (same time and size), and a dirty graph still rebuilds its pipelines.
TEST_F(EditSessionTest, AReloadFromDiskNeedsNoVisibleChange) {
  ASSERT_TRUE(edit().start());
  const auto stamp = fs::last_write_time(graph_file_);
  std::string text = testing::read(graph_file_);
  text.replace(text.find("\"maxLayers\": 3"), 14, "\"maxLayers\": 5");
  testing::write(graph_file_, text);
  fs::last_write_time(graph_file_, stamp);
  edit().poll_files();
  EXPECT_EQ(running_cap(renderer_), 3) << "the watcher cannot see this write";
  edit().reload_from_disk();
  EXPECT_EQ(running_cap(renderer_), 5);
  EXPECT_EQ(edit().graph_cap(), 5);
  edit().set_param("layers", "maxLayers", 6);
  const int loads = renderer_.loads;
  edit().reload_from_disk();
  EXPECT_EQ(renderer_.loads, loads + 1);
  EXPECT_EQ(edit().graph_cap(), 6) << "the unsaved edit was dropped";
  EXPECT_FALSE(edit().diagnostics().has_errors());
}

// A scene file that no longer loads: the status names the first error and where it is, the
// scene that ran keeps running.
TEST_F(EditSessionTest, ARefusedSceneFileSaysWhyInTheStatus) {
  ASSERT_TRUE(edit().start());
  const int uploads = renderer_.scene_uploads;
  change_on_disk(scene_file_, "{ \"version\": 1,\n  \"lights\": [");
  edit().poll_files();
  EXPECT_EQ(edit().message().rfind("the scene on disk is refused (1 error): FG001 ", 0), 0u)
      << edit().message();
  EXPECT_NE(edit().message().find(scene_file_.filename().string() + ":2:"), std::string::npos)
      << edit().message();
  EXPECT_NE(edit().message().find("; the last good scene keeps running"), std::string::npos);
  EXPECT_EQ(renderer_.scene_uploads, uploads);
}

TEST_F(EditSessionTest, ASceneChangedOnDiskReplacesTheDocumentAndKeepsTheView) {
  ASSERT_TRUE(edit().start());
  ViewportCamera view = edit().camera();
  view.move({0.0f, 0.0f, 1.0f}, 2.0f);
  edit().set_camera(view);
  std::string text = testing::read(scene_file_);
  text.replace(text.find("\"lamp d\""), 8, "\"lamp z\"");
  change_on_disk(scene_file_, text);
  edit().poll_files();
  EXPECT_GE(edit().scene().find_light("lamp z"), 0);
  EXPECT_EQ(renderer_.scene_uploads, 2);
  EXPECT_EQ(renderer_.camera.position, view.camera().position);
  EXPECT_EQ(edit().message(), "scene reloaded from disk");
  // With unsaved edits the file waits; the edits are not lost.
  move_lamp_c_between_a_and_b();
  change_on_disk(scene_file_, testing::read(fixture("lamps.json")));
  edit().poll_files();
  EXPECT_EQ(edit().scene().lights()[light("lamp c")].position.x, 1.5f);
  EXPECT_EQ(edit().message(), "the scene changed on disk; your unsaved edits are kept");
}

TEST_F(EditSessionTest, OurOwnSavesAreNotReloaded) {
  ASSERT_TRUE(edit().start());
  move_lamp_c_between_a_and_b();
  edit().set_param("layers", "maxLayers", 4);
  ASSERT_TRUE(edit().save()) << edit().message();
  EXPECT_FALSE(edit().dirty());
  const int loads = renderer_.loads;
  edit().poll_files();
  EXPECT_EQ(renderer_.loads, loads);
  EXPECT_EQ(renderer_.scene_uploads, 1);
  EXPECT_NE(testing::read(graph_file_).find("\"maxLayers\": 4"), std::string::npos);
  // An undo after the save makes the status's "saved ..." untrue: it says what it did.
  EXPECT_EQ(edit().message().rfind("saved ", 0), 0u) << edit().message();
  ASSERT_TRUE(edit().undo());
  EXPECT_TRUE(edit().dirty());
  EXPECT_EQ(edit().message(), "undid a graph edit");
  ASSERT_TRUE(edit().redo());
  EXPECT_EQ(edit().message(), "redid a graph edit");
}

TEST_F(EditSessionTest, ASizeTheRendererRefusesIsNotKept) {
  ASSERT_TRUE(edit().start());
  renderer_.refuse = [](const fg::Plan&, fg::Extent2D size) {
    base::Diagnostics out;
    if (size.width > 1000) {
      out.add({codes::graph::kRealiseFailed, base::Severity::error, "too large", "", "", 0, 0});
    }
    return out;
  };
  EXPECT_TRUE(edit().resize({320, 180}));
  EXPECT_EQ(renderer_.viewport().width, 320u);
  EXPECT_FALSE(edit().resize({4000, 10}));
  EXPECT_EQ(renderer_.viewport().width, 320u);
  EXPECT_NE(edit().message().find("cannot render at 4000x10"), std::string::npos)
      << edit().message();
  EXPECT_FALSE(edit().diagnostics().has_errors());
}

TEST_F(EditSessionTest, AViewOfAResourceTheGraphCannotShowIsUndone) {
  ASSERT_TRUE(edit().start());
  edit().set_view_resource("hdr");
  EXPECT_EQ(edit().shown_resource(), "hdr");
  edit().set_view_resource("table");  // a buffer: FG072
  EXPECT_EQ(edit().message(), "cannot show 'table'");
  EXPECT_EQ(edit().view_resource(), "hdr");
  EXPECT_EQ(edit().shown_resource(), "hdr");
  edit().set_view_resource("");
  EXPECT_EQ(edit().shown_resource(), "ldr");
}

TEST_F(EditSessionTest, ClosingUnconfirmedKeepsUnsavedEdits) {
  ASSERT_TRUE(edit().start());
  move_lamp_c_between_a_and_b();
  const auto kept = edit().close_keeping_unsaved();
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NE(kept[0].find("scene.json"), std::string::npos) << kept[0];
  EXPECT_TRUE(fs::exists(RecoveryFile::path_for(scene_file_)));
  EXPECT_FALSE(fs::exists(RecoveryFile::path_for(graph_file_)));
}

}  // namespace
}  // namespace antumbra::editor
