#pragma once
// The kinds of table `antumbra docs-tables` generates. A kind fixes what a table shows:
// its rows and columns, which scenario (bench) or graph (quality) and which pass fills
// each cell, and how numbers are written. Markers in Markdown name a kind and its
// results files (docs_tables.hpp); the kind turns the loaded files into Markdown lines.

#include <string>
#include <string_view>
#include <vector>

#include "docs_results.hpp"

namespace antumbra::app::docs {

struct TableKind {
  const char* name;
  // Results files the marker must name: exactly `sources`, or at least one when 0.
  int sources;
  // What measures the results (said while a table waits for them).
  const char* measure;
  // The region's lines: what measured it, a blank line, the table. `link_base` is the
  // folder of the Markdown document, relative to the root (links to the results).
  std::vector<std::string> (*generate)(const std::vector<const ResultFile*>& files,
                                       const std::string& link_base);
};

// Every kind: moving, vis, table1, penumbra, dynamic, materials, pages (bench.json); quality,
// quality-overlap and ranking (quality JSON, one file per size).
const std::vector<TableKind>& table_kinds();
// nullptr when no kind has that name.
const TableKind* find_table_kind(std::string_view name);

// The kinds by results type (docs_bench_tables.cpp, docs_quality_tables.cpp).
std::vector<TableKind> bench_table_kinds();
std::vector<TableKind> quality_table_kinds();

// A Markdown table: the header row, the delimiter row, one line per row.
std::vector<std::string> markdown_table(const std::vector<std::string>& header,
                                        const std::vector<std::vector<std::string>>& rows);
// "[moving.json](results/moving.json)": the results file linked from a document in
// `link_base` (relative to the root).
std::string results_link(const ResultFile& file, const std::string& link_base);
// "Measured at commit `abc` on NVIDIA H200 (driver NVIDIA 570.86)" for the files, grouped
// where they share commit, device and driver, each group listing its files' links.
std::string provenance(const std::vector<const ResultFile*>& files, const std::string& link_base);

}  // namespace antumbra::app::docs
