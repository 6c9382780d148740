#include "antumbra/editor/edit_history.hpp"

#include <atomic>
#include <limits>
#include <stdexcept>
#include <utility>

namespace antumbra::editor {
namespace {

constexpr std::size_t kAppend = std::numeric_limits<std::size_t>::max();

// Unique across every history in the process: a view caching on (revision) can never
// mistake a newly loaded document for the one it saw before.
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

Json& resolve(Json& root, const std::string& pointer, Json::value_t type) {
  const Json::json_pointer p(pointer);
  if (!root.contains(p)) throw std::logic_error("edit history: no value at '" + pointer + "'");
  Json& value = root[p];
  if (value.type() != type)
    throw std::logic_error("edit history: '" + pointer + "' has the wrong type for this edit");
  return value;
}

std::size_t key_position(const Json& object, const std::string& key) {
  std::size_t i = 0;
  for (auto it = object.begin(); it != object.end(); ++it, ++i) {
    if (it.key() == key) return i;
  }
  return kAppend;
}

// ordered_json appends new keys; undoing a removal must put the key back where it was.
void insert_member_at(Json& object, const std::string& key, Json value, std::size_t position) {
  if (position >= object.size()) {
    object[key] = std::move(value);
    return;
  }
  Json rebuilt = Json::object();
  auto it = object.begin();
  for (std::size_t i = 0; i < position; ++i, ++it) rebuilt[it.key()] = std::move(it.value());
  rebuilt[key] = std::move(value);
  for (; it != object.end(); ++it) rebuilt[it.key()] = std::move(it.value());
  object = std::move(rebuilt);
}

void set_member(Json& root, JsonEdit& edit, const std::optional<Json>& value) {
  Json& object = resolve(root, edit.parent, Json::value_t::object);
  const std::size_t found = key_position(object, edit.key);
  if (found != kAppend) edit.index = found;
  if (!value) {
    if (found != kAppend) object.erase(edit.key);
  } else if (found != kAppend) {
    object[edit.key] = *value;
  } else {
    if (edit.index == kAppend) edit.index = object.size();
    insert_member_at(object, edit.key, *value, edit.index);
  }
}

void apply_element(Json& root, const JsonEdit& edit, bool insert) {
  Json& array = resolve(root, edit.parent, Json::value_t::array);
  if (insert) {
    // The element an insert adds, or the one an erase took (restored by its undo).
    const Json& element = edit.kind == JsonEdit::Kind::insert_element ? *edit.after : *edit.before;
    if (edit.index > array.size()) throw std::logic_error("edit history: insert past the end");
    array.insert(array.begin() + static_cast<std::ptrdiff_t>(edit.index), element);
  } else {
    if (edit.index >= array.size()) throw std::logic_error("edit history: erase past the end");
    array.erase(array.begin() + static_cast<std::ptrdiff_t>(edit.index));
  }
}

// Forward applies `after`, backward restores `before`.
void apply_edit(Json& root, JsonEdit& edit, bool forward) {
  switch (edit.kind) {
    case JsonEdit::Kind::set_member:
      set_member(root, edit, forward ? edit.after : edit.before);
      return;
    case JsonEdit::Kind::insert_element:
      apply_element(root, edit, forward);
      return;
    case JsonEdit::Kind::erase_element:
      apply_element(root, edit, !forward);
      return;
  }
}

// All or nothing: a failing edit undoes the ones before it, then rethrows.
void apply_all(Json& root, std::vector<JsonEdit>& edits, bool forward) {
  const std::size_t n = edits.size();
  std::size_t done = 0;
  try {
    for (; done < n; ++done) apply_edit(root, edits[forward ? done : n - 1 - done], forward);
  } catch (...) {
    while (done-- > 0) apply_edit(root, edits[forward ? done : n - 1 - done], !forward);
    throw;
  }
}

}  // namespace

JsonEdit JsonEdit::set(std::string parent, std::string key, std::optional<Json> before,
                       std::optional<Json> after) {
  return {Kind::set_member, std::move(parent), std::move(key),
          kAppend,          std::move(before), std::move(after)};
}

JsonEdit JsonEdit::insert(std::string array, std::size_t index, Json element) {
  return {Kind::insert_element, std::move(array), {}, index, std::nullopt, std::move(element)};
}

JsonEdit JsonEdit::erase(std::string array, std::size_t index, Json element) {
  return {Kind::erase_element, std::move(array), {}, index, std::move(element), std::nullopt};
}

void EditHistory::apply(Json& root, Command command) {
  apply_all(root, command.edits, true);
  revision_ = next_revision();
  redo_.clear();
  if (gesture_open_ && gesture_has_step_ && !undo_.empty()) {
    merge_into(undo_.back().command, std::move(command));
    undo_.back().id = next_id_++;
    return;
  }
  undo_.push_back({std::move(command), next_id_++});
  gesture_has_step_ = gesture_open_;
}

void EditHistory::merge_into(Command& into, Command&& command) {
  for (JsonEdit& edit : command.edits) {
    // A drag sets one value many times: keep the first `before` and the last `after`.
    if (!into.edits.empty()) {
      JsonEdit& last = into.edits.back();
      if (last.kind == JsonEdit::Kind::set_member && edit.kind == JsonEdit::Kind::set_member &&
          last.parent == edit.parent && last.key == edit.key) {
        last.after = std::move(edit.after);
        continue;
      }
    }
    into.edits.push_back(std::move(edit));
  }
  into.focus_after = command.focus_after;
}

const Command* EditHistory::undo(Json& root) {
  end_gesture();
  if (undo_.empty()) return nullptr;
  apply_all(root, undo_.back().command.edits, false);
  revision_ = next_revision();
  redo_.push_back(std::move(undo_.back()));
  undo_.pop_back();
  return &redo_.back().command;
}

const Command* EditHistory::redo(Json& root) {
  end_gesture();
  if (redo_.empty()) return nullptr;
  apply_all(root, redo_.back().command.edits, true);
  revision_ = next_revision();
  undo_.push_back(std::move(redo_.back()));
  redo_.pop_back();
  return &undo_.back().command;
}

std::string_view EditHistory::undo_description() const {
  return undo_.empty() ? std::string_view() : undo_.back().command.description;
}

std::string_view EditHistory::redo_description() const {
  return redo_.empty() ? std::string_view() : redo_.back().command.description;
}

void EditHistory::begin_gesture() {
  gesture_open_ = true;
  gesture_has_step_ = false;
}

void EditHistory::end_gesture() {
  gesture_open_ = false;
  gesture_has_step_ = false;
}

void EditHistory::clear(bool saved) {
  undo_.clear();
  redo_.clear();
  end_gesture();
  base_id_ = next_id_++;
  saved_id_ = saved ? base_id_ : 0;  // 0 is never an id: unsaved until the next save
  revision_ = next_revision();
}

}  // namespace antumbra::editor
