// The plan's per-pass weights from a bench.json (plan_times.hpp).
#include "plan_times.hpp"

#include "antumbra/base/text.hpp"
#include "antumbra/fg/registry.hpp"

namespace antumbra::app {
namespace {

std::vector<std::string> scenario_names(const BenchFile& bench) {
  std::vector<std::string> names;
  for (const BenchResult& r : bench.results) names.push_back(r.scenario.name);
  return names;
}

std::string where(const BenchFile& bench, std::size_t index) {
  return bench.file + " scenario " + base::quote_name(bench.results[index].scenario.name) +
         " (at /scenarios/" + std::to_string(index) + ")";
}

std::size_t pick_scenario(const BenchFile& bench, const std::string& scenario) {
  const std::vector<std::string> names = scenario_names(bench);
  if (names.empty()) throw PlanTimesError(bench.file + ": no scenarios to take times from");
  if (scenario.empty()) {
    if (names.size() == 1) return 0;
    throw PlanTimesError(bench.file + " has " + std::to_string(names.size()) +
                         " scenarios; pick one with --scenario: " + base::name_list(names));
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == scenario) return i;
  }
  throw PlanTimesError(bench.file + " has no scenario " + base::quote_name(scenario) +
                       fg::did_you_mean(scenario, names) + " (it has " + base::name_list(names) +
                       ")");
}

}  // namespace

PlanTimes plan_times(const fg::Plan& plan, const BenchFile& bench, const std::string& scenario) {
  const std::size_t index = pick_scenario(bench, scenario);
  const BenchResult& result = bench.results[index];
  if (result.status != "ok") {
    throw PlanTimesError(where(bench, index) + " did not run (status " + result.status +
                         (result.detail.empty() ? "" : ": " + result.detail) + "): no times");
  }
  PlanTimes times;
  std::vector<std::string> missing;
  for (const fg::PlanPass& pass : plan.passes) {
    const PassStats* found = nullptr;
    for (const PassStats& p : result.passes) {
      if (p.name == pass.name) {
        found = &p;
        break;
      }
    }
    if (found == nullptr) missing.push_back(pass.name);
    times.ms.push_back(found == nullptr ? 0.0 : found->gpu.median_ms);
  }
  if (!missing.empty()) {
    std::vector<std::string> timed;
    for (const PassStats& p : result.passes) timed.push_back(p.name);
    throw PlanTimesError(where(bench, index) + " has no time for the plan's pass(es) " +
                         base::name_list(missing) + " (it timed " + base::name_list(timed) +
                         "): measure this graph, or pick its scenario");
  }
  times.source = bench.file + " scenario " + result.scenario.name;
  if (!bench.device.empty()) times.source += " on " + bench.device;
  return times;
}

PlanTimes load_plan_times(const fg::Plan& plan, const std::string& file,
                          const std::string& scenario) {
  return plan_times(plan, load_bench_file(file), scenario);
}

}  // namespace antumbra::app
