// Compile time of synthetic graphs: N passes in a chain of blurs with fan-in
// composites and side branches that get culled, so every phase has work to do.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/compiler.hpp"
#include "fake_registry.hpp"

namespace antumbra::fg {
namespace {

// The JSON text of a graph with `n` passes: a chain of blurs and composites (each
// composite also reads a resource four links back), and every tenth pass a dead
// end that the compiler culls.
std::string synthetic_graph(int n) {
  base::Json resources = base::Json::object();
  base::Json passes = base::Json::array();
  const auto add_image = [&](const std::string& name, int i) {
    resources[name] = {
        {"kind", "image"}, {"format", "rgba16f"}, {"size", i % 3 == 0 ? "viewport/2" : "viewport"}};
  };
  add_image("r0", 0);
  passes.push_back({{"name", "p0"}, {"type", "composite"}, {"out", {{"out", "r0"}}}});
  std::vector<std::string> chain{"r0"};
  for (int i = 1; i < n; ++i) {
    const std::string id = std::to_string(i);
    const std::string& prev = chain.back();
    if (i % 10 == 9) {
      add_image("dead" + id, i);
      passes.push_back({{"name", "p" + id},
                        {"type", "blur"},
                        {"in", {{"src", prev}}},
                        {"out", {{"dst", "dead" + id}}}});
      continue;
    }
    const std::string out = "r" + id;
    add_image(out, i);
    if (i % 2 == 0) {
      const std::string& back = chain[chain.size() >= 4 ? chain.size() - 4 : 0];
      passes.push_back({{"name", "p" + id},
                        {"type", "composite"},
                        {"in", {{"a", prev}, {"b", back}}},
                        {"out", {{"out", out}}}});
    } else {
      passes.push_back({{"name", "p" + id},
                        {"type", "blur"},
                        {"params", {{"radius", 3}}},
                        {"in", {{"src", prev}}},
                        {"out", {{"dst", out}}}});
    }
    chain.push_back(out);
  }
  const base::Json graph = {{"version", 1},
                            {"name", "synthetic"},
                            {"resources", resources},
                            {"passes", passes},
                            {"output", chain.back()}};
  return graph.dump(1);
}

const Registry& registry() {
  static const Registry kRegistry = testing::make_fake_registry();
  return kRegistry;
}

void parse_and_compile(benchmark::State& state) {
  const std::string text = synthetic_graph(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto plan = compile_text(text, "synthetic.json", registry());
    if (!plan.ok()) {
      state.SkipWithError(plan.diagnostics().to_text().c_str());
      break;
    }
    benchmark::DoNotOptimize(plan.value().passes.data());
  }
  state.SetLabel(std::to_string(text.size()) + " bytes");
}

void compile_only(benchmark::State& state) {
  const std::string text = synthetic_graph(static_cast<int>(state.range(0)));
  auto doc = parse_json(text, "synthetic.json");
  auto graph = parse_graph(doc.value());
  if (!graph.ok()) {
    state.SkipWithError(graph.diagnostics().to_text().c_str());
    return;
  }
  std::size_t executed = 0;
  for (auto _ : state) {
    auto plan = compile(graph.value(), registry());
    if (!plan.ok()) {
      state.SkipWithError(plan.diagnostics().to_text().c_str());
      break;
    }
    executed = plan.value().passes.size();
    benchmark::DoNotOptimize(plan.value().passes.data());
  }
  state.counters["executed"] = static_cast<double>(executed);
  state.counters["declared"] = static_cast<double>(graph.value().passes.size());
}

BENCHMARK(parse_and_compile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(compile_only)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace antumbra::fg
