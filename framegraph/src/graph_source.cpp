// The one read of a graph file (docs/architecture.md, "One load path").
#include "antumbra/fg/graph_source.hpp"

#include <utility>

#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

GraphSource GraphSource::from_file(std::string path) {
  return {std::move(path), std::nullopt};
}

GraphSource GraphSource::from_text(std::string text, std::string name) {
  return {std::move(name), std::move(text)};
}

Result<GraphDesc> read_graph(const GraphSource& source) {
  Result<JsonDocument> document =
      source.text ? parse_json(*source.text, source.file) : load_json_file(source.file);
  if (!document) return document.diagnostics();
  return parse_graph(document.value());
}

Result<Plan> compile_graph(const GraphSource& source, const Registry& registry,
                           const CompileOptions& options, const GraphEdit& edit) {
  Result<GraphDesc> graph = read_graph(source);
  if (!graph) return graph.diagnostics();
  if (edit) edit(graph.value());
  Result<Plan> plan = compile(graph.value(), registry, options);
  Diagnostics all = graph.diagnostics();
  all.append(plan.diagnostics());
  if (!plan) return all;
  return Result<Plan>(std::move(plan.value()), std::move(all));
}

Result<Plan> compile_file(const std::string& path, const Registry& registry,
                          const CompileOptions& options) {
  return compile_graph(GraphSource::from_file(path), registry, options);
}

Result<Plan> compile_text(std::string_view text, const std::string& file, const Registry& registry,
                          const CompileOptions& options) {
  return compile_graph(GraphSource::from_text(std::string(text), file), registry, options);
}

}  // namespace antumbra::fg
