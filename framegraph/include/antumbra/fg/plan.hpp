#pragma once
// The compiled plan: everything the executor needs, in plain data. Produced by
// compile() (compiler.hpp) from a GraphDesc and a Registry; consumed by the Vulkan
// executor, the CLI (`plan`), the editor and golden tests.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"

namespace antumbra::fg {

// Size of an image resource: absolute, or relative to the viewport.
struct SizeSpec {
  bool relative = true;  // true: scale * viewport; false: width x height
  double scale_x = 1.0;
  double scale_y = 1.0;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

struct Extent2D {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  bool operator==(const Extent2D&) const = default;
};

// A memory footprint as the allocator sees it.
struct Footprint {
  std::uint64_t size = 0;
  std::uint64_t alignment = 1;
};

struct PlanResource {
  std::string name;
  ResourceKind kind = ResourceKind::image;
  Format format = Format::undefined;
  SizeSpec size;
  Extent2D extent;  // resolved against the viewport the plan was compiled for
  std::uint32_t layers = 1;
  std::uint64_t buffer_size = 0;  // bytes, for buffers
  bool persistent = false;        // keeps contents across frames (never aliased)
  bool is_output = false;         // the graph's output
  bool imported = false;          // the host's image, bound at run time (never created)
  // Lifetime in execution order (indices into Plan::passes); -1 if unused.
  int first_use = -1;
  int last_use = -1;
  std::vector<Access> usages;  // every distinct access, for usage flags
  // Aliasing: transient resources share one heap at these offsets.
  bool aliased = false;  // placed in the shared transient heap
  std::uint64_t heap_offset = 0;
  Footprint footprint;
};

struct PlanBinding {
  std::string port;
  int resource = -1;  // index into Plan::resources, -1 for an unbound optional port
  Access access = Access::none;
  Stage stage = Stage::none;
};

// Where a barrier's source state comes from. The executor records the source the plan
// names and checks its own record of each resource against it (fgvk::source_mismatch,
// docs/architecture.md section 4); only what the plan cannot know, the frame before a
// plan's first one, comes from that record.
enum class BarrierSource : std::uint8_t {
  // An earlier pass of this frame left the resource in (from, from_stage).
  this_frame,
  // The resource's first use in the frame; it keeps its memory between frames (persistent,
  // or the output), and the previous frame left it in (from, from_stage): its last access
  // there, the host's copy (transfer_src) for the output. On a plan's first frame the
  // previous frame was another plan's, or none (a new resource is undefined).
  last_frame,
  // The first use of an aliased (transient) resource: its heap memory was last used by
  // other resources, in this frame or the last, whose every earlier access and write must
  // finish first. from is none (the resource has no earlier access) and discard is set.
  aliased_memory,
  // The first use of an imported resource: the host's image, in the state the host says
  // it leaves it in before the frame (fgvk::ImportedImage::before); from is none.
  imported,
};
std::string_view to_string(BarrierSource source);

// One state change of one resource, placed before the pass that needs it.
struct PlanBarrier {
  int resource = -1;
  Access from = Access::none;  // the state `source` left the resource in
  Stage from_stage = Stage::none;
  Access to = Access::none;
  Stage to_stage = Stage::none;
  bool discard = false;  // previous contents not needed (first use of a transient or the output)
  BarrierSource source = BarrierSource::this_frame;
  // A final barrier of an imported resource: its target is the state the host wants the
  // image in after the frame (fgvk::ImportedImage::after); to is none.
  bool to_host = false;
};

// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's noexcept move is reported.
struct PlanPass {
  std::string name;
  std::string type;
  int source_index = -1;  // index in the description's "passes" array
  Json params;            // every parameter, defaults filled in
  std::vector<PlanBinding> bindings;
  std::vector<PlanBarrier> barriers;  // executed before the pass
  // The executed passes its "after" names (indices into Plan::passes, ascending): order
  // the bindings do not show, kept for the schedule analysis (plan_schedule.hpp).
  std::vector<int> after;
};

struct AliasingReport {
  std::uint64_t bytes_without_aliasing = 0;
  std::uint64_t heap_bytes = 0;
  [[nodiscard]] std::uint64_t bytes_saved() const { return bytes_without_aliasing - heap_bytes; }
};

struct Plan {
  std::string name;
  std::string file;
  Extent2D viewport;
  std::vector<PlanResource> resources;
  std::vector<PlanPass> passes;              // executed passes, in order
  std::vector<std::string> culled_passes;    // names, in description order
  std::vector<std::string> disabled_passes;  // "enabled": false, in description order
  int output = -1;                           // index into resources
  // After the last pass: the output -> transfer_src (the host copies it out), every
  // imported resource (an imported output too) -> the host's state.
  std::vector<PlanBarrier> final_barriers;
  AliasingReport aliasing;

  [[nodiscard]] int find_resource(std::string_view name) const;
  [[nodiscard]] const PlanPass* find_pass(std::string_view name) const;
};

}  // namespace antumbra::fg
