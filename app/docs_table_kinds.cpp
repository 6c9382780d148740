#include "docs_table_kinds.hpp"

#include <algorithm>
#include <filesystem>
#include <tuple>

namespace antumbra::app::docs {

const std::vector<TableKind>& table_kinds() {
  static const std::vector<TableKind> kKinds = [] {
    auto kinds = bench_table_kinds();
    for (auto& kind : quality_table_kinds()) kinds.push_back(kind);
    return kinds;
  }();
  return kKinds;
}

const TableKind* find_table_kind(std::string_view name) {
  const auto& kinds = table_kinds();
  const auto it = std::find_if(kinds.begin(), kinds.end(),
                               [&](const TableKind& kind) { return name == kind.name; });
  return it == kinds.end() ? nullptr : &*it;
}

namespace {

std::string row_line(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const auto& cell : cells) line += " " + cell + " |";
  return line;
}

}  // namespace

std::vector<std::string> markdown_table(const std::vector<std::string>& header,
                                        const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::string> lines{row_line(header),
                                 row_line(std::vector<std::string>(header.size(), "---"))};
  for (const auto& row : rows) lines.push_back(row_line(row));
  return lines;
}

std::string results_link(const ResultFile& file, const std::string& link_base) {
  const std::filesystem::path target(file.path());
  const auto relative = target.lexically_relative(link_base.empty() ? "." : link_base);
  std::string link = "[";  // piece by piece: GCC 12 warns (-Wrestrict) on "a" + s
  link += target.filename().string();
  return link + "](" + relative.generic_string() + ")";
}

std::string provenance(const std::vector<const ResultFile*>& files, const std::string& link_base) {
  // Groups in the order their first file comes.
  using Key = std::tuple<std::string, std::string, std::string>;
  std::vector<std::pair<Key, std::vector<const ResultFile*>>> groups;
  for (const auto* file : files) {
    const Key key{file->text("commit"), file->text("device"), file->text("driver")};
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& group) { return group.first == key; });
    if (it == groups.end()) it = groups.insert(groups.end(), {key, {}});
    it->second.push_back(file);
  }
  std::string text;
  for (const auto& [key, members] : groups) {
    if (!text.empty()) text += "; ";
    text += "Measured at commit `" + std::get<0>(key) + "` on " + std::get<1>(key) + " (driver " +
            std::get<2>(key) + "): ";
    for (std::size_t i = 0; i < members.size(); ++i) {
      text += (i > 0 ? ", " : "") + results_link(*members[i], link_base);
    }
  }
  return text + ".";
}

}  // namespace antumbra::app::docs
