// Schedule analysis of a compiled plan (fg/plan_schedule.hpp).
#include "antumbra/fg/plan_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace antumbra::fg {
namespace {

using Adjacency = std::vector<std::vector<int>>;

struct Neighbours {
  Adjacency preds;
  Adjacency succs;
};

Neighbours neighbours(const ScheduleInput& input) {
  const std::size_t n = input.weights.size();
  Neighbours out{Adjacency(n), Adjacency(n)};
  for (const DepEdge& e : input.edges) {
    const bool in_range = e.from >= 0 && e.to >= 0 && static_cast<std::size_t>(e.from) < n &&
                          static_cast<std::size_t>(e.to) < n;
    if (!in_range || e.from == e.to) {
      throw std::invalid_argument("schedule edge " + std::to_string(e.from) + " -> " +
                                  std::to_string(e.to) + " is not between two of " +
                                  std::to_string(n) + " nodes");
    }
    out.preds[static_cast<std::size_t>(e.to)].push_back(e.from);
    out.succs[static_cast<std::size_t>(e.from)].push_back(e.to);
  }
  for (Adjacency* list : {&out.preds, &out.succs}) {
    for (auto& v : *list) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
  }
  return out;
}

// Kahn's algorithm, the lowest ready index first, so the order is deterministic.
std::vector<int> topological_order(const Neighbours& g) {
  const std::size_t n = g.preds.size();
  std::vector<std::size_t> waiting(n);
  std::priority_queue<int, std::vector<int>, std::greater<>> ready;
  for (std::size_t i = 0; i < n; ++i) {
    waiting[i] = g.preds[i].size();
    if (waiting[i] == 0) ready.push(static_cast<int>(i));
  }
  std::vector<int> order;
  while (!ready.empty()) {
    const int p = ready.top();
    ready.pop();
    order.push_back(p);
    for (int s : g.succs[static_cast<std::size_t>(p)]) {
      if (--waiting[static_cast<std::size_t>(s)] == 0) ready.push(s);
    }
  }
  if (order.size() != n) throw std::invalid_argument("schedule edges form a cycle");
  return order;
}

// Sums of milliseconds carry round-off; comparisons of path lengths allow for it.
double tolerance(double total) {
  return 1e-9 * std::max(1.0, total);
}

void compute_starts(const Neighbours& g, const std::vector<int>& order, Schedule& s) {
  for (int p : order) {
    PassTiming& t = s.passes[static_cast<std::size_t>(p)];
    for (int q : g.preds[static_cast<std::size_t>(p)]) {
      const PassTiming& pred = s.passes[static_cast<std::size_t>(q)];
      t.earliest_start = std::max(t.earliest_start, pred.earliest_start + pred.weight);
    }
    s.critical = std::max(s.critical, t.earliest_start + t.weight);
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    PassTiming& t = s.passes[static_cast<std::size_t>(*it)];
    double finish = s.critical;
    for (int q : g.succs[static_cast<std::size_t>(*it)]) {
      finish = std::min(finish, s.passes[static_cast<std::size_t>(q)].latest_start);
    }
    t.latest_start = finish - t.weight;
    t.slack = t.latest_start - t.earliest_start;
    if (t.slack < tolerance(s.critical)) t.slack = 0;
  }
}

// Back from the lowest-index node that finishes last, through the lowest-index predecessor
// that finishes exactly when the current node may start.
void trace_critical_path(const Neighbours& g, Schedule& s) {
  const double eps = tolerance(s.critical);
  int at = -1;
  for (std::size_t i = 0; i < s.passes.size() && at < 0; ++i) {
    if (s.passes[i].earliest_start + s.passes[i].weight >= s.critical - eps)
      at = static_cast<int>(i);
  }
  while (at >= 0) {
    s.critical_path.push_back(at);
    s.passes[static_cast<std::size_t>(at)].critical = true;
    const double start = s.passes[static_cast<std::size_t>(at)].earliest_start;
    int next = -1;
    for (int q : g.preds[static_cast<std::size_t>(at)]) {
      const PassTiming& pred = s.passes[static_cast<std::size_t>(q)];
      if (std::abs(pred.earliest_start + pred.weight - start) <= eps) {
        next = q;
        break;
      }
    }
    at = next;
  }
  std::reverse(s.critical_path.begin(), s.critical_path.end());
}

// What a plan pass's read and write of each resource orders, walking execution order.
struct ResourceUse {
  int last_writer = -1;
  std::vector<int> readers;  // since the last write
};

void add_resource_edges(const PlanPass& pass, int index, std::vector<ResourceUse>& uses,
                        std::vector<DepEdge>& edges) {
  for (const PlanBinding& b : pass.bindings) {
    if (b.resource < 0 || !is_read(b.access)) continue;
    ResourceUse& use = uses[static_cast<std::size_t>(b.resource)];
    // No writer yet: a persistent or imported resource's contents from before the frame.
    if (use.last_writer >= 0)
      edges.push_back({use.last_writer, index, EdgeKind::read_after_write, b.resource});
    use.readers.push_back(index);
  }
  for (const PlanBinding& b : pass.bindings) {
    if (b.resource < 0 || !is_write(b.access)) continue;
    ResourceUse& use = uses[static_cast<std::size_t>(b.resource)];
    if (use.last_writer >= 0 && use.last_writer != index)
      edges.push_back({use.last_writer, index, EdgeKind::write_after_write, b.resource});
    for (int reader : use.readers) {
      if (reader != index) edges.push_back({reader, index, EdgeKind::write_after_read, b.resource});
    }
    use.readers.clear();
    use.last_writer = index;
  }
}

double rounded(double ms) {
  return std::round(ms * 1e6) / 1e6;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", rounded(value));
  return text;
}

Json pass_names(const Plan& plan, const std::vector<int>& indices) {
  Json names = Json::array();
  for (int i : indices) names.push_back(plan.passes[static_cast<std::size_t>(i)].name);
  return names;
}

}  // namespace

Schedule analyse_schedule(const ScheduleInput& input) {
  const Neighbours g = neighbours(input);
  const std::vector<int> order = topological_order(g);
  Schedule s;
  s.passes.resize(input.weights.size());
  for (std::size_t i = 0; i < input.weights.size(); ++i) {
    s.passes[i].weight = input.weights[i];
    s.passes[i].depends_on = g.preds[i];
    s.serial += input.weights[i];
    if (i < input.async_eligible.size() && input.async_eligible[i])
      s.async_total += input.weights[i];
  }
  compute_starts(g, order, s);
  trace_critical_path(g, s);
  s.overlap_bound = std::max(0.0, std::min({s.serial - s.critical, s.async_total, s.serial / 2}));
  if (s.overlap_bound < tolerance(s.serial)) s.overlap_bound = 0;
  return s;
}

std::vector<DepEdge> plan_dependencies(const Plan& plan) {
  std::vector<ResourceUse> uses(plan.resources.size());
  std::vector<DepEdge> edges;
  for (std::size_t i = 0; i < plan.passes.size(); ++i) {
    const int index = static_cast<int>(i);
    add_resource_edges(plan.passes[i], index, uses, edges);
    for (int before : plan.passes[i].after) edges.push_back({before, index, EdgeKind::after, -1});
  }
  const auto less = [](const DepEdge& a, const DepEdge& b) {
    return std::tie(a.from, a.to, a.kind, a.resource) < std::tie(b.from, b.to, b.kind, b.resource);
  };
  std::sort(edges.begin(), edges.end(), less);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool async_eligible(const PlanPass& pass) {
  bool any = false;
  for (const PlanBinding& b : pass.bindings) {
    if (b.resource < 0) continue;
    if (b.stage != Stage::compute && b.stage != Stage::transfer) return false;
    any = true;
  }
  return any;
}

ScheduleInput schedule_input(const Plan& plan, const std::vector<double>& weights) {
  if (weights.size() != plan.passes.size()) {
    throw std::invalid_argument("schedule_input: " + std::to_string(weights.size()) +
                                " weights for " + std::to_string(plan.passes.size()) + " passes");
  }
  ScheduleInput input;
  input.weights = weights;
  for (const PlanPass& pass : plan.passes) input.async_eligible.push_back(async_eligible(pass));
  input.edges = plan_dependencies(plan);
  return input;
}

std::vector<double> unit_weights(const Plan& plan) {
  return std::vector<double>(plan.passes.size(), 1.0);
}

Json schedule_to_json(const Plan& plan, const Schedule& schedule,
                      const std::string& weight_source) {
  Json j = Json::object();
  j["weights"] = weight_source;
  j["criticalPath"] = pass_names(plan, schedule.critical_path);
  j["criticalMs"] = rounded(schedule.critical);
  j["serialMs"] = rounded(schedule.serial);
  j["asyncEligibleMs"] = rounded(schedule.async_total);
  j["overlapBoundMs"] = rounded(schedule.overlap_bound);
  Json passes = Json::array();
  for (std::size_t i = 0; i < schedule.passes.size(); ++i) {
    const PassTiming& t = schedule.passes[i];
    Json pass = Json::object();
    pass["name"] = plan.passes[i].name;
    pass["ms"] = rounded(t.weight);
    pass["earliestStartMs"] = rounded(t.earliest_start);
    pass["latestStartMs"] = rounded(t.latest_start);
    pass["slackMs"] = rounded(t.slack);
    pass["critical"] = t.critical;
    pass["asyncEligible"] = async_eligible(plan.passes[i]);
    pass["dependsOn"] = pass_names(plan, t.depends_on);
    passes.push_back(std::move(pass));
  }
  j["passes"] = std::move(passes);
  return j;
}

std::string schedule_summary_text(const Plan& plan, const Schedule& schedule,
                                  const std::string& weight_source) {
  const std::string unit = weight_source == "unit" ? " pass(es)" : " ms";
  std::string path;
  for (int i : schedule.critical_path) {
    if (!path.empty()) path += " -> ";
    path += plan.passes[static_cast<std::size_t>(i)].name;
  }
  std::string slack;
  for (std::size_t i = 0; i < schedule.passes.size(); ++i) {
    if (schedule.passes[i].slack <= 0) continue;
    slack +=
        (slack.empty() ? "" : ", ") + plan.passes[i].name + " " + number(schedule.passes[i].slack);
  }
  std::string out = "schedule (weights: " + weight_source +
                    (weight_source == "unit" ? ", 1 per pass" : "") + "):\n";
  out += "  serial " + number(schedule.serial) + unit + ", critical path " +
         number(schedule.critical) + unit + ": " + path + "\n";
  out += "  async compute could save at most " + number(schedule.overlap_bound) + unit +
         " (async-eligible " + number(schedule.async_total) + unit + ")\n";
  out += "  slack: " + (slack.empty() ? std::string("none") : slack) + "\n";
  return out;
}

}  // namespace antumbra::fg
