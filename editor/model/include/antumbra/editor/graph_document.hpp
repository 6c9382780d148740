#pragma once
// The frame-graph file the editor is working on: passes and their parameters, with the
// controls' types and ranges taken from each pass type's reflection, and parameter
// edits that respect them. Everything else in the file is left exactly as it was.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/editor/json_file.hpp"
#include "antumbra/fg/reflection.hpp"
#include "antumbra/fg/registry.hpp"

namespace antumbra::editor {

// Pass type -> its reflection (nullptr when unknown). The application passes the
// built-in registry's; tests pass a fake one.
using PassDescLookup = std::function<const fg::PassDesc*(std::string_view type)>;
[[nodiscard]] PassDescLookup lookup_in(const fg::Registry& registry);

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's noexcept move is reported.
struct ParamView {
  std::string name;
  bool declared = false;  // false: in the file but not in the reflection (kept, read-only)
  fg::ParamType type = fg::ParamType::number;
  base::Json value;        // the file's value, else the default
  bool from_file = false;  // false: the default applies
  base::Json default_value;
  std::optional<double> min;  // numbers and integers
  std::optional<double> max;
  std::vector<std::string> choices;  // enumerations
  std::string description;
};

struct PassView {
  std::size_t index = 0;  // in /passes
  std::string name;
  std::string type;
  bool known_type = false;
  std::vector<ParamView> params;  // declared ones in reflection order, then undeclared ones
};

// Out-of-range numbers: clamped into the range with a note, or refused.
enum class RangePolicy { clamp, reject };

class GraphDocument {
 public:
  // Bad files (unreadable, bad JSON, a structure parse_graph rejects) come back as
  // diagnostics with file and line:column.
  static base::Result<GraphDocument> load(const std::filesystem::path& file, PassDescLookup lookup);
  static base::Result<GraphDocument> parse(std::string_view text, const std::filesystem::path& file,
                                           PassDescLookup lookup);

  [[nodiscard]] const std::filesystem::path& file() const { return file_.path(); }
  [[nodiscard]] const base::Json& json() const { return file_.root(); }
  [[nodiscard]] std::vector<PassView> passes() const;
  [[nodiscard]] int find_pass(std::string_view name) const;  // -1 when absent
  [[nodiscard]] std::optional<ParamView> param(std::string_view pass, std::string_view name) const;

  // Checks `value` against the parameter's reflection (type, enum choices, range) and
  // sets it as one undoable command. Unknown passes or parameters are refused with a
  // "did you mean".
  EditResult set_param(std::string_view pass, std::string_view name, const base::Json& value,
                       RangePolicy policy = RangePolicy::clamp);
  // Removes the parameter from the file, so the pass type's default applies.
  EditResult reset_param(std::string_view pass, std::string_view name);

  bool undo() { return file_.undo() != nullptr; }
  bool redo() { return file_.redo() != nullptr; }
  [[nodiscard]] bool can_undo() const { return file_.history().can_undo(); }
  [[nodiscard]] bool can_redo() const { return file_.history().can_redo(); }
  [[nodiscard]] const EditHistory& history() const { return file_.history(); }
  void begin_gesture() { file_.history().begin_gesture(); }
  void end_gesture() { file_.history().end_gesture(); }
  [[nodiscard]] bool dirty() const { return file_.dirty(); }
  [[nodiscard]] std::uint64_t revision() const { return file_.revision(); }

  [[nodiscard]] std::string to_text() const { return file_.to_text(); }
  void save() { file_.save_as(file_.path()); }
  void save_as(const std::filesystem::path& file) { file_.save_as(file); }
  [[nodiscard]] AtomicWriteHooks& save_hooks() { return file_.save_hooks(); }

  [[nodiscard]] bool recovery_available() const { return file_.recovery_available(); }
  bool autosave_if_due(RecoveryFile::Clock::time_point now) { return file_.autosave_if_due(now); }
  base::Diagnostics recover();
  void close() { file_.close(); }
  [[nodiscard]] RecoveryFile& recovery() { return file_.recovery(); }

 private:
  friend class GraphEdits;  // structural edits (graph_edits.hpp), in the same history
  GraphDocument() = default;
  [[nodiscard]] PassView view(std::size_t index) const;

  JsonFile file_;
  PassDescLookup lookup_;
};

// The name of the graph's light-layering pass (the first), empty when it has none.
[[nodiscard]] std::string layering_pass(const GraphDocument& graph);
// The layer cap of that pass (antumbra/layering/layer_cap.hpp), its default when the
// graph has no light-layering pass or the file's value is not an integer.
[[nodiscard]] int layer_cap(const GraphDocument& graph);

}  // namespace antumbra::editor
