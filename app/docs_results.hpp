#pragma once
// The results files that docs tables are generated from (docs/results/): bench.json of
// `antumbra bench` and the JSON of `antumbra quality --format json`, each naming the
// commit, device and driver that measured it. A lookup that fails throws a
// DocsTableError whose diagnostic is located in the results file (JSON Pointer and
// line:column), so that a table needing a scenario the file lacks says which and where.

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"

namespace antumbra::codes::docs {
// `antumbra docs-tables` (app/docs_tables.hpp). Kept beside the tool rather than in
// base/diagnostic_codes.hpp, which every target includes (see the catalogue's header).
inline constexpr const char* kMarker = "DT001";          // malformed, unclosed or stray marker
inline constexpr const char* kUnknownTable = "DT002";    // the marker names no table kind
inline constexpr const char* kResultsMissing = "DT003";  // a named results file does not exist
inline constexpr const char* kProvenance = "DT004";      // no commit, device or driver
inline constexpr const char* kResultsLack = "DT005";     // a scenario, graph, pass or number
inline constexpr const char* kDiffers = "DT010";         // a region differs from what is generated
inline constexpr const char* kGenerated = "DT011";       // note: the generated line
}  // namespace antumbra::codes::docs

namespace antumbra::app::docs {

// A diagnostic that ends one table's generation (the region is left as it is).
class DocsTableError : public std::runtime_error {
 public:
  explicit DocsTableError(base::Diagnostic diagnostic)
      : std::runtime_error(diagnostic.message), diagnostic_(std::move(diagnostic)) {}
  [[nodiscard]] const base::Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  base::Diagnostic diagnostic_;
};

// A value inside a results file and where it is (for the next lookup's diagnostics).
struct Located {
  const base::Json* value = nullptr;
  std::string pointer;
};

// One results file; `path()` as the marker names it, relative to the root.
class ResultFile {
 public:
  explicit ResultFile(base::JsonDocument document);

  [[nodiscard]] const std::string& path() const { return document_.file(); }
  [[nodiscard]] const base::Json& root() const { return document_.root(); }
  [[nodiscard]] std::string text(const std::string& key) const;  // "" when absent

  // The bench scenario named `name` (under /scenarios); throws when the file lacks it.
  [[nodiscard]] Located scenario(const std::string& name, const std::string& table) const;
  // The quality result of the graph whose file is `graph` (e.g. "pcss.json", under /graphs).
  [[nodiscard]] Located quality_graph(const std::string& graph, const std::string& table) const;
  // The number at `path` (a JSON Pointer below `at`); throws when absent or not a number.
  [[nodiscard]] double number(const Located& at, const std::string& path,
                              const std::string& table) const;
  // The sum of the medians of the passes of `types` in a scenario; nullopt when it has none.
  [[nodiscard]] std::optional<double> pass_median(const Located& scenario,
                                                  const std::vector<std::string>& types,
                                                  const std::string& table) const;
  // The sum of the medians of every pass whose type is not among `types`.
  [[nodiscard]] double other_passes_median(const Located& scenario,
                                           const std::vector<std::string>& types,
                                           const std::string& table) const;

  // A diagnostic at `pointer` in this file.
  [[noreturn]] void fail(const std::string& message, const std::string& pointer) const;

 private:
  base::JsonDocument document_;
};

// Results files by path, each read once: nullopt when the file does not exist, the parse
// or provenance diagnostics when it does not load.
class ResultCache {
 public:
  explicit ResultCache(std::filesystem::path root) : root_(std::move(root)) {}
  const std::optional<base::Result<ResultFile>>& get(const std::string& path);

 private:
  std::filesystem::path root_;
  std::map<std::string, std::optional<base::Result<ResultFile>>> files_;
};

// `value` with `decimals` digits after the point ("2.50").
std::string fixed(double value, int decimals);

}  // namespace antumbra::app::docs
