// One Markdown document's generated regions: each region's results loaded, its table
// generated, and the region replaced (or, with check, compared line by line).
#include <algorithm>
#include <filesystem>

#include "docs_table_kinds.hpp"
#include "docs_tables.hpp"

namespace antumbra::app::docs {
namespace {

// Where a region sits, for diagnostics at its marker.
struct RegionContext {
  const Region& region;
  const std::string& file;
  base::Diagnostics& diagnostics;

  void error(const char* code, std::string message) const {
    diagnostics.add({code, base::Severity::error, std::move(message), file, "",
                     static_cast<int>(region.begin + 1), region.kind_column});
  }
};

std::string kind_names() {
  std::string names;
  for (const auto& kind : table_kinds())
    names += (names.empty() ? "" : ", ") + std::string(kind.name);
  return names;
}

std::string sources_text(const Region& region) {
  std::string text;
  for (const auto& source : region.sources) text += (text.empty() ? "" : ", ") + source;
  return text;
}

// The region's files; nullopt (diagnostics added) when one does not load or is missing
// from a region that is not pending. `missing` says whether any is still to be measured.
std::optional<std::vector<const ResultFile*>> load_sources(const RegionContext& at,
                                                           const TableKind& kind,
                                                           ResultCache& results, bool& missing) {
  std::vector<const ResultFile*> files;
  missing = false;
  bool failed = false;
  for (const auto& source : at.region.sources) {
    const auto& loaded = results.get(source);
    if (!loaded) {
      missing = true;
      if (!at.region.pending) {
        at.error(codes::docs::kResultsMissing, "table '" + at.region.kind + "' reads " + source +
                                                   ", which does not exist (measure with `" +
                                                   kind.measure +
                                                   "`, or mark the region \"(pending):\")");
        failed = true;
      }
    } else if (!loaded->ok()) {
      at.diagnostics.append(loaded->diagnostics());
      failed = true;
    } else {
      files.push_back(&loaded->value());
    }
  }
  if (failed) return std::nullopt;
  return files;
}

// The region as it should read, markers included; nullopt when it cannot be generated.
std::optional<std::vector<std::string>> generate_region(const RegionContext& at,
                                                        ResultCache& results) {
  const Region& region = at.region;
  const TableKind* kind = find_table_kind(region.kind);
  if (kind == nullptr) {
    at.error(codes::docs::kUnknownTable,
             "unknown table kind '" + region.kind + "' (kinds: " + kind_names() + ")");
    return std::nullopt;
  }
  const auto count = static_cast<int>(region.sources.size());
  if (kind->sources > 0 && count != kind->sources) {
    at.error(codes::docs::kMarker,
             "table '" + region.kind + "' reads " + std::to_string(kind->sources) +
                 " results file(s), the marker names " + std::to_string(count));
    return std::nullopt;
  }
  bool missing = false;
  const auto files = load_sources(at, *kind, results, missing);
  if (!files) return std::nullopt;
  std::vector<std::string> lines{marker_line(region.kind, region.sources, missing)};
  if (missing) {
    lines.push_back("*Pending: no results yet in " + sources_text(region) + " (measure with `" +
                    kind->measure + "`, then run `make docs-tables`; docs/measuring.md).*");
  } else {
    const std::string link_base = std::filesystem::path(at.file).parent_path().generic_string();
    try {
      const auto body = kind->generate(*files, link_base);
      lines.insert(lines.end(), body.begin(), body.end());
    } catch (const DocsTableError& e) {
      at.diagnostics.add(e.diagnostic());
      return std::nullopt;
    }
  }
  lines.emplace_back(kEndMarker);
  return lines;
}

// The first line where the committed region and the generated one part; nullopt when equal.
std::optional<std::size_t> first_difference(const std::vector<std::string>& committed,
                                            const std::vector<std::string>& generated) {
  const std::size_t n = std::max(committed.size(), generated.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= committed.size() || i >= generated.size() || committed[i] != generated[i]) return i;
  }
  return std::nullopt;
}

void report_difference(const RegionContext& at, const std::vector<std::string>& committed,
                       const std::vector<std::string>& generated, std::size_t i) {
  // A shorter committed region differs at its end marker.
  const std::size_t at_line = std::min(i, committed.size() - 1);
  const std::string& have = committed[at_line];
  const std::string want = i < generated.size() ? generated[i] : "(nothing: the region ends)";
  std::size_t column = 0;
  while (column < have.size() && column < want.size() && have[column] == want[column]) ++column;
  const int line = static_cast<int>(at.region.begin + at_line + 1);
  at.diagnostics.add({codes::docs::kDiffers, base::Severity::error,
                      "table '" + at.region.kind + "' differs from what " +
                          sources_text(at.region) + " generates (run make docs-tables)",
                      at.file, "", line, static_cast<int>(column) + 1, have});
  at.diagnostics.add(
      {codes::docs::kGenerated, base::Severity::note, "generated: " + want, at.file, "", line, 0});
}

}  // namespace

DocumentResult process_document(const std::string& text, const std::string& file,
                                ResultCache& results, bool check) {
  DocumentResult result;
  const auto lines = split_lines(text);
  const auto regions = find_regions(lines, file);
  if (!regions.ok()) {
    result.text = text;
    result.diagnostics = regions.diagnostics();
    return result;
  }
  std::vector<std::string> out;
  std::size_t next = 0;  // the first line not yet copied
  for (const auto& region : regions.value()) {
    const RegionContext at{region, file, result.diagnostics};
    const std::vector<std::string> committed(lines.begin() + static_cast<long>(region.begin),
                                             lines.begin() + static_cast<long>(region.end) + 1);
    out.insert(out.end(), lines.begin() + static_cast<long>(next),
               lines.begin() + static_cast<long>(region.begin));
    next = region.end + 1;
    ++result.regions;
    const auto generated = generate_region(at, results);
    if (!generated) {
      out.insert(out.end(), committed.begin(), committed.end());
      continue;
    }
    if (const auto i = first_difference(committed, *generated)) {
      ++result.differing;
      if (check) report_difference(at, committed, *generated, *i);
    }
    out.insert(out.end(), generated->begin(), generated->end());
  }
  out.insert(out.end(), lines.begin() + static_cast<long>(next), lines.end());
  result.text = join_lines(out);
  return result;
}

}  // namespace antumbra::app::docs
