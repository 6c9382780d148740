#include "antumbra/runtime/data_paths.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace antumbra::runtime {
namespace {

// Written by CMake into the top of every build folder and never installed
// (docs/integration.md, "Installing and finding the package"): a build outside its source
// tree still finds that tree, while no library or program carries the path.
constexpr const char* kSourceDirMarker = "antumbra-source-dir.txt";

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

// The source tree named by the marker of the build folder holding `dir`, if any.
std::filesystem::path build_tree_source(std::filesystem::path dir) {
  while (!dir.empty()) {
    std::ifstream marker(dir / kSourceDirMarker);
    std::string source;
    if (marker && std::getline(marker, source) && is_root(source)) return source;
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
    const auto bin = exe.parent_path();
    // An installed program: <prefix>/bin/antumbra beside <prefix>/share/antumbra, checked
    // before the folders above it so that a prefix inside a clone still uses its own copy.
    const auto installed = (bin / ".." / "share" / "antumbra").lexically_normal();
    if (is_root(installed)) return {installed};
    tried.push_back(installed.string());
    if (auto found = search_up(bin); !found.empty()) return {found};
    tried.push_back(bin.string());
    if (auto found = build_tree_source(bin); !found.empty()) return {found};
  }
  std::string message =
      "cannot find Antumbra's data/ and passes/ folders (set ANTUMBRA_ROOT); searched:";
  for (const auto& t : tried) message += "\n  " + t;
  throw DataPathsError(message);
}

}  // namespace antumbra::runtime
