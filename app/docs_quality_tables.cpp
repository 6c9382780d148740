// The docs tables read from `antumbra quality --format json`: one results file per size,
// RMSE of display luminance against the area-light reference per graph and region.
#include <algorithm>
#include <filesystem>
#include <numeric>

#include "docs_table_kinds.hpp"

namespace antumbra::app::docs {
namespace {

using Files = std::vector<const ResultFile*>;
using Lines = std::vector<std::string>;
using Rows = std::vector<std::vector<std::string>>;

// The graphs of the first file, by file name, in its order: every other file must have them.
std::vector<std::string> graph_names(const ResultFile& file, const std::string& table) {
  const auto& root = file.root();
  if (!root.contains("graphs") || !root["graphs"].is_array()) {
    file.fail("table '" + table + "' needs the graphs' results (an array at /graphs)", "/graphs");
  }
  std::vector<std::string> names;
  for (const auto& graph : root["graphs"]) {
    if (graph.contains("graph") && graph["graph"].is_string()) {
      names.push_back(std::filesystem::path(graph["graph"].get<std::string>()).filename());
    }
  }
  return names;
}

std::string size_of(const ResultFile& file, const std::string& table) {
  const Located root{&file.root(), ""};
  return std::to_string(static_cast<int>(file.number(root, "/width", table))) + "x" +
         std::to_string(static_cast<int>(file.number(root, "/height", table)));
}

// The RMSE over `region`, "-" when the run had no such region (a reference without depth).
std::string rmse(const ResultFile& file, const Located& graph, const char* region,
                 const std::string& table) {
  const auto& value = *graph.value;
  if (!value.contains("regions") || !value["regions"].is_object() ||
      !value["regions"].contains(region)) {
    return "-";
  }
  return fixed(file.number(graph, "/regions/" + std::string(region) + "/rmse", table), 5);
}

Lines with_provenance(const Files& files, const std::string& link_base, const Lines& table) {
  const std::string scene = std::filesystem::path(files.front()->text("scene")).filename().string();
  Lines lines{provenance(files, link_base) + " `antumbra quality` on `" + scene +
                  "`: RMSE of display luminance against the area-light reference.",
              ""};
  lines.insert(lines.end(), table.begin(), table.end());
  return lines;
}

// Rows: graphs; columns: sizes; cells: RMSE over all / penumbra / `third` pixels.
Lines quality_table(const Files& files, const std::string& link_base, const char* table,
                    const char* third) {
  Lines header{"graph"};
  for (const auto* file : files) {
    header.push_back(size_of(*file, table) + ": all / penumbra / " + third);
  }
  Rows rows;
  for (const auto& graph : graph_names(*files.front(), table)) {
    rows.push_back({"`" + graph + "`"});
    for (const auto* file : files) {
      const Located g = file->quality_graph(graph, table);
      rows.back().push_back(rmse(*file, g, "all", table) + " / " +
                            rmse(*file, g, "penumbra", table) + " / " +
                            rmse(*file, g, third, table));
    }
  }
  return with_provenance(files, link_base, markdown_table(header, rows));
}

// Rows: sizes; columns: each graph's RMSE over all pixels, then their order, best first.
Lines ranking_table(const Files& files, const std::string& link_base) {
  const auto graphs = graph_names(*files.front(), "ranking");
  Lines header{"size"};
  for (const auto& graph : graphs) header.push_back("`" + graph + "`");
  header.emplace_back("ranking (best first)");
  Rows rows;
  for (const auto* file : files) {
    rows.push_back({size_of(*file, "ranking")});
    std::vector<double> errors;
    for (const auto& graph : graphs) {
      const Located g = file->quality_graph(graph, "ranking");
      errors.push_back(file->number(g, "/regions/all/rmse", "ranking"));
      rows.back().push_back(fixed(errors.back(), 5));
    }
    std::vector<std::size_t> order(graphs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return errors[a] < errors[b]; });
    std::string ranking;
    for (const std::size_t i : order) {
      ranking += (ranking.empty() ? "" : ", ") + std::filesystem::path(graphs[i]).stem().string();
    }
    rows.back().push_back(ranking);
  }
  return with_provenance(files, link_base, markdown_table(header, rows));
}

}  // namespace

std::vector<TableKind> quality_table_kinds() {
  return {
      {"quality", 0, "antumbra quality --format json --size WxH --graph ...",
       [](const Files& files, const std::string& link_base) {
         return quality_table(files, link_base, "quality", "silhouette");
       }},
      // Scenes built to overlap penumbrae (tests/data/quality/overlap.json).
      {"quality-overlap", 0, "antumbra quality --format json --scene S --size WxH --graph ...",
       [](const Files& files, const std::string& link_base) {
         return quality_table(files, link_base, "quality-overlap", "overlap");
       }},
      {"ranking", 0, "antumbra quality --format json --size WxH --graph ...", ranking_table},
  };
}

}  // namespace antumbra::app::docs
