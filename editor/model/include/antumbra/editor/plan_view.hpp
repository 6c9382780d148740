#pragma once
// The plan view's model, without a window: what the compiler decided for the running
// graph, read from the plan's JSON (fg::plan_to_json, the same text `antumbra plan
// --format json` prints, so the view and the command cannot disagree): passes in
// execution order with their barriers and GPU times, each transient resource's lifetime
// over those passes, which resources share memory through aliasing, what aliasing saved,
// and the schedule (critical path, async-compute bound) when the plan carries one.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/base/json_document.hpp"

namespace antumbra::editor {

struct PlanViewBarrier {
  std::string resource;
  std::string source;  // "this_frame", "aliased_memory", "previous_frame", ...
  std::string from;
  std::string from_stage;
  std::string to;
  std::string to_stage;
  bool discard = false;
  // "depth: depth_attachment (fragment) -> sampled (compute)", for the hover.
  [[nodiscard]] std::string text() const;
};

struct PlanViewPass {
  std::string name;
  std::string type;
  std::vector<PlanViewBarrier> barriers;  // recorded before the pass
  std::optional<double> gpu_ms;           // measured; none before the first timings
  bool critical = false;                  // on the schedule's critical path
};

struct PlanViewLifetime {
  std::string resource;
  std::string kind;    // "image" or "buffer"
  std::string detail;  // "rgba16f viewport/2 x1" or "16400 bytes"
  int first = -1;      // index into PlanView::passes of its first use
  int last = -1;       // and its last
  bool persistent = false;
  bool imported = false;
  bool aliased = false;
  std::uint64_t offset = 0;  // in the transient heap, when aliased
  std::uint64_t bytes = 0;
  // The other resources whose heap ranges overlap this one's (their lifetimes do not):
  // the same memory, at different times of the frame.
  std::vector<std::string> shares_with;
};

struct PlanViewSchedule {
  std::vector<std::string> critical_path;
  double critical_ms = 0.0;
  double serial_ms = 0.0;
  double overlap_bound_ms = 0.0;
  std::string weights;  // "unit" or where the times came from
};

struct PlanView {
  std::string name;
  std::vector<PlanViewPass> passes;
  std::vector<PlanViewLifetime> lifetimes;  // in the plan's resource order
  std::vector<PlanViewBarrier> final_barriers;
  std::vector<std::string> culled;
  std::vector<std::string> disabled;
  std::uint64_t bytes_without_aliasing = 0;
  std::uint64_t heap_bytes = 0;
  std::uint64_t bytes_saved = 0;
  std::optional<PlanViewSchedule> schedule;
};

// Reads a plan's JSON; missing keys leave the defaults (the view never throws on a plan).
[[nodiscard]] PlanView build_plan_view(const base::Json& plan);

// Pass name -> measured GPU ms: sets each pass's gpu_ms.
void set_pass_times(PlanView& view, const std::map<std::string, double, std::less<>>& times);

// "3.6 MiB", "512 KiB", "96 B".
[[nodiscard]] std::string byte_text(std::uint64_t bytes);

}  // namespace antumbra::editor
