// The windowed editor's state without a window: one undo order across the scene and the
// graph, a drag as one undo step, the navigation camera reaching the frame (and leaving
// the shadow cache correct when it comes back), and files changed on disk reloaded as
// transactions. lavapipe with validation + synchronization validation.

#include "editor_state.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>

#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/recovery_file.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/layering/layer_cap.hpp"
#include "gpu_test_support.hpp"
#include "register_builtin_passes.hpp"
#include "render_test_support.hpp"

namespace antumbra::render_testing {
namespace {

namespace fs = std::filesystem;
using editor_app::DocKind;
using editor_app::EditorState;

class EditorStateGpu : public RenderTest {
 protected:
  // The lamps fixture and layered-ssss with a cap of 3, copied where saves may go.
  std::unique_ptr<EditorState> open(runtime::RenderSession& session) {
    fs::copy_file(source_dir() / "tests/data/editor/lamps.json", dir_.path() / "scene.json");
    std::string graph = read(source_dir() / "data/graphs/layered-ssss.json");
    const auto at = graph.find("\"maxLayers\": 4");
    EXPECT_NE(at, std::string::npos);
    graph.replace(at, 14, "\"maxLayers\": 3");
    write(dir_.path() / "graph.json", graph);
    auto scene = editor::SceneDocument::load(dir_.path() / "scene.json");
    auto document = editor::GraphDocument::load(dir_.path() / "graph.json",
                                                editor::lookup_in(registry_.reflection()));
    EXPECT_TRUE(scene.ok() && document.ok());
    renderer_ = std::make_unique<editor_app::SessionRenderer>(session);
    auto state = std::make_unique<EditorState>(*renderer_, std::move(scene.value()),
                                               std::move(document.value()),
                                               editor::lookup_in(registry_.reflection()),
                                               /*poll_interval_ms=*/0.0);
    EXPECT_TRUE(state->start());
    return state;
  }

  static std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  static void write(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  }

  // The watcher compares modification times: make the change visible to it (a later mtime);
  // the state was made with a poll interval of 0, so this poll looks at once.
  static void poll_after_change(EditorState& state, const fs::path& changed) {
    fs::last_write_time(changed, fs::last_write_time(changed) + std::chrono::seconds(2));
    state.poll_files();
  }

  fgvk::PassRegistry registry_ = passes::builtin_pass_registry();
  std::unique_ptr<editor_app::SessionRenderer> renderer_;  // the state's, over the test's session
  gpu::testing::TempDir dir_;
};

TEST_F(EditorStateGpu, UndoFollowsOneOrderAcrossSceneAndGraph) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  const auto c = static_cast<std::size_t>(state->scene().find_light("lamp c"));
  state->scene_edited(state->scene().set_position(c, {1.5f, 2.0f, 0.0f}));
  EXPECT_TRUE(state->report().over_cap());
  state->set_param(state->layering_pass(), layering::kLayerCap.name, 4);
  EXPECT_EQ(state->graph_cap(), 4);
  EXPECT_FALSE(state->report().over_cap());
  EXPECT_FALSE(state->diagnostics().has_errors());
  state->undo();  // the cap, the later edit
  EXPECT_EQ(state->graph_cap(), 3);
  EXPECT_TRUE(state->report().over_cap());
  EXPECT_EQ(state->scene().lights()[c].position.x, 1.5f);
  state->undo();  // then the light
  EXPECT_EQ(state->scene().lights()[c].position.x, 6.0f);
  EXPECT_FALSE(state->report().over_cap());
  EXPECT_FALSE(state->can_undo());
  state->redo();
  state->redo();
  EXPECT_EQ(state->scene().lights()[c].position.x, 1.5f);
  EXPECT_EQ(state->graph_cap(), 4);
  session->render(1, nullptr);
  EXPECT_TRUE(state->dirty());
}

TEST_F(EditorStateGpu, AGestureIsOneUndoStepUntilReleased) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  const auto a = static_cast<std::size_t>(state->scene().find_light("lamp a"));
  state->open_gesture(DocKind::scene);
  for (int i = 1; i <= 3; ++i) {
    state->scene_edited(state->scene().set_position(a, {0.5f * static_cast<float>(i), 2.0f, 0.0f}));
    session->render(1, nullptr);
    state->end_frame(true);  // the drag still holds it
    EXPECT_TRUE(state->gesture_open());
  }
  state->end_frame(false);
  EXPECT_FALSE(state->gesture_open());
  state->scene_edited(state->scene().set_position(a, {9.0f, 2.0f, 0.0f}));  // its own step
  state->undo();
  EXPECT_EQ(state->scene().lights()[a].position.x, 1.5f);
  state->undo();
  EXPECT_EQ(state->scene().lights()[a].position.x, 0.0f);
  EXPECT_FALSE(state->can_undo());
}

TEST_F(EditorStateGpu, TheNavigationCameraReachesTheFrameAndComesBackExactly) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  session->render(2, nullptr);
  const gpu::HostImage scene_view = read_output(*session);
  editor::ViewportCamera camera = state->camera();
  camera.orbit({120.0f, -40.0f});
  camera.dolly(2.0f);
  state->set_camera(camera);
  session->render(2, nullptr);
  const gpu::HostImage orbited = read_output(*session);
  EXPECT_GT(max_abs_difference(scene_view, orbited), 0.1f) << "the camera did not reach the frame";
  // Faces culled for the orbited view were not redrawn; coming back must still be exact.
  state->reset_camera();
  session->render(2, nullptr);
  EXPECT_EQ(max_abs_difference(scene_view, read_output(*session)), 0.0f);
  expect_no_validation_errors(*session);
}

TEST_F(EditorStateGpu, FilesChangedOnDiskReloadAsTransactions) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  const fs::path graph = dir_.path() / "graph.json";
  const std::string good = read(graph);
  write(graph, "{ \"version\": 1,\n  \"passes\": [");
  poll_after_change(*state, graph);
  EXPECT_TRUE(state->diagnostics().has_errors());
  EXPECT_NE(state->reload_summary().find("refused"), std::string::npos);
  session->render(1, nullptr);  // the last good graph keeps running
  EXPECT_FALSE(is_blank(read_output(*session)));
  write(graph, good);
  poll_after_change(*state, graph);
  EXPECT_FALSE(state->diagnostics().has_errors());
  EXPECT_NE(state->reload_summary().find("reloaded in"), std::string::npos);
  session->render(1, nullptr);
  state->frame_presented();  // the latency the editor shows: file seen -> new frame
  EXPECT_NE(state->message().find("file seen -> new frame"), std::string::npos) << state->message();
  // A scene edited by another tool replaces the document; the view stays where it was.
  editor::ViewportCamera camera = state->camera();
  camera.move({0.0f, 0.0f, 1.0f}, 2.0f);
  state->set_camera(camera);
  const fs::path scene = dir_.path() / "scene.json";
  std::string text = read(scene);
  const auto at = text.find("\"lamp d\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 8, "\"lamp z\"");
  write(scene, text);
  poll_after_change(*state, scene);
  EXPECT_GE(state->scene().find_light("lamp z"), 0);
  EXPECT_EQ(state->camera().camera().position, camera.camera().position);
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
}

// What the panels show before anything happened must not read as a measurement or a
// reload: timings are "--" until frames were timed, and the first load is no reload.
TEST_F(EditorStateGpu, NothingIsReportedBeforeItHappened) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  EXPECT_EQ(state->reload_summary(), "none yet");
  EXPECT_EQ(state->pass_time_text("lighting"), "-- ms");
  state->refresh_timings();  // no frame rendered yet: nothing measured
  EXPECT_EQ(state->pass_time_text("lighting"), "-- ms");
  session->render(2, nullptr);
  state->refresh_timings();
  EXPECT_NE(state->pass_time_text("lighting"), "-- ms");
  EXPECT_NE(state->pass_time_text("lighting").find(" ms"), std::string::npos);
  expect_no_validation_errors(*session);
}

// An editor closed by --frames running out (nobody asked) keeps unsaved edits in recovery
// files and says so; a clean document leaves none.
TEST_F(EditorStateGpu, ClosingUnconfirmedKeepsUnsavedEdits) {
  OPEN_SESSION(session, {64, 36});
  auto state = open(*session);
  const auto c = static_cast<std::size_t>(state->scene().find_light("lamp c"));
  state->scene_edited(state->scene().set_position(c, {1.5f, 2.0f, 0.0f}));
  const auto kept = state->close_keeping_unsaved();
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NE(kept[0].find("scene.json"), std::string::npos) << kept[0];
  EXPECT_TRUE(fs::exists(editor::RecoveryFile::path_for(dir_.path() / "scene.json")));
  EXPECT_FALSE(fs::exists(editor::RecoveryFile::path_for(dir_.path() / "graph.json")));
  const std::string recovered = read(editor::RecoveryFile::path_for(dir_.path() / "scene.json"));
  EXPECT_NE(recovered.find("1.5"), std::string::npos);
  expect_no_validation_errors(*session);
}

}  // namespace
}  // namespace antumbra::render_testing
