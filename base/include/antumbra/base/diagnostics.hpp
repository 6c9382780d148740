#pragma once
// Diagnostics for user input (graphs, scenes, shaders): every message points into
// the source by file, JSON Pointer and line:column, and prints like a compiler.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace antumbra::base {

enum class Severity { note, warning, error };

const char* to_string(Severity severity);

struct Diagnostic {
  std::string code;  // e.g. "FG012"; the catalogue is in diagnostic_codes.hpp
  Severity severity = Severity::error;
  std::string message;
  std::string file;
  std::string pointer;  // JSON Pointer into the document, "" for the root
  int line = 0;         // 1-based; 0 when unknown
  int column = 0;       // 1-based; 0 when unknown
  // The source line the diagnostic points at, printed under it with a caret at `column`
  // (shader errors: the GLSL line); empty when there is nothing to show.
  std::string excerpt;
};

// "file:line:col: error[FG012]: message (at /passes/2/in/depth)", then, with an excerpt,
// "  | <source line>" and "  | ^" under the column.
std::string format_text(const Diagnostic& diagnostic);
nlohmann::json to_json(const Diagnostic& diagnostic);

class Diagnostics {
 public:
  void add(Diagnostic diagnostic) { items_.push_back(std::move(diagnostic)); }
  void append(const Diagnostics& other);
  [[nodiscard]] bool has_errors() const;
  [[nodiscard]] std::size_t error_count() const;
  [[nodiscard]] std::size_t warning_count() const;
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] std::size_t size() const { return items_.size(); }
  [[nodiscard]] const std::vector<Diagnostic>& items() const { return items_; }
  [[nodiscard]] const Diagnostic& operator[](std::size_t i) const { return items_[i]; }
  [[nodiscard]] auto begin() const { return items_.begin(); }
  [[nodiscard]] auto end() const { return items_.end(); }
  // The first diagnostic with this code, or nullptr.
  [[nodiscard]] const Diagnostic* find(std::string_view code) const;
  [[nodiscard]] std::string to_text() const;  // one line per diagnostic
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  std::vector<Diagnostic> items_;
};

// Expected failure on user input: a value, or diagnostics explaining why not.
// Warnings may accompany a value.
template <class T>
class Result {
 public:
  Result(T value, Diagnostics diagnostics = {})  // NOLINT(google-explicit-constructor)
      : value_(std::move(value)), diagnostics_(std::move(diagnostics)) {}
  Result(Diagnostics diagnostics)  // NOLINT(google-explicit-constructor)
      : diagnostics_(std::move(diagnostics)) {}

  [[nodiscard]] bool ok() const { return value_.has_value() && !diagnostics_.has_errors(); }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] T& value() { return *value_; }
  [[nodiscard]] const T& value() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  [[nodiscard]] const Diagnostics& diagnostics() const { return diagnostics_; }
  [[nodiscard]] Diagnostics& diagnostics() { return diagnostics_; }

 private:
  std::optional<T> value_;
  Diagnostics diagnostics_;
};

}  // namespace antumbra::base
