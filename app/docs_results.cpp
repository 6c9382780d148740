#include "docs_results.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace antumbra::app::docs {

ResultFile::ResultFile(base::JsonDocument document) : document_(std::move(document)) {
}

std::string ResultFile::text(const std::string& key) const {
  const auto& root = document_.root();
  if (!root.is_object() || !root.contains(key) || !root[key].is_string()) return "";
  return root[key].get<std::string>();
}

void ResultFile::fail(const std::string& message, const std::string& pointer) const {
  throw DocsTableError(
      document_.make(codes::docs::kResultsLack, base::Severity::error, message, pointer));
}

namespace {

// The element of the array at `array_key` of the root whose `key` is accepted by `match`.
template <class Match>
std::optional<Located> find_element(const base::Json& root, const std::string& array_key,
                                    const std::string& key, Match match) {
  if (!root.is_object() || !root.contains(array_key) || !root[array_key].is_array()) {
    return std::nullopt;
  }
  const auto& array = root[array_key];
  for (std::size_t i = 0; i < array.size(); ++i) {
    const auto& item = array[i];
    if (item.is_object() && item.contains(key) && item[key].is_string() &&
        match(item[key].get<std::string>())) {
      return Located{&item, base::pointer_append(base::pointer_append("", array_key), i)};
    }
  }
  return std::nullopt;
}

}  // namespace

Located ResultFile::scenario(const std::string& name, const std::string& table) const {
  auto found = find_element(root(), "scenarios", "scenario",
                            [&](const std::string& value) { return value == name; });
  if (!found) {
    fail("table '" + table + "' needs scenario \"" + name + "\", which " + path() +
             " lacks (measure it with `antumbra bench --scenario " + name + "`)",
         "/scenarios");
  }
  return *found;
}

Located ResultFile::quality_graph(const std::string& graph, const std::string& table) const {
  // `quality --graph` takes a path: match its file name.
  auto found = find_element(root(), "graphs", "graph", [&](const std::string& value) {
    return std::filesystem::path(value).filename().string() == graph;
  });
  if (!found) {
    fail("table '" + table + "' needs graph \"" + graph + "\", which " + path() + " lacks",
         "/graphs");
  }
  return *found;
}

double ResultFile::number(const Located& at, const std::string& path,
                          const std::string& table) const {
  const base::Json::json_pointer pointer(path);
  if (!at.value->contains(pointer) || !(*at.value)[pointer].is_number()) {
    fail("table '" + table + "' needs a number at " + at.pointer + path, at.pointer + path);
  }
  return (*at.value)[pointer].get<double>();
}

namespace {

// Calls `visit(type, median)` for every pass of a scenario.
template <class Visit>
void for_each_pass(const ResultFile& file, const Located& scenario, const std::string& table,
                   Visit visit) {
  const auto& value = *scenario.value;
  if (!value.contains("passes") || !value["passes"].is_array()) {
    file.fail("table '" + table + "' needs the passes of " + scenario.pointer,
              scenario.pointer + "/passes");
  }
  const auto& passes = value["passes"];
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const Located pass{&passes[i], base::pointer_append(scenario.pointer + "/passes", i)};
    const auto& type = passes[i].contains("type") && passes[i]["type"].is_string()
                           ? passes[i]["type"].get<std::string>()
                           : std::string();
    visit(type, file.number(pass, "/medianMs", table));
  }
}

bool contains(const std::vector<std::string>& types, const std::string& type) {
  return std::find(types.begin(), types.end(), type) != types.end();
}

}  // namespace

std::optional<double> ResultFile::pass_median(const Located& scenario,
                                              const std::vector<std::string>& types,
                                              const std::string& table) const {
  std::optional<double> sum;
  for_each_pass(*this, scenario, table, [&](const std::string& type, double median) {
    if (contains(types, type)) sum = sum.value_or(0.0) + median;
  });
  return sum;
}

double ResultFile::other_passes_median(const Located& scenario,
                                       const std::vector<std::string>& types,
                                       const std::string& table) const {
  double sum = 0.0;
  for_each_pass(*this, scenario, table, [&](const std::string& type, double median) {
    if (!contains(types, type)) sum += median;
  });
  return sum;
}

namespace {

// Every results file names what measured it; a table without that would be a typed number.
base::Result<ResultFile> checked(base::JsonDocument document) {
  base::Diagnostics diagnostics;
  for (const char* key : {"commit", "device", "driver"}) {
    const auto& root = document.root();
    if (!root.is_object() || !root.contains(key) || !root[key].is_string() ||
        root[key].get<std::string>().empty()) {
      diagnostics.add(document.make(codes::docs::kProvenance, base::Severity::error,
                                    document.file() + " does not say the " + key +
                                        " it was measured with (a string at /" + key + ")",
                                    ""));
    }
  }
  if (diagnostics.has_errors()) return diagnostics;
  return ResultFile(std::move(document));
}

}  // namespace

const std::optional<base::Result<ResultFile>>& ResultCache::get(const std::string& path) {
  if (auto it = files_.find(path); it != files_.end()) return it->second;
  std::optional<base::Result<ResultFile>> loaded;
  std::ifstream in(root_ / path, std::ios::binary);
  if (in) {
    std::ostringstream text;
    text << in.rdbuf();
    // Named as the marker names it, so that diagnostics read "docs/results/x.json:3:5".
    auto document = base::parse_json(text.str(), path);
    loaded = document.ok() ? checked(std::move(document.value()))
                           : base::Result<ResultFile>(document.diagnostics());
  }
  return files_.emplace(path, std::move(loaded)).first->second;
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace antumbra::app::docs
