#pragma once
// Which lines an edit changed: the lines between the longest common start and end of two
// texts, as they were and as they are (what a diff tool shows as one hunk).
#include <sstream>
#include <string>
#include <vector>

namespace antumbra::editor::testing {

struct LineDiff {
  std::vector<std::string> removed;
  std::vector<std::string> added;
};

inline std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

inline LineDiff line_diff(const std::string& before, const std::string& after) {
  const auto a = split_lines(before);
  const auto b = split_lines(after);
  std::size_t start = 0;
  while (start < a.size() && start < b.size() && a[start] == b[start]) ++start;
  std::size_t end = 0;
  while (end < a.size() - start && end < b.size() - start &&
         a[a.size() - 1 - end] == b[b.size() - 1 - end]) {
    ++end;
  }
  return {
      {a.begin() + static_cast<std::ptrdiff_t>(start), a.end() - static_cast<std::ptrdiff_t>(end)},
      {b.begin() + static_cast<std::ptrdiff_t>(start), b.end() - static_cast<std::ptrdiff_t>(end)}};
}

}  // namespace antumbra::editor::testing
