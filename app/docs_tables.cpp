#include "docs_tables.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "docs_table_kinds.hpp"

namespace antumbra::app::docs {
namespace {

constexpr const char* kMarkerTail = "; do not edit -->";

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

base::Diagnostic marker_error(const std::string& file, std::size_t line, int column,
                              std::string message) {
  return {codes::docs::kMarker,
          base::Severity::error,
          std::move(message),
          file,
          "",
          static_cast<int>(line + 1),
          column};
}

// "KIND from A, B" after the prefix; false when it does not read so.
bool parse_marker_body(const std::string& body, Region& region) {
  const auto from = body.find(" from ");
  if (from == std::string::npos) return false;
  region.kind = trim(body.substr(0, from));
  std::stringstream sources(body.substr(from + 6));
  for (std::string source; std::getline(sources, source, ',');) {
    region.sources.push_back(trim(source));
  }
  const auto empty = [](const std::string& s) { return s.empty(); };
  return !region.kind.empty() && region.kind.find(' ') == std::string::npos &&
         !region.sources.empty() &&
         std::none_of(region.sources.begin(), region.sources.end(), empty);
}

// A start marker at `index`; an error when the line starts like one but does not parse.
std::optional<base::Diagnostic> parse_marker(const std::string& line, std::size_t index,
                                             const std::string& file, Region& region) {
  const std::string text = trim(line);
  const int column = static_cast<int>(line.find(kMarkerPrefix)) + 1;
  std::string rest = text.substr(std::string(kMarkerPrefix).size());
  region = Region{};
  region.begin = index;
  region.pending = starts_with(rest, " (pending):");
  const bool colon = region.pending || starts_with(rest, ":");
  if (colon) rest = rest.substr(rest.find(':') + 1);
  const std::string tail = kMarkerTail;
  const bool closed = rest.size() >= tail.size() && rest.ends_with(tail);
  if (!colon || !closed || !parse_marker_body(rest.substr(0, rest.size() - tail.size()), region)) {
    return marker_error(file, index, column,
                        "malformed marker: expected \"" + marker_line("KIND", {"FILE"}, false) +
                            "\" (\"(pending):\" before the kind while its results are missing)");
  }
  region.kind_column =
      static_cast<int>(line.find(region.kind, static_cast<std::size_t>(column))) + 1;
  return std::nullopt;
}

}  // namespace

std::string marker_line(const std::string& kind, const std::vector<std::string>& sources,
                        bool pending) {
  std::string line =
      std::string(kMarkerPrefix) + (pending ? " (pending): " : ": ") + kind + " from ";
  for (std::size_t i = 0; i < sources.size(); ++i) line += (i > 0 ? ", " : "") + sources[i];
  return line + kMarkerTail;
}

base::Result<std::vector<Region>> find_regions(const std::vector<std::string>& lines,
                                               const std::string& file) {
  std::vector<Region> regions;
  base::Diagnostics diagnostics;
  std::optional<Region> open;
  bool fenced = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string text = trim(lines[i]);
    if (starts_with(text, "```") || starts_with(text, "~~~")) fenced = !fenced;
    if (fenced) continue;
    if (starts_with(text, kMarkerPrefix)) {
      if (open) {
        diagnostics.add(marker_error(file, open->begin, 1,
                                     "unclosed marker: another region starts at line " +
                                         std::to_string(i + 1) + " before \"" + kEndMarker + "\""));
      }
      Region region;
      auto error = parse_marker(lines[i], i, file, region);
      if (error) diagnostics.add(std::move(*error));
      open = error ? std::nullopt : std::optional<Region>(region);
    } else if (text == kEndMarker) {
      if (!open) {
        diagnostics.add(marker_error(file, i, 1, "end marker without a start marker"));
        continue;
      }
      open->end = i;
      regions.push_back(*open);
      open.reset();
    }
  }
  if (open) {
    diagnostics.add(marker_error(
        file, open->begin, 1,
        "unclosed marker: no \"" + std::string(kEndMarker) + "\" before the end of the file"));
  }
  if (diagnostics.has_errors()) return diagnostics;
  return regions;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    lines.push_back(text.substr(start, end - start));
  }
  lines.push_back(text.substr(start));
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i > 0 ? "\n" : "") + lines[i];
  return text;
}

std::vector<std::string> documents(const std::filesystem::path& root) {
  std::vector<std::string> out;
  if (std::filesystem::exists(root / "README.md")) out.emplace_back("README.md");
  std::vector<std::string> docs;
  if (std::filesystem::is_directory(root / "docs")) {
    for (const auto& entry : std::filesystem::directory_iterator(root / "docs")) {
      if (entry.is_regular_file() && entry.path().extension() == ".md") {
        docs.push_back("docs/" + entry.path().filename().string());
      }
    }
  }
  std::sort(docs.begin(), docs.end());
  out.insert(out.end(), docs.begin(), docs.end());
  return out;
}

TreeResult process_tree(const std::filesystem::path& root, bool check) {
  TreeResult tree;
  ResultCache results(root);
  for (const auto& file : documents(root)) {
    std::ifstream in(root / file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const auto result = process_document(text.str(), file, results, check);
    tree.diagnostics.append(result.diagnostics);
    tree.regions += result.regions;
    tree.differing += result.differing;
    if (!check && result.text != text.str()) {
      std::ofstream out(root / file, std::ios::binary);
      out << result.text;
      if (!out) throw std::runtime_error("cannot write " + (root / file).string());
      tree.rewritten.push_back(file);
    }
  }
  return tree;
}

}  // namespace antumbra::app::docs
