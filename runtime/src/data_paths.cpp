#include "antumbra/runtime/data_paths.hpp"

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace antumbra::runtime {
namespace {

bool is_root(const std::filesystem::path& dir) {
  std::error_code ec;
  return std::filesystem::is_directory(dir / "data", ec) &&
         std::filesystem::is_directory(dir / "passes", ec);
}

std::filesystem::path search_up(std::filesystem::path dir) {
  while (!dir.empty()) {
    if (is_root(dir)) return dir;
    if (dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return {};
}

}  // namespace

DataPaths find_data_paths() {
  std::vector<std::string> tried;
  if (const char* env = std::getenv("ANTUMBRA_ROOT"); env != nullptr && *env != '\0') {
    if (is_root(env)) return {std::filesystem::absolute(env)};
    throw DataPathsError(std::string("ANTUMBRA_ROOT=") + env + " does not hold data/ and passes/");
  }
  std::error_code ec;
  const auto cwd = std::filesystem::current_path(ec);
  if (!ec) {
    if (auto found = search_up(cwd); !found.empty()) return {found};
    tried.push_back(cwd.string());
  }
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    if (auto found = search_up(exe.parent_path()); !found.empty()) return {found};
    tried.push_back(exe.parent_path().string());
  }
#ifdef ANTUMBRA_SOURCE_DIR
  if (is_root(ANTUMBRA_SOURCE_DIR)) return {ANTUMBRA_SOURCE_DIR};
  tried.emplace_back(ANTUMBRA_SOURCE_DIR);
#endif
  std::string message =
      "cannot find Antumbra's data/ and passes/ folders (set ANTUMBRA_ROOT); searched up from:";
  for (const auto& t : tried) message += "\n  " + t;
  throw DataPathsError(message);
}

}  // namespace antumbra::runtime
