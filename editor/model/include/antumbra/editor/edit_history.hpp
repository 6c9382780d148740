#pragma once
// Undo/redo over a JSON document. Every edit the editor makes is a Command: a list of
// primitive changes (set or remove an object member, insert or erase an array element)
// that carry both the old and the new value, so undo and redo replay them exactly and
// the document's key order survives any sequence of edits.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "antumbra/base/json_document.hpp"

namespace antumbra::editor {

using base::Json;

struct JsonEdit {
  enum class Kind { set_member, insert_element, erase_element };
  Kind kind = Kind::set_member;
  std::string parent;          // JSON Pointer of the object or array changed
  std::string key;             // set_member: the member
  std::size_t index = 0;       // insert/erase: the element; set_member: the key's position
                               // (filled on first apply, so that undo re-inserts it there)
  std::optional<Json> before;  // set_member: old value (nullopt = absent); erase: the element
  std::optional<Json> after;   // set_member: new value (nullopt = remove); insert: the element

  static JsonEdit set(std::string parent, std::string key, std::optional<Json> before,
                      std::optional<Json> after);
  static JsonEdit insert(std::string array, std::size_t index, Json element);
  static JsonEdit erase(std::string array, std::size_t index, Json element);
};

struct Command {
  std::string description;  // "Move 'lamp'", shown as "Undo Move 'lamp'"
  std::vector<JsonEdit> edits;
  // What the views should select after undo / after (re)do, -1 for nothing. Selection is
  // view state, not file content, so it is restored by commands but never one itself.
  int focus_before = -1;
  int focus_after = -1;
};

// What a document says about an edit: refused (expected: bad user input, with why),
// applied, or accepted without change.
struct EditResult {
  bool ok = true;
  bool changed = false;  // false for a refused edit or one that changes nothing
  std::string message;   // why it was refused, or a note (e.g. "clamped to 32")
  std::string code;      // a refusal's diagnostic code, where one says it (FG040, FG071)
  explicit operator bool() const { return ok; }
  static EditResult refused(std::string why, std::string code = {}) {
    return {false, false, std::move(why), std::move(code)};
  }
};

class EditHistory {
 public:
  // Applies `command` to `root` and records it. Inside an open gesture every command
  // after the first merges into one undo step. A failed edit (a pointer that does not
  // resolve: a programming error) throws std::logic_error with `root` unchanged.
  void apply(Json& root, Command command);
  // The command undone / redone (for its focus), or nullptr when there is none.
  const Command* undo(Json& root);
  const Command* redo(Json& root);
  [[nodiscard]] bool can_undo() const { return !undo_.empty(); }
  [[nodiscard]] bool can_redo() const { return !redo_.empty(); }
  [[nodiscard]] std::string_view undo_description() const;
  [[nodiscard]] std::string_view redo_description() const;
  [[nodiscard]] std::size_t undo_count() const { return undo_.size(); }
  [[nodiscard]] std::size_t redo_count() const { return redo_.size(); }

  // A drag of a slider or a light is one gesture: one undo step however many frames
  // it lasts. Undo and redo close an open gesture.
  void begin_gesture();
  void end_gesture();
  [[nodiscard]] bool in_gesture() const { return gesture_open_; }

  // Unsaved changes: the current state differs from the one last marked saved.
  [[nodiscard]] bool dirty() const { return state_id() != saved_id_; }
  void mark_saved() { saved_id_ = state_id(); }
  // Forgets every step (after a load); the current state counts as saved when `saved`.
  void clear(bool saved = true);
  // Changes whenever the content does (apply, undo, redo, clear), unique within the
  // process: cached views compare it.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }

 private:
  struct Step {
    Command command;
    std::uint64_t id = 0;  // identifies the state after this step; new on every merge
  };
  [[nodiscard]] std::uint64_t state_id() const {
    return undo_.empty() ? base_id_ : undo_.back().id;
  }
  static void merge_into(Command& into, Command&& command);

  std::vector<Step> undo_;
  std::vector<Step> redo_;
  std::uint64_t next_id_ = 1;
  std::uint64_t base_id_ = 0;   // the state with nothing to undo
  std::uint64_t saved_id_ = 0;  // never reachable again once its step is dropped
  std::uint64_t revision_ = 0;  // 0 until the first change or clear
  bool gesture_open_ = false;
  bool gesture_has_step_ = false;
};

}  // namespace antumbra::editor
