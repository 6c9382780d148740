#pragma once
// The graph description: what a graph file says, checked for structure and types
// but not yet against the pass registry (that is the compiler's job).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/fg/plan.hpp"
#include "antumbra/fg/reflection.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

inline constexpr int kGraphVersion = 1;  // newest graph file version this build reads

struct ResourceDesc {
  std::string name;
  ResourceKind kind = ResourceKind::image;
  Format format = Format::undefined;
  SizeSpec size;
  std::uint32_t layers = 1;
  std::uint64_t buffer_size = 0;  // bytes, for buffers
  bool persistent = false;
  // The host binds its own image at run time ("import": true; docs/integration.md):
  // never created nor aliased, its contents before the frame are the host's.
  bool imported = false;
  std::string pointer;  // "/resources/<name>", for diagnostics
};

struct PortBindingDesc {
  std::string port;
  std::string resource;
  std::string pointer;  // "/passes/<i>/in/<port>"
};

struct PassInstanceDesc {
  std::string name;
  std::string type;
  Json params = Json::object();
  std::vector<PortBindingDesc> inputs;   // "in", in file order
  std::vector<PortBindingDesc> outputs;  // "out", in file order
  std::vector<std::string> after;        // explicit ordering dependencies
  std::optional<bool> side_effects;      // overrides the pass type's default when set
  bool enabled = true;
  std::string pointer;  // "/passes/<i>"
};

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's noexcept move is reported.
struct GraphDesc {
  int version = kGraphVersion;
  std::string name;
  std::vector<ResourceDesc> resources;   // in file order
  std::vector<PassInstanceDesc> passes;  // in file order
  std::string output;
  // The source, so later phases can point diagnostics at line:column. Graphs built
  // in code leave it empty; their diagnostics then carry only the pointer.
  JsonDocument document;

  [[nodiscard]] int find_resource(std::string_view name) const;
  [[nodiscard]] int find_pass(std::string_view name) const;
};

// Checks the document's structure and types (codes FG010-FG029, plus format and
// size syntax FG050-FG057) and builds the description.
Result<GraphDesc> parse_graph(const JsonDocument& document);

// True for [A-Za-z][A-Za-z0-9_.-]*: pass and resource names.
bool is_identifier(std::string_view name);

// "viewport", "viewport/2", "512x256", "scale 0.5x0.25": for messages and plan files.
std::string describe_size(const SizeSpec& size);
bool operator==(const SizeSpec& a, const SizeSpec& b);

}  // namespace antumbra::fg
