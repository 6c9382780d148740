// `validate` means `render` works: mutants of every shipped graph (an input unbound, a
// pass disabled, every choice of an enumeration, a flipped flag, numbers at their
// range's ends, a resource with one layer) that the Vulkan-free compiler accepts -- what
// `antumbra validate` runs -- must also load on the device and render a frame without
// errors. Rules that only the executor knew (TL004: layered shadows without their
// inputs) were how a graph CI called valid failed to render.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/compiler.hpp"
#include "register_builtin_passes.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

struct Mutant {
  std::string what;
  base::Json json;
  // The mutated pass's type, ports and parameters after the change: another graph's mutant
  // with the same context tests the same thing (graph files share most of their passes).
  std::string context;
};

// The mutated pass as the check depends on it: type, the ports it binds with their
// resources' declarations, every parameter.
std::string pass_context(const base::Json& graph, std::size_t i) {
  const auto& pass = graph.at("passes")[i];
  const auto& resources = graph.value("resources", base::Json::object());
  base::Json ports = base::Json::array();
  for (const char* side : {"in", "out"}) {
    if (!pass.contains(side)) continue;
    for (const auto& [port, resource] : pass[side].items()) {
      const std::string name = resource.is_string() ? resource.get<std::string>() : "";
      ports.push_back({side + (":" + port), resources.value(name, resource)});
    }
  }
  return pass.value("type", std::string()) + " " + ports.dump() + " " +
         pass.value("params", base::Json::object()).dump() + " " +
         std::to_string(pass.value("enabled", true));
}

// One change at a time to the graph's JSON, guided by the registry's reflection.
std::vector<Mutant> mutants_of(const base::Json& graph, const fg::Registry& registry) {
  std::vector<Mutant> out;
  const auto add = [&](std::string what, const auto& change, std::size_t pass = SIZE_MAX) {
    base::Json copy = graph;
    change(copy);
    std::string context = pass == SIZE_MAX ? std::string() : pass_context(copy, pass);
    out.push_back({std::move(what), std::move(copy), std::move(context)});
  };
  const auto& passes = graph.at("passes");
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const auto& pass = passes[i];
    const std::string name = pass.value("name", std::to_string(i));
    if (pass.contains("in")) {
      for (const auto& [port, unused] : pass["in"].items()) {
        add(
            std::string(name).append(": in.").append(port).append(" unbound"),
            [&, port = port](base::Json& g) { g["passes"][i]["in"].erase(port); }, i);
      }
    }
    add(name + " disabled",
        [&](base::Json& g) { g["passes"][i]["enabled"] = false; });  // graph-wide
    const fg::PassDesc* desc = registry.find(pass.value("type", std::string()));
    if (desc == nullptr) continue;
    for (const auto& param : desc->params) {
      std::vector<base::Json> values;
      if (param.type == fg::ParamType::enumeration) {
        for (const auto& c : param.choices) values.emplace_back(c);
      } else if (param.type == fg::ParamType::boolean) {
        values = {true, false};
      } else if (param.type == fg::ParamType::integer) {
        if (param.min) values.emplace_back(static_cast<int>(*param.min));
        if (param.max) values.emplace_back(static_cast<int>(*param.max));
      } else if (param.type == fg::ParamType::number) {
        if (param.min) values.emplace_back(*param.min);
        if (param.max) values.emplace_back(*param.max);
      }
      for (const auto& v : values) {
        if (pass.contains("params") && pass["params"].contains(param.name) &&
            pass["params"][param.name] == v) {
          continue;
        }
        if (!pass.contains("params") && v == param.default_value) continue;
        add(
            name + ": " + param.name + " = " + v.dump(),
            [&](base::Json& g) { g["passes"][i]["params"][param.name] = v; }, i);
      }
    }
  }
  if (graph.contains("resources")) {
    for (const auto& [name, resource] : graph["resources"].items()) {
      if (!resource.is_object() || resource.value("layers", 1) <= 1) continue;
      add(name + " with 1 layer",
          [&, key = name](base::Json& g) { g["resources"][key]["layers"] = 1; });
    }
  }
  return out;
}

}  // namespace

class ValidateMeansRenderTest : public RenderTest {};

TEST_F(ValidateMeansRenderTest, WhatTheCompilerAcceptsTheDeviceRenders) {
  const auto registry = passes::builtin_pass_registry();
  const auto files = shipped_graph_files();
  ASSERT_FALSE(files.empty());
  constexpr VkExtent2D kTiny{48, 27};
  OPEN_SESSION(session, kTiny);
  session->set_scene(point_and_spot_scene());
  int accepted = 0;
  int refused = 0;
  int repeated = 0;
  std::set<std::string> contexts;  // a mutated pass in a context already rendered is skipped
  for (const auto& file : files) {
    const auto original = base::parse_json(read_text(file), file.string());
    ASSERT_TRUE(original.ok()) << file;
    for (const auto& mutant : mutants_of(original->root(), registry.reflection())) {
      SCOPED_TRACE(file.filename().string() + ": " + mutant.what);
      if (!mutant.context.empty() && !contexts.insert(mutant.context).second) {
        ++repeated;
        continue;
      }
      const auto document = base::parse_json(mutant.json.dump(2), file.string());
      ASSERT_TRUE(document.ok());
      const auto graph = fg::parse_graph(document.value());
      if (!graph.ok()) {
        ++refused;
        continue;
      }
      fg::CompileOptions options;
      options.viewport = {kTiny.width, kTiny.height};
      const auto plan = fg::compile(graph.value(), registry.reflection(), options);
      if (!plan.ok()) {
        ++refused;
        continue;
      }
      ++accepted;
      const auto diagnostics = session->load_graph(graph.value());
      EXPECT_FALSE(diagnostics.has_errors()) << "validate accepts it, render refuses it:\n"
                                             << describe(diagnostics);
      if (diagnostics.has_errors()) continue;
      const std::size_t errors_before = session->gpu().validation_error_count();
      EXPECT_NO_THROW(session->render(1, nullptr));
      EXPECT_EQ(session->gpu().validation_error_count(), errors_before)
          << "validation errors while rendering this mutant";
    }
  }
  expect_no_validation_errors(*session);
  // The mutants must exercise both sides, or the test proves nothing.
  EXPECT_GT(accepted, 50);
  EXPECT_GT(refused, 20);
  std::printf(
      "%d mutant(s) accepted and rendered, %d refused by the compiler, %d repeated a context\n",
      accepted, refused, repeated);
}
