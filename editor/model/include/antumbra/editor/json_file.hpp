#pragma once
// What the scene and graph documents share: a JSON file being edited, its undo history,
// the unsaved-changes flag, format-preserving atomic saves and the recovery file. The
// documents add the meaning (lights, pass parameters) and the validation of edits.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/atomic_file.hpp"
#include "antumbra/editor/edit_history.hpp"
#include "antumbra/editor/recovery_file.hpp"

namespace antumbra::editor {

// A file that cannot be opened is bad user input (a wrong path): a diagnostic, FG000.
[[nodiscard]] base::Result<std::string> read_text_file(const std::filesystem::path& file);

class JsonFile {
 public:
  JsonFile() = default;
  // `document` is `text` parsed; the recovery file beside `path` is looked for.
  JsonFile(const std::filesystem::path& path, base::JsonDocument document, std::string text);

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] const base::Json& root() const { return root_; }

  void apply(Command command) { history_.apply(root_, std::move(command)); }
  const Command* undo() { return history_.undo(root_); }
  const Command* redo() { return history_.redo(root_); }
  [[nodiscard]] EditHistory& history() { return history_; }
  [[nodiscard]] const EditHistory& history() const { return history_; }
  [[nodiscard]] bool dirty() const { return history_.dirty(); }
  [[nodiscard]] std::uint64_t revision() const { return history_.revision(); }

  // The loaded formatting kept where only values changed (json_text.hpp).
  [[nodiscard]] std::string to_text() const;
  // Atomic; throws SaveError and stays dirty on failure. Removes the recovery file.
  void save_as(const std::filesystem::path& path);
  [[nodiscard]] AtomicWriteHooks& save_hooks() { return save_hooks_; }

  [[nodiscard]] bool recovery_available() const { return recovery_available_; }
  [[nodiscard]] RecoveryFile& recovery() { return recovery_; }
  bool autosave_if_due(RecoveryFile::Clock::time_point now);
  // The recovery file's text (diagnostics when missing or unreadable), and parsed
  // (diagnostics when bad too); nothing changes yet.
  [[nodiscard]] base::Result<std::string> read_recovery_text() const;
  [[nodiscard]] base::Result<base::JsonDocument> read_recovery() const;
  // Takes `root` as the content: unsaved changes to the file, with no undo history.
  void replace_content(base::Json root);
  void close();

 private:
  std::filesystem::path path_;
  base::JsonDocument base_;  // the file as last loaded or saved, with positions
  std::string base_text_;
  base::Json root_;
  EditHistory history_;
  RecoveryFile recovery_;
  bool recovery_available_ = false;
  AtomicWriteHooks save_hooks_;
};

}  // namespace antumbra::editor
