#pragma once
// The graph compiler: GraphDesc + Registry -> Plan. The phases are declared in
// compiler_phases.hpp so tests can drive each one alone.

#include <functional>
#include <optional>
#include <string>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/fg/plan.hpp"
#include "antumbra/fg/registry.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

using FootprintFn = std::function<Footprint(const PlanResource&)>;

// Images: width*height*layers*bytes_per_texel rounded up to 64 KiB (aligned to
// 64 KiB); buffers: size rounded up to 256 bytes (aligned to 256). The executor
// passes a callback that asks the driver instead.
Footprint default_footprint(const PlanResource& resource);

struct CompileOptions {
  Extent2D viewport{1280, 720};
  FootprintFn footprint = default_footprint;
  // The device the plan is for; none: "auto" parameters choose by the graph alone.
  std::optional<DeviceTraits> device;
};

// Runs every phase; stops at the first phase that reports errors. Warnings and
// notes (unused resources, culled passes) accompany a successful plan.
Result<Plan> compile(const GraphDesc& graph, const Registry& registry,
                     const CompileOptions& options = {});

// compile_graph() (fg/graph_source.hpp, the one load path) of GraphSource::from_file.
Result<Plan> compile_file(const std::string& path, const Registry& registry,
                          const CompileOptions& options = {});
// compile_graph() of GraphSource::from_text: text already in memory (tests, tools).
Result<Plan> compile_text(std::string_view text, const std::string& file, const Registry& registry,
                          const CompileOptions& options = {});

}  // namespace antumbra::fg
