#include "antumbra/base/diagnostics.hpp"

#include <algorithm>

namespace antumbra::base {

const char* to_string(Severity severity) {
  switch (severity) {
    case Severity::note:
      return "note";
    case Severity::warning:
      return "warning";
    case Severity::error:
      return "error";
  }
  return "error";
}

std::string format_text(const Diagnostic& diagnostic) {
  std::string out;
  if (!diagnostic.file.empty()) {
    out += diagnostic.file;
    if (diagnostic.line > 0) {
      out += ':' + std::to_string(diagnostic.line);
      if (diagnostic.column > 0) out += ':' + std::to_string(diagnostic.column);
    }
    out += ": ";
  }
  out += to_string(diagnostic.severity);
  out += '[' + diagnostic.code + "]: " + diagnostic.message;
  if (!diagnostic.pointer.empty()) out += " (at " + diagnostic.pointer + ')';
  if (!diagnostic.excerpt.empty()) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "a" + s.
    out += "\n  | ";
    out += diagnostic.excerpt;
    if (diagnostic.column > 0) {
      // Tabs stay tabs so that the caret lines up under the same terminal columns.
      std::string pad;
      for (int i = 0; i + 1 < diagnostic.column && i < static_cast<int>(diagnostic.excerpt.size());
           ++i) {
        pad += diagnostic.excerpt[static_cast<std::size_t>(i)] == '\t' ? '\t' : ' ';
      }
      out += "\n  | ";
      out += pad;
      out += '^';
    }
  }
  return out;
}

nlohmann::json to_json(const Diagnostic& diagnostic) {
  auto out =
      nlohmann::json{{"code", diagnostic.code},       {"severity", to_string(diagnostic.severity)},
                     {"message", diagnostic.message}, {"file", diagnostic.file},
                     {"pointer", diagnostic.pointer}, {"line", diagnostic.line},
                     {"column", diagnostic.column}};
  if (!diagnostic.excerpt.empty()) out["excerpt"] = diagnostic.excerpt;
  return out;
}

void Diagnostics::append(const Diagnostics& other) {
  items_.insert(items_.end(), other.items_.begin(), other.items_.end());
}

bool Diagnostics::has_errors() const {
  return error_count() > 0;
}

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(
      std::count_if(items_.begin(), items_.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

std::size_t Diagnostics::warning_count() const {
  return static_cast<std::size_t>(
      std::count_if(items_.begin(), items_.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::warning; }));
}

const Diagnostic* Diagnostics::find(std::string_view code) const {
  auto it = std::find_if(items_.begin(), items_.end(),
                         [&](const Diagnostic& d) { return d.code == code; });
  return it == items_.end() ? nullptr : &*it;
}

std::string Diagnostics::to_text() const {
  std::string out;
  for (const auto& d : items_) out += format_text(d) + '\n';
  return out;
}

nlohmann::json Diagnostics::to_json() const {
  auto array = nlohmann::json::array();
  for (const auto& d : items_) array.push_back(base::to_json(d));
  return array;
}

}  // namespace antumbra::base
