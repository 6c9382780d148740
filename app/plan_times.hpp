#pragma once
// `antumbra plan --times bench.json [--scenario NAME]`: the per-pass GPU medians of one
// scenario of a bench.json (`antumbra bench`) as the weights of the plan's schedule
// analysis (fg/plan_schedule.hpp), so the critical path and the async-compute bound are
// stated in measured milliseconds. No device: tested on synthetic files
// (tests/bench/plan_times_test.cpp).

#include <stdexcept>
#include <string>
#include <vector>

#include "antumbra/fg/plan.hpp"
#include "bench_baseline.hpp"

namespace antumbra::app {

// A bench.json that cannot give the plan its times: the message names the file, the
// scenario (by name and JSON Pointer) and what is missing.
class PlanTimesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PlanTimes {
  std::vector<double> ms;  // one per Plan::passes entry
  std::string source;      // "FILE scenario NAME", and the device when the file names one
};

// The scenario named `scenario`, or the file's only one when `scenario` is empty; every
// executed pass of the plan must have a median there (passes the scenario timed but the
// plan lacks are ignored). Throws PlanTimesError.
PlanTimes plan_times(const fg::Plan& plan, const BenchFile& bench, const std::string& scenario);

// load_bench_file (located errors for unreadable or malformed files) then plan_times.
// Throws BaselineError or PlanTimesError.
PlanTimes load_plan_times(const fg::Plan& plan, const std::string& file,
                          const std::string& scenario);

}  // namespace antumbra::app
