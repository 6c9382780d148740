// `plan --times`: a bench.json scenario's per-pass medians as the plan's schedule weights,
// and the errors that say which file, scenario and pass are at fault.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "plan_times.hpp"
#include "synthetic_bench.hpp"

namespace antumbra::app {
namespace {

using test::bench_json;
using test::scenario;
using test::write_file;

fg::Plan plan_of(const std::vector<std::string>& names) {
  fg::Plan plan;
  for (const auto& name : names) {
    fg::PlanPass pass;
    pass.name = name;
    plan.passes.push_back(std::move(pass));
  }
  return plan;
}

BenchFile bench_file(const nlohmann::json& json) {
  return load_bench_file(write_file("bench.json", json.dump(2)).string());
}

// The message of the PlanTimesError the call throws ("" when it throws none).
template <class F>
std::string error_of(F&& call) {
  try {
    call();
  } catch (const PlanTimesError& e) {
    return e.what();
  }
  return {};
}

TEST(PlanTimes, TheOnlyScenarioGivesEveryPassItsMedianInPlanOrder) {
  const auto bench = bench_file(
      bench_json("GPU A", {scenario("t/a", 3.5, {{"light", 0.5}, {"gbuffer", 1.0}, {"x", 2.0}})}));
  const auto times = plan_times(plan_of({"gbuffer", "light"}), bench, "");
  EXPECT_EQ(times.ms, (std::vector<double>{1.0, 0.5}));
  EXPECT_NE(times.source.find("scenario t/a on GPU A"), std::string::npos) << times.source;
}

TEST(PlanTimes, SeveralScenariosNeedOneNamed) {
  const auto bench = bench_file(bench_json(
      "GPU A", {scenario("t/a", 1, {{"gbuffer", 1.0}}), scenario("t/b", 2, {{"gbuffer", 2.0}})}));
  const auto plan = plan_of({"gbuffer"});
  EXPECT_EQ(plan_times(plan, bench, "t/b").ms, (std::vector<double>{2.0}));
  const std::string which = error_of([&] { plan_times(plan, bench, ""); });
  EXPECT_NE(which.find("has 2 scenarios; pick one with --scenario: 't/a', 't/b'"),
            std::string::npos)
      << which;
  const std::string typo = error_of([&] { plan_times(plan, bench, "t/c"); });
  EXPECT_NE(typo.find("no scenario 't/c'; did you mean 't/a'?"), std::string::npos) << typo;
}

TEST(PlanTimes, AFailedScenarioOrAMissingPassIsRefusedWithItsPlace) {
  const auto bench = bench_file(bench_json(
      "GPU A", {scenario("t/a", 1, {{"gbuffer", 1.0}}), scenario("t/bad", 0, {}, "invalid")}));
  const std::string failed = error_of([&] { plan_times(plan_of({"gbuffer"}), bench, "t/bad"); });
  EXPECT_NE(failed.find("scenario 't/bad' (at /scenarios/1) did not run (status invalid"),
            std::string::npos)
      << failed;
  const std::string missing = error_of([&] {
    plan_times(plan_of({"gbuffer", "tonemap"}), bench, "t/a");
  });
  EXPECT_NE(missing.find("(at /scenarios/0) has no time for the plan's pass(es) 'tonemap'"),
            std::string::npos)
      << missing;
}

TEST(PlanTimes, AMalformedFileIsLocated) {
  auto json = bench_json("GPU A", {scenario("t/a", 1, {{"gbuffer", 1.0}})});
  json["scenarios"][0]["passes"][0]["medianMs"] = "fast";
  const auto file = write_file("bad.json", json.dump(2)).string();
  try {
    load_plan_times(plan_of({"gbuffer"}), file, "");
    FAIL() << "a string median was accepted";
  } catch (const BaselineError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("/scenarios/0/passes/0/medianMs"), std::string::npos) << text;
    EXPECT_NE(text.find("bad.json:"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace antumbra::app
