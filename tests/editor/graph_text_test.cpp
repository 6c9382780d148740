// Saving keeps the file's text (issue 31): every shipped graph loads and saves
// byte-identical, and one structural edit of any of them is a minimal diff: a rename one
// line, a removed pass only its lines (and the comma before it), an added pass only new
// lines (and a comma).
#include <algorithm>
#include <functional>

#include <gtest/gtest.h>

#include "antumbra/editor/graph_edits.hpp"
#include "editor_test_support.hpp"
#include "text_diff.hpp"

namespace antumbra::editor {
namespace {

using testing::read;
using testing::source_file;

std::vector<std::filesystem::path> shipped_graphs() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(source_file("data/graphs"))) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string without_comma(std::string line) {
  if (!line.empty() && line.back() == ',') line.pop_back();
  return line;
}

class GraphTextTest : public ::testing::Test {
 protected:
  GraphDocument load(const std::filesystem::path& file) {
    return testing::take(GraphDocument::load(file, lookup_in(registry_)));
  }
  // For every pass of every shipped graph: `edit`, `check` the diff it made, undo it and
  // find the file's text again.
  void each_pass(const std::function<void(GraphEdits&, const PassView&)>& edit,
                 const std::function<void(const testing::LineDiff&, const PassView&)>& check) {
    for (const auto& file : shipped_graphs()) {
      const std::string original = read(file);
      GraphDocument doc = load(file);
      GraphEdits edits(doc, registry_);
      for (const PassView& pass : doc.passes()) {
        SCOPED_TRACE(file.filename().string() + ": " + pass.name);
        edit(edits, pass);
        check(testing::line_diff(original, doc.to_text()), pass);
        ASSERT_TRUE(doc.undo());
        EXPECT_EQ(doc.to_text(), original);
      }
    }
  }
  fg::Registry registry_ = testing::make_fake_registry();
};

TEST_F(GraphTextTest, EveryShippedGraphSavesByteIdentical) {
  const testing::ScratchDir dir;
  const auto files = shipped_graphs();
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    GraphDocument doc = load(file);
    EXPECT_EQ(doc.to_text(), read(file)) << file;
    doc.save_as(dir.path() / file.filename());
    EXPECT_EQ(read(dir.path() / file.filename()), read(file)) << file;
  }
}

TEST_F(GraphTextTest, ARenameOfAnyPassIsAOneLineDiff) {
  each_pass([&](GraphEdits& edits,
                const PassView& pass) { EXPECT_TRUE(edits.rename_pass(pass.name, "renamed").ok); },
            [](const testing::LineDiff& diff, const PassView&) {
              EXPECT_EQ(diff.removed.size(), 1u);
              EXPECT_EQ(diff.added.size(), 1u);
            });
}

TEST_F(GraphTextTest, ARemovedPassTakesOnlyItsLines) {
  each_pass([&](GraphEdits& edits,
                const PassView& pass) { EXPECT_TRUE(edits.remove_pass(pass.name).ok); },
            [](const testing::LineDiff& diff, const PassView& pass) {
              const std::string name_line = "\"name\": \"" + pass.name + "\"";
              EXPECT_TRUE(std::any_of(diff.removed.begin(), diff.removed.end(),
                                      [&](const std::string& line) {
                                        return line.find(name_line) != std::string::npos;
                                      }));
              EXPECT_LT(diff.removed.size(), 40u);  // not the whole file
              if (!diff.added.empty()) {            // the last pass: the line above loses its comma
                ASSERT_EQ(diff.added.size(), 1u);
                EXPECT_EQ(diff.added[0], without_comma(diff.removed[0]));
              }
            });
}

TEST_F(GraphTextTest, AnAddedPassOnlyAddsLines) {
  for (const auto& file : shipped_graphs()) {
    const std::string original = read(file);
    GraphDocument doc = load(file);
    GraphEdits edits(doc, registry_);
    ASSERT_TRUE(edits.add_pass("blur", "extra").ok) << file;
    const auto diff = testing::line_diff(original, doc.to_text());
    ASSERT_LE(diff.removed.size(), 1u) << file;  // the last pass's closing line
    ASSERT_GE(diff.added.size(), 5u) << file;
    if (!diff.removed.empty()) {
      EXPECT_EQ(diff.added[0], diff.removed[0] + ",") << file;
    }
    const std::string all = doc.to_text();
    EXPECT_NE(all.find("\"name\": \"extra\""), std::string::npos) << all;
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.to_text(), original) << file;
  }
}

}  // namespace
}  // namespace antumbra::editor
