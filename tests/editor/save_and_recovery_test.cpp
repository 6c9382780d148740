// Atomic saves (including a save interrupted just before the rename) and recovery files.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "antumbra/editor/atomic_file.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using namespace std::chrono_literals;
using testing::fixture;
using testing::read;
using testing::ScratchDir;

struct SimulatedCrash : std::runtime_error {
  SimulatedCrash() : std::runtime_error("simulated crash before rename") {}
};

TEST(AtomicSave, ReplacesTheFileAndLeavesNoTemporary) {
  ScratchDir dir;
  const auto file = dir.path() / "scene.json";
  testing::write(file, "old content\n");
  write_file_atomically(file, "new content\n");
  EXPECT_EQ(read(file), "new content\n");
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"scene.json"}));
  write_file_atomically(dir.path() / "fresh.json", "{}\n");  // no old file is fine too
  EXPECT_EQ(read(dir.path() / "fresh.json"), "{}\n");
}

TEST(AtomicSave, AnInterruptedSaveLeavesTheOldFileIntact) {
  ScratchDir dir;
  const auto file = dir.path() / "scene.json";
  const std::string old_bytes = "{\n  \"version\": 1\n}\n";
  testing::write(file, old_bytes);
  const std::string new_bytes(1 << 16, 'x');  // big enough to need several writes
  bool hook_ran = false;
  AtomicWriteHooks hooks;
  hooks.before_rename = [&](const std::filesystem::path& temporary) {
    hook_ran = true;
    // The new content is complete and beside the target, but not yet in its place.
    EXPECT_EQ(temporary.parent_path(), dir.path());
    EXPECT_EQ(read(temporary), new_bytes);
    EXPECT_EQ(read(file), old_bytes);
    throw SimulatedCrash();
  };
  EXPECT_THROW(write_file_atomically(file, new_bytes, hooks), SimulatedCrash);
  EXPECT_TRUE(hook_ran);
  EXPECT_EQ(read(file), old_bytes);
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"scene.json"}));
}

TEST(AtomicSave, AFailureSaysWhichFileAndWhy) {
  ScratchDir dir;
  const auto file = dir.path() / "missing-dir" / "scene.json";
  try {
    write_file_atomically(file, "{}");
    FAIL() << "expected SaveError";
  } catch (const SaveError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("temporary"), std::string::npos) << e.what();
  }
}

TEST(AtomicSave, KeepsTheFilePermissions) {
  ScratchDir dir;
  const auto file = dir.path() / "scene.json";
  testing::write(file, "{}\n");
  ASSERT_EQ(::chmod(file.c_str(), 0600), 0);
  write_file_atomically(file, "{\"a\": 1}\n");
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
}

TEST(SceneSave, AnInterruptedSaveKeepsTheFileAndTheUnsavedState) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  const std::string old_bytes = read(file);
  auto doc = testing::take(SceneDocument::load(file));
  ASSERT_TRUE(doc.set_range(0, 1.25f));
  doc.save_hooks().before_rename = [](const std::filesystem::path&) { throw SimulatedCrash(); };
  EXPECT_THROW(doc.save(), SimulatedCrash);
  EXPECT_EQ(read(file), old_bytes);
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"lamps.json"}));
  EXPECT_TRUE(doc.dirty());

  doc.save_hooks().before_rename = nullptr;
  doc.save();
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(read(file), doc.to_text());
  auto again = SceneDocument::load(file);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->lights()[0].range, 1.25f);
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"lamps.json"}));
}

TEST(SceneSave, SaveAsMovesTheDocument) {
  ScratchDir dir;
  auto doc = testing::take(SceneDocument::load(fixture("lamps.json")));
  doc.set_intensity(1, 3.0f);
  doc.save_as(dir.path() / "copy.json");
  EXPECT_EQ(doc.file(), dir.path() / "copy.json");
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(doc.recovery().path(), dir.path() / "copy.json.recovery");
  EXPECT_EQ(read(dir.path() / "copy.json"), doc.to_text());
}

TEST(Recovery, WrittenAtMostEveryIntervalWhileDirtyAndRemovedOnSave) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  auto doc = testing::take(SceneDocument::load(file));
  const auto recovery = dir.path() / "lamps.json.recovery";
  EXPECT_EQ(doc.recovery().path(), recovery);
  const auto t0 = RecoveryFile::Clock::time_point{} + 100s;

  EXPECT_FALSE(doc.autosave_if_due(t0));  // clean: nothing to protect
  EXPECT_FALSE(std::filesystem::exists(recovery));
  doc.set_range(0, 3.0f);
  EXPECT_TRUE(doc.autosave_if_due(t0));
  EXPECT_EQ(read(recovery), doc.to_text());
  doc.set_range(0, 3.5f);
  EXPECT_FALSE(doc.autosave_if_due(t0 + 1s));  // not due yet
  EXPECT_TRUE(doc.autosave_if_due(t0 + RecoveryFile::kDefaultInterval));
  EXPECT_EQ(read(recovery), doc.to_text());
  EXPECT_FALSE(doc.autosave_if_due(t0 + 60s));  // due, but nothing new
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"lamps.json", "lamps.json.recovery"}));

  doc.save();
  EXPECT_FALSE(std::filesystem::exists(recovery));
  doc.set_range(0, 4.0f);
  EXPECT_TRUE(doc.autosave_if_due(t0 + 120s));
  EXPECT_TRUE(std::filesystem::exists(recovery));
  doc.close();  // a clean end of the session
  EXPECT_FALSE(std::filesystem::exists(recovery));
}

TEST(Recovery, UndoBackToTheSavedStateRemovesIt) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  auto doc = testing::take(SceneDocument::load(file));
  doc.set_range(0, 3.0f);
  ASSERT_TRUE(doc.autosave_if_due(RecoveryFile::Clock::now()));
  doc.undo();
  EXPECT_FALSE(doc.autosave_if_due(RecoveryFile::Clock::now()));
  EXPECT_FALSE(std::filesystem::exists(doc.recovery().path()));
}

TEST(Recovery, ANewerRecoveryFileIsReportedAndRecovered) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  const std::string on_disk = read(file);
  std::string edited;
  {
    auto doc = testing::take(SceneDocument::load(file));
    EXPECT_FALSE(doc.recovery_available());
    doc.set_position(2, {1.5f, 2.0f, 1.0f});
    doc.set_name(3, "lamp renamed");
    ASSERT_TRUE(doc.autosave_if_due(RecoveryFile::Clock::now()));
    edited = doc.to_text();
    // The editor "crashes" here: no save, no close.
  }
  const auto recovery = RecoveryFile::path_for(file);
  std::filesystem::last_write_time(recovery, std::filesystem::last_write_time(file) + 10s);

  auto doc = testing::take(SceneDocument::load(file));
  EXPECT_TRUE(doc.recovery_available());
  EXPECT_EQ(doc.find_light("lamp renamed"), -1);  // load itself reads the file
  const base::Diagnostics diagnostics = doc.recover();
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.to_text();
  EXPECT_EQ(doc.find_light("lamp renamed"), 3);
  EXPECT_EQ(doc.lights()[2].position, glm::vec3(1.5f, 2.0f, 1.0f));
  EXPECT_TRUE(doc.dirty());  // recovered edits are not saved yet
  EXPECT_FALSE(doc.can_undo());
  EXPECT_EQ(doc.to_text(), edited);
  EXPECT_EQ(read(file), on_disk);
  doc.save();
  EXPECT_EQ(read(file), edited);
  EXPECT_FALSE(std::filesystem::exists(recovery));
}

TEST(Recovery, AnOlderRecoveryFileIsNotReported) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  const auto recovery = RecoveryFile::path_for(file);
  testing::write(recovery, read(file));
  std::filesystem::last_write_time(recovery, std::filesystem::last_write_time(file) - 10s);
  auto doc = testing::take(SceneDocument::load(file));
  EXPECT_FALSE(doc.recovery_available());
}

TEST(Recovery, ABadRecoveryFileIsADiagnosticAndChangesNothing) {
  ScratchDir dir;
  const auto file = dir.copy(fixture("lamps.json"));
  auto doc = testing::take(SceneDocument::load(file));
  const base::Diagnostics none = doc.recover();
  ASSERT_NE(none.find("ED020"), nullptr);

  testing::write(RecoveryFile::path_for(file), "{\n  \"version\": 1,\n  \"lights\": [\n");
  const std::string before = doc.to_text();
  const base::Diagnostics bad = doc.recover();
  ASSERT_TRUE(bad.has_errors());
  EXPECT_EQ(bad[0].line, 4);
  EXPECT_EQ(doc.to_text(), before);
  EXPECT_FALSE(doc.dirty());
}

TEST(Recovery, TheGraphDocumentHasItToo) {
  ScratchDir dir;
  const fg::Registry registry = testing::make_fake_registry();
  const auto file = dir.copy(fixture("graph.json"));
  auto doc = testing::take(GraphDocument::load(file, lookup_in(registry)));
  const EditResult edit = doc.set_param("layers", "maxLayers", 3);
  ASSERT_TRUE(edit) << edit.message;
  ASSERT_TRUE(doc.autosave_if_due(RecoveryFile::Clock::now()));
  std::filesystem::last_write_time(doc.recovery().path(),
                                   std::filesystem::last_write_time(file) + 10s);
  auto reloaded = testing::take(GraphDocument::load(file, lookup_in(registry)));
  EXPECT_TRUE(reloaded.recovery_available());
  EXPECT_FALSE(reloaded.recover().has_errors());
  EXPECT_EQ(reloaded.param("layers", "maxLayers")->value, 3);
  reloaded.close();
  EXPECT_FALSE(std::filesystem::exists(doc.recovery().path()));
}

}  // namespace
}  // namespace antumbra::editor
