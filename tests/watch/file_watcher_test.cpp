#include <gtest/gtest.h>

#include <fstream>

#include "antumbra/watch/file_watcher.hpp"

namespace fs = std::filesystem;
using antumbra::watch::FileWatcher;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("antumbra-watch-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// Moves the file's time forward so a rewrite within one timestamp tick still counts.
void touch_later(const fs::path& p) {
  fs::last_write_time(p, fs::last_write_time(p) + std::chrono::seconds(2));
}

}  // namespace

TEST(FileWatcher, ReportsNothingUntilAFileChanges) {
  TempDir dir;
  const auto a = dir.path / "a.json";
  write(a, "{}");
  FileWatcher watcher;
  watcher.add(a);
  EXPECT_TRUE(watcher.poll().empty());
  touch_later(a);
  const auto changed = watcher.poll();
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0], a);
  EXPECT_TRUE(watcher.poll().empty()) << "a change is reported once";
}

TEST(FileWatcher, SizeChangeWithTheSameTimeCounts) {
  TempDir dir;
  const auto a = dir.path / "a.glsl";
  write(a, "x");
  const auto time = fs::last_write_time(a);
  FileWatcher watcher;
  watcher.add(a);
  write(a, "xyz");
  fs::last_write_time(a, time);
  EXPECT_EQ(watcher.poll().size(), 1u);
}

TEST(FileWatcher, DeletionAndReappearanceAreChanges) {
  TempDir dir;
  const auto a = dir.path / "scene.json";
  write(a, "{}");
  FileWatcher watcher;
  watcher.add(a);
  fs::remove(a);
  EXPECT_EQ(watcher.poll().size(), 1u);
  EXPECT_TRUE(watcher.poll().empty());
  write(a, "{}");
  EXPECT_EQ(watcher.poll().size(), 1u);
}

TEST(FileWatcher, SetKeepsBaselinesOfFilesStillWatched) {
  TempDir dir;
  const auto a = dir.path / "a";
  const auto b = dir.path / "b";
  write(a, "1");
  write(b, "2");
  FileWatcher watcher;
  watcher.add(a);
  touch_later(a);  // changed before the set is replaced: must not be lost
  watcher.set({a, b});
  EXPECT_EQ(watcher.size(), 2u);
  const auto changed = watcher.poll();
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0], a);
}

TEST(FileWatcher, MissingFileIsWatchedUntilItAppears) {
  TempDir dir;
  const auto a = dir.path / "later.json";
  FileWatcher watcher;
  watcher.add(a);
  EXPECT_TRUE(watcher.poll().empty());
  write(a, "{}");
  EXPECT_EQ(watcher.poll().size(), 1u);
}
