// Phases 3-6: dependency edges, cycle detection, culling and ordering.
#include <algorithm>
#include <functional>
#include <optional>
#include <queue>
#include <tuple>

#include "antumbra/fg/compiler_phases.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {
namespace {

void add_edge(std::vector<DepEdge>& edges, DepEdge edge) {
  edges.push_back(edge);
}

bool edge_less(const DepEdge& a, const DepEdge& b) {
  return std::tie(a.from, a.to, a.kind, a.resource) < std::tie(b.from, b.to, b.kind, b.resource);
}

// Sorted and without duplicates (a pass may read one resource through two ports).
void normalize(std::vector<DepEdge>& edges) {
  std::sort(edges.begin(), edges.end(), edge_less);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

// What the walk over the passes, in file order, knows of each resource so far.
struct AccessState {
  std::vector<int> last_writer;
  std::vector<std::vector<int>> readers;  // readers since the last write
  std::vector<DepEdge> persistent_reads;  // reads of last frame's contents
};

// Says who writes a resource after pass `i` reads it, if anyone: the fix is usually to
// reorder.
std::string later_writer_hint(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                              std::size_t i, int resource) {
  std::string hint;
  for (std::size_t j = i + 1; j < passes.size() && hint.empty(); ++j) {
    for (const BoundPort& w : passes[j].writes) {
      if (w.resource == resource && passes[j].enabled) {
        hint = "; " + quote_name(graph.passes[j].name) +
               " writes it later (move it earlier, or make the resource persistent to read "
               "the previous "
               "frame)";
        break;
      }
    }
  }
  return hint;
}

void add_read_edges(const GraphDesc& graph, const std::vector<ResolvedPass>& passes, std::size_t i,
                    AccessState& access, std::vector<DepEdge>& edges, Diagnostics& diags) {
  const int to = static_cast<int>(i);
  for (const BoundPort& read : passes[i].reads) {
    const auto r = static_cast<std::size_t>(read.resource);
    if (access.last_writer[r] >= 0) {
      add_edge(edges, {access.last_writer[r], to, EdgeKind::read_after_write, read.resource});
    } else if (graph.resources[r].imported) {
      // The host's contents from before the frame: nothing in the graph to wait for.
    } else if (graph.resources[r].persistent) {
      access.persistent_reads.push_back({-1, to, EdgeKind::read_after_write, read.resource});
    } else {
      const std::string hint = later_writer_hint(graph, passes, i, read.resource);
      diags.add(graph.document.make(codes::kReadNeverWritten, Severity::error,
                                    "pass " + quote_name(graph.passes[i].name) + " reads " +
                                        quote_name(graph.resources[r].name) +
                                        " but no earlier pass writes it" + hint,
                                    read.pointer));
    }
    access.readers[r].push_back(to);
  }
}

void add_write_edges(const ResolvedPass& rp, int to, AccessState& access,
                     std::vector<DepEdge>& edges) {
  for (const BoundPort& write : rp.writes) {
    const auto r = static_cast<std::size_t>(write.resource);
    if (access.last_writer[r] >= 0)
      add_edge(edges, {access.last_writer[r], to, EdgeKind::write_after_write, write.resource});
    for (int reader : access.readers[r]) {
      if (reader != to) add_edge(edges, {reader, to, EdgeKind::write_after_read, write.resource});
    }
    access.readers[r].clear();
    access.last_writer[r] = to;
  }
}

// A persistent read consumes what the frame's last writer left behind.
void link_persistent_reads(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                           const AccessState& access, std::vector<DepEdge>& previous_frame,
                           Diagnostics& diags) {
  for (DepEdge e : access.persistent_reads) {
    const auto r = static_cast<std::size_t>(e.resource);
    if (access.last_writer[r] < 0) {
      const auto& pass = graph.passes[static_cast<std::size_t>(e.to)];
      const auto* read = &passes[static_cast<std::size_t>(e.to)].reads.front();
      for (const auto& b : passes[static_cast<std::size_t>(e.to)].reads) {
        if (b.resource == e.resource) read = &b;
      }
      diags.add(graph.document.make(codes::kReadNeverWritten, Severity::error,
                                    "pass " + quote_name(pass.name) + " reads persistent " +
                                        quote_name(graph.resources[r].name) +
                                        " but no pass ever writes it",
                                    read->pointer));
      continue;
    }
    e.from = access.last_writer[r];
    add_edge(previous_frame, e);
  }
}

// Explicit ordering: "after": ["x"] makes x run first.
void add_after_edges(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                     std::vector<DepEdge>& edges, Diagnostics& diags) {
  std::vector<std::string> names;
  for (const auto& p : graph.passes) names.push_back(p.name);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (!passes[i].enabled) continue;
    const auto& pass = graph.passes[i];
    for (std::size_t k = 0; k < pass.after.size(); ++k) {
      const int j = graph.find_pass(pass.after[k]);
      if (j < 0) {
        diags.add(graph.document.make(codes::kUnknownAfter, Severity::error,
                                      "\"after\" names unknown pass " + quote_name(pass.after[k]) +
                                          did_you_mean(pass.after[k], names),
                                      pointer_append(pass.pointer + "/after", k)));
      } else if (passes[static_cast<std::size_t>(j)].enabled) {
        add_edge(edges, {j, static_cast<int>(i), EdgeKind::after, -1});
      }
    }
  }
}

}  // namespace

std::string_view to_string(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::read_after_write:
      return "read";
    case EdgeKind::write_after_read:
      return "write-after-read";
    case EdgeKind::write_after_write:
      return "write-after-write";
    case EdgeKind::after:
      return "after";
  }
  return "read";
}

DependencyGraph build_dependencies(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                                   Diagnostics& diags) {
  DependencyGraph deps;
  const std::size_t n_res = graph.resources.size();
  AccessState access{std::vector<int>(n_res, -1), std::vector<std::vector<int>>(n_res), {}};
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (!passes[i].enabled) continue;
    add_read_edges(graph, passes, i, access, deps.edges, diags);
    add_write_edges(passes[i], static_cast<int>(i), access, deps.edges);
  }
  link_persistent_reads(graph, passes, access, deps.previous_frame, diags);
  add_after_edges(graph, passes, deps.edges, diags);
  normalize(deps.edges);
  normalize(deps.previous_frame);
  return deps;
}

namespace {

// The closing edge of a cycle is one the author most likely added last, so the error points
// at what to change. Resource edges always run forward in file order (build_dependencies walks
// the passes top-down and a read waits for an earlier writer), so every cycle has a backward
// edge (from a pass to one at or above it in the file) and every backward edge is an "after"
// entry. Among backward edges, "after" ones come first (in case resource edges ever run
// backwards), then the one into the earliest pass, then from the earliest pass.
bool closes_before(const DepEdge& a, const DepEdge& b) {
  return std::tuple(a.kind != EdgeKind::after, a.to, a.from) <
         std::tuple(b.kind != EdgeKind::after, b.to, b.from);
}

// The fewest edges from `start` to `goal`, in order (empty when start == goal); nullopt when
// `goal` is unreachable. `out_edges[p]` lists p's edges in the sorted order of `edges`, so
// among parallel edges the data edge with the lowest resource index is the one named.
std::optional<std::vector<DepEdge>> shortest_path(const std::vector<DepEdge>& edges,
                                                  const std::vector<std::vector<int>>& out_edges,
                                                  int start, int goal) {
  std::vector<int> via(out_edges.size(), -1);  // the edge that first reached each pass
  std::vector<bool> seen(out_edges.size(), false);
  std::queue<int> frontier;
  seen[static_cast<std::size_t>(start)] = true;
  frontier.push(start);
  while (!frontier.empty() && !seen[static_cast<std::size_t>(goal)]) {
    const int p = frontier.front();
    frontier.pop();
    for (int e : out_edges[static_cast<std::size_t>(p)]) {
      const auto to = static_cast<std::size_t>(edges[static_cast<std::size_t>(e)].to);
      if (seen[to]) continue;
      seen[to] = true;
      via[to] = e;
      frontier.push(static_cast<int>(to));
    }
  }
  if (!seen[static_cast<std::size_t>(goal)]) return std::nullopt;
  std::vector<DepEdge> path;
  for (int p = goal; p != start;) {
    const DepEdge& e = edges[static_cast<std::size_t>(via[static_cast<std::size_t>(p)])];
    path.push_back(e);
    p = e.from;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::vector<DepEdge> find_cycle(const DependencyGraph& deps, std::size_t pass_count) {
  std::vector<std::vector<int>> out_edges(pass_count);
  std::vector<DepEdge> backward;
  for (std::size_t e = 0; e < deps.edges.size(); ++e) {
    const DepEdge& edge = deps.edges[e];
    out_edges[static_cast<std::size_t>(edge.from)].push_back(static_cast<int>(e));
    if (edge.from >= edge.to) backward.push_back(edge);
  }
  std::sort(backward.begin(), backward.end(), closes_before);
  // A backward edge closes a cycle when its target reaches its source again.
  for (const DepEdge& closing : backward) {
    if (auto cycle = shortest_path(deps.edges, out_edges, closing.to, closing.from)) {
      cycle->push_back(closing);
      return *cycle;
    }
  }
  return {};
}

std::vector<bool> cull_passes(const DependencyGraph& deps, const std::vector<ResolvedPass>& passes,
                              int output_resource) {
  std::vector<bool> keep(passes.size(), false);
  std::vector<int> work;
  const auto mark = [&](int p) {
    if (!keep[static_cast<std::size_t>(p)]) {
      keep[static_cast<std::size_t>(p)] = true;
      work.push_back(p);
    }
  };
  int output_writer = -1;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (!passes[i].enabled) continue;
    if (passes[i].side_effects) mark(static_cast<int>(i));
    for (const BoundPort& w : passes[i].writes) {
      if (w.resource == output_resource) output_writer = static_cast<int>(i);
    }
  }
  if (output_writer >= 0) mark(output_writer);
  // Walk producer edges backwards: whoever feeds a kept pass is kept. WAR and
  // "after" edges only order passes; they do not make the earlier one needed.
  // A write-after-write keeps the earlier writer only when the later write may
  // keep its contents (an attachment that loads); storage_write discards them.
  const auto keeps_contents = [&](const DepEdge& e) {
    for (const BoundPort& w : passes[static_cast<std::size_t>(e.to)].writes) {
      if (w.resource == e.resource) {
        const ResolvedPass& writer = passes[static_cast<std::size_t>(e.to)];
        // (No format here: a format-dependent use is never a discarding storage_write.)
        return writer.desc->use_of(*w.port, writer.params).access != Access::storage_write;
      }
    }
    return true;
  };
  std::vector<std::vector<int>> producers(passes.size());
  for (const auto* list : {&deps.edges, &deps.previous_frame}) {
    for (const DepEdge& e : *list) {
      if (e.kind == EdgeKind::read_after_write ||
          (e.kind == EdgeKind::write_after_write && keeps_contents(e))) {
        producers[static_cast<std::size_t>(e.to)].push_back(e.from);
      }
    }
  }
  while (!work.empty()) {
    const int p = work.back();
    work.pop_back();
    for (int from : producers[static_cast<std::size_t>(p)]) mark(from);
  }
  return keep;
}

std::vector<int> order_passes(const DependencyGraph& deps, const std::vector<bool>& keep) {
  const std::size_t n = keep.size();
  std::vector<int> in_degree(n, 0);
  std::vector<std::vector<int>> successors(n);
  for (const DepEdge& e : deps.edges) {
    const auto from = static_cast<std::size_t>(e.from);
    const auto to = static_cast<std::size_t>(e.to);
    if (!keep[from] || !keep[to]) continue;
    successors[from].push_back(e.to);
    ++in_degree[to];
  }
  // Min-heap on the description index keeps the order stable and predictable.
  std::priority_queue<int, std::vector<int>, std::greater<>> ready;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i] && in_degree[i] == 0) ready.push(static_cast<int>(i));
  }
  std::vector<int> order;
  while (!ready.empty()) {
    const int p = ready.top();
    ready.pop();
    order.push_back(p);
    for (int s : successors[static_cast<std::size_t>(p)]) {
      if (--in_degree[static_cast<std::size_t>(s)] == 0) ready.push(s);
    }
  }
  return order;
}

}  // namespace antumbra::fg
