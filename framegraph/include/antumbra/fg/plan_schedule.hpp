#pragma once
// What the dependencies between a plan's passes allow: the critical path through them, the
// slack of every pass, and a bound on what running work on an async compute queue beside
// the graphics queue could save at best. The evidence for or against async compute
// (issue 31); docs/architecture.md, section 3 ("Schedule analysis"), defines every number.
//
// The plan runs its passes one after another on one queue, so a frame costs the serial
// total. Two queues could overlap independent passes; no schedule on them beats
//   max(critical, graphics-only work, serial / 2),
// so the saving is at most overlap_bound = serial - that max
//   = min(serial - critical, async-eligible work, serial / 2).

#include <string>
#include <vector>

#include "antumbra/fg/compiler_phases.hpp"
#include "antumbra/fg/plan.hpp"

namespace antumbra::fg {

// A DAG to schedule: node weights (ms, or 1 per node), which nodes could run on an async
// compute queue, and edges (from must finish before to starts). Built from a plan by
// schedule_input(), or by hand in tests.
struct ScheduleInput {
  std::vector<double> weights;       // >= 0, one per node
  std::vector<bool> async_eligible;  // one per node; missing entries count as false
  std::vector<DepEdge> edges;        // DepEdge::from/to index the nodes
};

struct PassTiming {
  double weight = 0;
  double earliest_start = 0;    // every predecessor done, with unlimited queues
  double latest_start = 0;      // the latest start that keeps the critical length
  double slack = 0;             // latest_start - earliest_start
  bool critical = false;        // on the reported critical path
  std::vector<int> depends_on;  // direct predecessors, ascending
};

struct Schedule {
  std::vector<PassTiming> passes;  // one per node (Plan::passes order for a plan)
  std::vector<int> critical_path;  // one longest weighted path, first node first
  double critical = 0;             // its length
  double serial = 0;               // sum of all weights: the plan as it runs today
  double async_total = 0;          // sum of the weights of async-eligible nodes
  // min(serial - critical, async_total, serial / 2): an upper bound on the saving of any
  // two-queue schedule (header comment); 0 when nothing may run on the compute queue.
  double overlap_bound = 0;
};

// Earliest and latest starts, slack, a critical path and the totals. The critical path is
// the longest weighted path; among equal ones, the one ending at the lowest node index,
// reached through the lowest-index predecessor at each step. Throws std::invalid_argument
// when the edges form a cycle or name a node out of range (a compiled plan never does).
Schedule analyse_schedule(const ScheduleInput& input);

// The dependencies the plan's barriers encode, between indices into Plan::passes:
// read-after-write (the last earlier writer), write-after-read, write-after-write, and
// the plan's "after" edges (PlanPass::after). DepEdge::resource indexes Plan::resources
// (-1 for "after"). A persistent resource's read of last frame's contents orders nothing
// within the frame. Sorted, without duplicates.
std::vector<DepEdge> plan_dependencies(const Plan& plan);

// True when the pass could be recorded on a compute-only queue: it binds at least one
// resource, and every bound port is used in the compute or transfer stage. A pass that
// also draws (an attachment, a vertex or fragment read, "shader" which may mean fragment)
// stays on the graphics queue. Passes that rasterise into memory of their own, outside
// the graph, are invisible here: the bound is an upper bound for the graph as declared.
bool async_eligible(const PlanPass& pass);

// Per-pass weights in Plan::passes order; the totals are in the weights' unit.
ScheduleInput schedule_input(const Plan& plan, const std::vector<double>& weights);
// One per pass: the schedule in passes rather than milliseconds.
std::vector<double> unit_weights(const Plan& plan);

// The "schedule" object of `plan --format json`: "weights" (`weight_source`: "unit" or
// where the times came from), criticalPath (names), criticalMs, serialMs, asyncEligibleMs,
// overlapBoundMs and per pass (execution order) ms, earliestStartMs, latestStartMs,
// slackMs, critical, asyncEligible, dependsOn (names).
Json schedule_to_json(const Plan& plan, const Schedule& schedule, const std::string& weight_source);

// A few lines for `plan --format text`.
std::string schedule_summary_text(const Plan& plan, const Schedule& schedule,
                                  const std::string& weight_source);

}  // namespace antumbra::fg
