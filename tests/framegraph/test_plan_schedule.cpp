// Schedule analysis (fg/plan_schedule.hpp): hand-made DAGs with answers worked out by
// hand, then the dependencies and schedule of compiled plans.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "antumbra/fg/plan_schedule.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

DepEdge edge(int from, int to) {
  return {from, to, EdgeKind::read_after_write, -1};
}

// a(1) -> b(2) -> d(1), a -> c(3) -> d: the path through c is the longest.
ScheduleInput diamond(std::vector<bool> async) {
  return {{1, 2, 3, 1}, std::move(async), {edge(0, 1), edge(0, 2), edge(1, 3), edge(2, 3)}};
}

TEST(Schedule, DiamondStartsSlackAndCriticalPath) {
  const Schedule s = analyse_schedule(diamond({}));
  EXPECT_DOUBLE_EQ(s.serial, 7);
  EXPECT_DOUBLE_EQ(s.critical, 5);
  EXPECT_EQ(s.critical_path, (std::vector<int>{0, 2, 3}));
  const std::vector<double> earliest{0, 1, 1, 4};
  const std::vector<double> latest{0, 2, 1, 4};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(s.passes[i].earliest_start, earliest[i]) << i;
    EXPECT_DOUBLE_EQ(s.passes[i].latest_start, latest[i]) << i;
    EXPECT_DOUBLE_EQ(s.passes[i].slack, latest[i] - earliest[i]) << i;
  }
  EXPECT_TRUE(s.passes[2].critical);
  EXPECT_FALSE(s.passes[1].critical);
  EXPECT_EQ(s.passes[3].depends_on, (std::vector<int>{1, 2}));
  // Nothing may run on the compute queue: nothing to gain.
  EXPECT_DOUBLE_EQ(s.overlap_bound, 0);
}

TEST(Schedule, OverlapBoundIsTheSmallestOfItsThreeLimits) {
  // b on the compute queue beside c: at best 2 (serial 7 - critical 5).
  EXPECT_DOUBLE_EQ(analyse_schedule(diamond({false, true, false, false})).overlap_bound, 2);
  // c alone eligible (3): still limited by the critical path.
  EXPECT_DOUBLE_EQ(analyse_schedule(diamond({false, false, true, false})).overlap_bound, 2);
  // a(1) eligible: a has no partner to overlap with, but the bound only knows it is 1.
  EXPECT_DOUBLE_EQ(analyse_schedule(diamond({true, false, false, false})).overlap_bound, 1);
}

TEST(Schedule, ComputeWorkOnTheCriticalPathStillOverlapsGraphicsWork) {
  // a(4) compute, b(1) graphics, independent: a on the compute queue, b beside it on the
  // graphics queue, the frame takes 4 instead of 5. Counting only compute work off the
  // critical path would say 0.
  const Schedule s = analyse_schedule({{4, 1}, {true, false}, {}});
  EXPECT_DOUBLE_EQ(s.critical, 4);
  EXPECT_EQ(s.critical_path, (std::vector<int>{0}));
  EXPECT_DOUBLE_EQ(s.passes[1].slack, 3);
  EXPECT_DOUBLE_EQ(s.overlap_bound, 1);
}

TEST(Schedule, TwoQueuesHalveTheSerialTimeAtBest) {
  // Three independent compute passes of 2: critical 2, but two queues need 3.
  const Schedule s = analyse_schedule({{2, 2, 2}, {true, true, true}, {}});
  EXPECT_DOUBLE_EQ(s.critical, 2);
  EXPECT_DOUBLE_EQ(s.overlap_bound, 3);
}

TEST(Schedule, AChainCannotOverlap) {
  const Schedule s = analyse_schedule({{1, 2, 3}, {true, true, true}, {edge(0, 1), edge(1, 2)}});
  EXPECT_DOUBLE_EQ(s.critical, 6);
  EXPECT_DOUBLE_EQ(s.serial, 6);
  EXPECT_DOUBLE_EQ(s.overlap_bound, 0);
  EXPECT_EQ(s.critical_path, (std::vector<int>{0, 1, 2}));
}

TEST(Schedule, EqualPathsPickTheLowestIndices) {
  // 0 -> 2, 1 -> 2 with equal weights: the path through 0.
  const Schedule s = analyse_schedule({{1, 1, 1}, {}, {edge(1, 2), edge(0, 2)}});
  EXPECT_EQ(s.critical_path, (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(s.passes[1].slack, 0);  // also critical, though not the one reported
}

TEST(Schedule, EmptyAndBadInput) {
  const Schedule empty = analyse_schedule({});
  EXPECT_TRUE(empty.critical_path.empty());
  EXPECT_DOUBLE_EQ(empty.critical, 0);
  EXPECT_THROW(analyse_schedule({{1, 1}, {}, {edge(0, 1), edge(1, 0)}}), std::invalid_argument);
  EXPECT_THROW(analyse_schedule({{1}, {}, {edge(0, 3)}}), std::invalid_argument);
}

Plan compile_after(bool keep_after) {
  std::string text = testing::read_text(testing::data_path("graphs/good/after.json"));
  if (!keep_after) {
    const std::string entry = R"(, "after": ["gbuffer"])";
    text.erase(text.find(entry), entry.size());
  }
  auto result = testing::compile_json(text);
  EXPECT_TRUE(result.ok()) << result.diagnostics().to_text();
  return result.value();
}

std::vector<std::string> names(const Plan& plan, const std::vector<int>& indices) {
  std::vector<std::string> out;
  out.reserve(indices.size());
  for (int i : indices) out.push_back(plan.passes[static_cast<std::size_t>(i)].name);
  return out;
}

TEST(PlanSchedule, DependenciesFollowTheBindingsAndAfter) {
  const Plan plan = compile_after(true);
  ASSERT_EQ(testing::pass_names(plan), (std::vector<std::string>{"gbuffer", "lightList", "lighting",
                                                                 "quarter", "mix", "tonemap"}));
  EXPECT_EQ(plan.passes[1].after, (std::vector<int>{0}));
  const auto edges = plan_dependencies(plan);
  const auto has = [&](int from, int to, EdgeKind kind) {
    return std::any_of(edges.begin(), edges.end(), [&](const DepEdge& e) {
      return e.from == from && e.to == to && e.kind == kind;
    });
  };
  EXPECT_TRUE(has(0, 1, EdgeKind::after));
  EXPECT_TRUE(has(0, 2, EdgeKind::read_after_write));
  EXPECT_TRUE(has(1, 2, EdgeKind::read_after_write));
  EXPECT_TRUE(has(3, 4, EdgeKind::read_after_write));
  EXPECT_FALSE(has(0, 5, EdgeKind::read_after_write));
  const Schedule s = analyse_schedule(schedule_input(plan, unit_weights(plan)));
  EXPECT_DOUBLE_EQ(s.critical, 6);
  EXPECT_DOUBLE_EQ(s.overlap_bound, 0);
}

TEST(PlanSchedule, WithoutAfterTheLightListOverlaps) {
  const Plan plan = compile_after(false);
  // File order breaks the tie: the light list runs first.
  ASSERT_EQ(plan.passes[0].name, "lightList");
  const Schedule s = analyse_schedule(schedule_input(plan, unit_weights(plan)));
  EXPECT_DOUBLE_EQ(s.serial, 6);
  EXPECT_DOUBLE_EQ(s.critical, 5);
  // Two paths of 5 (through the light list or the G-buffer): the lower index is reported.
  EXPECT_EQ(names(plan, s.critical_path),
            (std::vector<std::string>{"lightList", "lighting", "quarter", "mix", "tonemap"}));
  EXPECT_TRUE(async_eligible(plan.passes[0]));
  EXPECT_FALSE(async_eligible(*plan.find_pass("gbuffer")));
  EXPECT_DOUBLE_EQ(s.passes[1].slack, 0);
  // The light list and the blur are compute (2), but only 1 is off the critical length.
  EXPECT_DOUBLE_EQ(s.async_total, 2);
  EXPECT_DOUBLE_EQ(s.overlap_bound, 1);
}

TEST(PlanSchedule, JsonNamesPassesAndSaysWhereTheWeightsCameFrom) {
  const Plan plan = compile_after(false);
  const std::map<std::string, double> by_name{{"lightList", 0.25}, {"gbuffer", 0.5},
                                              {"lighting", 1},     {"quarter", 0.125},
                                              {"mix", 0.5},        {"tonemap", 0.25}};
  std::vector<double> ms;
  for (const PlanPass& pass : plan.passes) ms.push_back(by_name.at(pass.name));
  const Schedule s = analyse_schedule(schedule_input(plan, ms));
  const Json j = schedule_to_json(plan, s, "bench.json (scenario x)");
  EXPECT_EQ(j["weights"], "bench.json (scenario x)");
  EXPECT_DOUBLE_EQ(j["serialMs"].get<double>(), 2.625);
  EXPECT_DOUBLE_EQ(j["criticalMs"].get<double>(), 2.375);
  // Light list + blur on the compute queue (0.375), but the frame cannot beat 2.375.
  EXPECT_DOUBLE_EQ(j["asyncEligibleMs"].get<double>(), 0.375);
  EXPECT_DOUBLE_EQ(j["overlapBoundMs"].get<double>(), 0.25);
  EXPECT_EQ(j["criticalPath"].front(), "gbuffer");
  EXPECT_EQ(j["passes"][2]["name"], "lighting");
  EXPECT_EQ(j["passes"][2]["dependsOn"], Json::array({"lightList", "gbuffer"}));
  EXPECT_DOUBLE_EQ(j["passes"][0]["slackMs"].get<double>(), 0.25);
  EXPECT_EQ(j["passes"][0]["asyncEligible"], true);
  const std::string text = schedule_summary_text(plan, s, "unit");
  EXPECT_NE(text.find("critical path"), std::string::npos) << text;
}

}  // namespace
}  // namespace antumbra::fg
