#include "antumbra/layering/layering_types.hpp"

#include <algorithm>
#include <array>

namespace antumbra::layering {
namespace {

template <typename Enum, std::size_t kN>
std::optional<Enum> parse_name(const std::array<std::pair<Enum, std::string_view>, kN>& names,
                               std::string_view name) {
  for (const auto& [value, text] : names)
    if (text == name) return value;
  return std::nullopt;
}

template <typename Enum, std::size_t kN>
std::string_view name_of(const std::array<std::pair<Enum, std::string_view>, kN>& names,
                         Enum value) {
  for (const auto& [v, text] : names)
    if (v == value) return text;
  return "unknown";
}

constexpr std::array<std::pair<Order, std::string_view>, 5> kOrderNames{{
    {Order::dsatur, "dsatur"},
    {Order::smallest_last, "smallest-last"},
    {Order::largest_first, "largest-first"},
    {Order::first_fit, "first-fit"},
    {Order::degree_ascending, "degree-ascending"},
}};
constexpr std::array<std::pair<CapPolicy, std::string_view>, 2> kPolicyNames{{
    {CapPolicy::least_conflict, "least-conflict"},
    {CapPolicy::fallback, "fallback"},
}};
constexpr std::array<std::pair<Criterion, std::string_view>, 2> kCriterionNames{{
    {Criterion::world_sphere, "world-sphere"},
    {Criterion::screen_tile, "screen-tile"},
}};

}  // namespace

std::uint32_t ConflictGraph::max_degree() const {
  std::uint32_t best = 0;
  for (std::size_t v = 0; v + 1 < offsets.size(); ++v)
    best = std::max(best, offsets[v + 1] - offsets[v]);
  return best;
}

bool ConflictGraph::has_edge(std::uint32_t a, std::uint32_t b) const {
  const auto list = adjacent(a);
  return std::binary_search(list.begin(), list.end(), b);
}

ConflictGraph ConflictGraph::from_edges(
    std::size_t vertex_count, std::span<const std::pair<std::uint32_t, std::uint32_t>> edges) {
  std::vector<std::vector<std::uint32_t>> lists(vertex_count);
  for (auto [a, b] : edges) {
    if (a == b || a >= vertex_count || b >= vertex_count) continue;
    lists[a].push_back(b);
    lists[b].push_back(a);
  }
  ConflictGraph graph;
  graph.offsets.assign(1, 0);
  for (auto& list : lists) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    graph.neighbours.insert(graph.neighbours.end(), list.begin(), list.end());
    graph.offsets.push_back(static_cast<std::uint32_t>(graph.neighbours.size()));
  }
  graph.weights.assign(graph.neighbours.size(), 1.0f);
  return graph;
}

std::string_view to_string(Order order) {
  return name_of(kOrderNames, order);
}
std::string_view to_string(CapPolicy policy) {
  return name_of(kPolicyNames, policy);
}
std::string_view to_string(Criterion criterion) {
  return name_of(kCriterionNames, criterion);
}
std::optional<Order> parse_order(std::string_view name) {
  return parse_name(kOrderNames, name);
}
std::optional<CapPolicy> parse_cap_policy(std::string_view name) {
  return parse_name(kPolicyNames, name);
}
std::optional<Criterion> parse_criterion(std::string_view name) {
  return parse_name(kCriterionNames, name);
}

}  // namespace antumbra::layering
