#pragma once
// Shared by the editor model tests: fixture paths, a scratch directory per test, and
// fake pass reflections for the graph document (the real ones live with the Vulkan
// passes).

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/fg/registry.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor::testing {

// tests/data/editor/<name>
std::filesystem::path fixture(const std::string& name);
// <source root>/<relative>
std::filesystem::path source_file(const std::string& relative);
std::string read(const std::filesystem::path& file);
// The value of a result that must be good; a bad one fails the test with its diagnostics
// (as an exception) instead of reaching an empty value.
template <class T>
T take(base::Result<T> result) {
  if (!result.ok()) throw std::runtime_error(result.diagnostics().to_text());
  return std::move(result.value());
}
void write(const std::filesystem::path& file, const std::string& text);
// The lines of `text`, without their line ends.
std::vector<std::string> lines(const std::string& text);
// The lines of `b` that differ from `a` (the same line count is expected).
std::vector<std::string> changed_lines(const std::string& a, const std::string& b);
// Every field of every light equal, in order (gtest failures name the light).
void expect_same_lights(const std::vector<scene::PointLight>& expected,
                        const std::vector<scene::PointLight>& actual);

// A fresh directory under the system temp directory, removed with everything in it.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // Copies a fixture in and returns the copy's path.
  std::filesystem::path copy(const std::filesystem::path& from, const std::string& as = {}) const;
  // Files in the directory (names only), sorted: to prove no temporary is left behind.
  [[nodiscard]] std::vector<std::string> files() const;

 private:
  std::filesystem::path path_;
};

// light-layering (maxLayers integer 1..32, order enum), lighting (ambient number 0..4),
// tonemap (exposure number 0..16, operator enum, enabled bool), blur (optional image
// `src` and buffer `weights` in, image `dst` out of src's size: structural edits) and
// shadow-pcss, so that the fixture and the shipped graphs can be edited in tests; all but
// the last with ports, so that live_graph.json compiles (the edit session's tests).
fg::Registry make_fake_registry();

}  // namespace antumbra::editor::testing
