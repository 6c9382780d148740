// The undo/redo machinery on plain JSON: exact inverses, key order, gestures, dirty state.
#include <gtest/gtest.h>

#include "antumbra/editor/edit_history.hpp"

namespace antumbra::editor {
namespace {

Json parse(const char* text) {
  return Json::parse(text);
}

Command set(const std::string& parent, const std::string& key, const Json& root, Json value) {
  std::optional<Json> before;
  const Json& object = root[Json::json_pointer(parent)];
  if (object.contains(key)) before = object[key];
  return {"set " + key, {JsonEdit::set(parent, key, before, std::move(value))}};
}

std::vector<std::string> keys(const Json& object) {
  std::vector<std::string> out;
  for (auto it = object.begin(); it != object.end(); ++it) out.push_back(it.key());
  return out;
}

TEST(EditHistory, UndoAndRedoReplayExactly) {
  Json root = parse(R"({"a": 1, "b": {"c": 2}})");
  const Json original = root;
  EditHistory history;
  history.apply(root, set("/b", "c", root, 3));
  EXPECT_EQ(root["b"]["c"], 3);
  ASSERT_TRUE(history.can_undo());
  EXPECT_EQ(history.undo_description(), "set c");
  ASSERT_NE(history.undo(root), nullptr);
  EXPECT_EQ(root, original);
  ASSERT_TRUE(history.can_redo());
  ASSERT_NE(history.redo(root), nullptr);
  EXPECT_EQ(root["b"]["c"], 3);
  EXPECT_EQ(history.undo_count(), 1u);
  EXPECT_EQ(history.redo_count(), 0u);
}

TEST(EditHistory, NothingToUndoOrRedoIsNotAnError) {
  Json root = parse(R"({"a": 1})");
  EditHistory history;
  EXPECT_FALSE(history.can_undo());
  EXPECT_EQ(history.undo(root), nullptr);
  EXPECT_EQ(history.redo(root), nullptr);
  EXPECT_EQ(root, parse(R"({"a": 1})"));
}

TEST(EditHistory, ARemovedKeyComesBackInItsPlace) {
  Json root = parse(R"({"x": 1, "y": 2, "z": 3})");
  EditHistory history;
  history.apply(root, {"remove y", {JsonEdit::set("", "y", Json(2), std::nullopt)}});
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "z"}));
  history.undo(root);
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(root["y"], 2);
  history.redo(root);
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "z"}));
}

TEST(EditHistory, AnAddedKeyIsAppendedAndRemovedByUndo) {
  Json root = parse(R"({"x": 1, "z": 3})");
  EditHistory history;
  history.apply(root, set("", "new", root, "v"));
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "z", "new"}));
  history.undo(root);
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "z"}));
  history.redo(root);
  EXPECT_EQ(keys(root), (std::vector<std::string>{"x", "z", "new"}));
}

TEST(EditHistory, ArrayInsertAndEraseAreInverses) {
  Json root = parse(R"({"list": [1, 2, 3]})");
  EditHistory history;
  history.apply(root, {"insert", {JsonEdit::insert("/list", 1, Json(9))}});
  EXPECT_EQ(root["list"], parse("[1, 9, 2, 3]"));
  history.apply(root, {"erase", {JsonEdit::erase("/list", 3, Json(3))}});
  EXPECT_EQ(root["list"], parse("[1, 9, 2]"));
  history.undo(root);
  history.undo(root);
  EXPECT_EQ(root["list"], parse("[1, 2, 3]"));
}

TEST(EditHistory, ANewEditAfterUndoClearsRedo) {
  Json root = parse(R"({"a": 1})");
  EditHistory history;
  history.apply(root, set("", "a", root, 2));
  history.apply(root, set("", "a", root, 3));
  history.undo(root);
  ASSERT_TRUE(history.can_redo());
  history.apply(root, set("", "a", root, 4));
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.redo(root), nullptr);
  EXPECT_EQ(root["a"], 4);
  history.undo(root);
  EXPECT_EQ(root["a"], 2);
}

TEST(EditHistory, AGestureIsOneUndoStep) {
  Json root = parse(R"({"p": {"x": 0}})");
  EditHistory history;
  history.begin_gesture();
  for (int i = 1; i <= 50; ++i) history.apply(root, set("/p", "x", root, i));
  history.end_gesture();
  EXPECT_EQ(root["p"]["x"], 50);
  EXPECT_EQ(history.undo_count(), 1u);
  history.undo(root);
  EXPECT_EQ(root["p"]["x"], 0);
  EXPECT_FALSE(history.can_undo());
  history.redo(root);
  EXPECT_EQ(root["p"]["x"], 50);
  // A later edit outside the gesture is a step of its own.
  history.apply(root, set("/p", "x", root, 51));
  EXPECT_EQ(history.undo_count(), 2u);
}

TEST(EditHistory, UndoInsideAGestureEndsIt) {
  Json root = parse(R"({"x": 0})");
  EditHistory history;
  history.apply(root, set("", "x", root, 1));
  history.begin_gesture();
  history.apply(root, set("", "x", root, 2));
  history.undo(root);
  EXPECT_FALSE(history.in_gesture());
  history.apply(root, set("", "x", root, 3));
  EXPECT_EQ(history.undo_count(), 2u);
  history.undo(root);
  EXPECT_EQ(root["x"], 1);
}

TEST(EditHistory, DirtyFollowsTheSavedState) {
  Json root = parse(R"({"a": 1})");
  EditHistory history;
  EXPECT_FALSE(history.dirty());
  history.apply(root, set("", "a", root, 2));
  EXPECT_TRUE(history.dirty());
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
  history.undo(root);
  EXPECT_TRUE(history.dirty());
  history.redo(root);
  EXPECT_FALSE(history.dirty());  // back at the saved state
  history.undo(root);
  history.apply(root, set("", "a", root, 2));  // same content, but the saved step is gone
  EXPECT_TRUE(history.dirty());
  history.clear(false);
  EXPECT_TRUE(history.dirty());
  history.clear(true);
  EXPECT_FALSE(history.dirty());
}

TEST(EditHistory, AFailingEditLeavesTheDocumentUnchanged) {
  Json root = parse(R"({"a": 1, "b": [1]})");
  const Json original = root;
  EditHistory history;
  Command command{"two edits",
                  {JsonEdit::set("", "a", Json(1), Json(5)),
                   JsonEdit::set("/missing", "k", std::nullopt, Json(1))}};
  EXPECT_THROW(history.apply(root, command), std::logic_error);
  EXPECT_EQ(root, original);
  EXPECT_FALSE(history.can_undo());
}

TEST(EditHistory, RevisionsChangeWithContentAndAreUniqueAcrossHistories) {
  Json a = parse(R"({"x": 0})");
  Json b = a;
  EditHistory first;
  EditHistory second;
  first.apply(a, set("", "x", a, 1));
  second.apply(b, set("", "x", b, 1));
  EXPECT_NE(first.revision(), second.revision());
  const auto before = first.revision();
  first.undo(a);
  EXPECT_NE(first.revision(), before);
}

}  // namespace
}  // namespace antumbra::editor
