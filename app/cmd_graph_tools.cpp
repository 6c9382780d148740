// validate, plan and schema: the Vulkan-free commands, usable in CI without a GPU.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "antumbra/fg/plan_memory.hpp"
#include "antumbra/fg/plan_schedule.hpp"
#include "antumbra/fg/schema.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "antumbra/scene/scene_format.hpp"
#include "commands.hpp"
#include "plan_times.hpp"

namespace antumbra::app {
namespace {

void print_plan_text(const fg::Plan& plan) {
  std::printf("graph %s (%s) at %ux%u\n", plan.name.c_str(), plan.file.c_str(), plan.viewport.width,
              plan.viewport.height);
  std::printf("passes (execution order):\n");
  for (std::size_t i = 0; i < plan.passes.size(); ++i) {
    const auto& pass = plan.passes[i];
    std::printf("  %2zu %-20s %-20s %zu barrier(s)\n", i, pass.name.c_str(), pass.type.c_str(),
                pass.barriers.size());
  }
  for (const auto& culled : plan.culled_passes)
    std::printf("     %-20s (culled)\n", culled.c_str());
  std::printf("resources:\n");
  for (const auto& r : plan.resources) {
    // Buffers have no format or extent: their kind and byte size take those columns.
    const std::string shape = r.kind == fg::ResourceKind::image
                                  ? std::to_string(r.extent.width) + "x" +
                                        std::to_string(r.extent.height) + " x" +
                                        std::to_string(r.layers)
                                  : std::to_string(r.buffer_size) + " bytes";
    const std::string kind = r.kind == fg::ResourceKind::image
                                 ? std::string(fg::to_string(r.format))
                                 : std::string(fg::to_string(r.kind));
    const std::string aliased = r.aliased ? " aliased @" + std::to_string(r.heap_offset) : "";
    std::printf("  %-20s %-10s %-16s life [%d, %d]%s\n", r.name.c_str(), kind.c_str(),
                shape.c_str(), r.first_use, r.last_use, aliased.c_str());
  }
  std::printf("aliasing: %llu bytes in the transient heap instead of %llu (saved %llu)\n",
              static_cast<unsigned long long>(plan.aliasing.heap_bytes),
              static_cast<unsigned long long>(plan.aliasing.bytes_without_aliasing),
              static_cast<unsigned long long>(plan.aliasing.bytes_saved()));
}

// A scene file, not a graph: no graph keys, and scene keys or the scene schema. `validate`
// then checks it with the scene parser instead of reporting every scene key as unknown.
bool looks_like_scene(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  const auto root = nlohmann::json::parse(in, nullptr, false);
  if (!root.is_object() || root.contains("passes") || root.contains("resources")) return false;
  const std::string schema = root.value("$schema", std::string());
  if (schema.ends_with("scene.schema.json")) return true;
  return root.contains("objects") || root.contains("lights") || root.contains("camera");
}

// What a scene holds, for the summary line.
std::string scene_summary(const scene::Scene& scene) {
  return "; scene: " + std::to_string(scene.meshes.size()) + " mesh(es), " +
         std::to_string(scene.lights.size()) + " light(s)";
}

}  // namespace

bool parse_size(const std::string& text, unsigned& width, unsigned& height) {
  const auto x = text.find('x');
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return false;
  try {
    std::size_t used = 0;
    const unsigned long w = std::stoul(text.substr(0, x), &used);
    if (used != x) return false;
    const unsigned long h = std::stoul(text.substr(x + 1), &used);
    if (used != text.size() - x - 1) return false;
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return false;
    width = static_cast<unsigned>(w);
    height = static_cast<unsigned>(h);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

int run_validate(const ValidateOptions& options) {
  const auto registry = runtime::pass_registry({});
  bool failed = false;
  bool unreadable = false;
  nlohmann::json report = nlohmann::json::array();
  for (const auto& file : options.files) {
    if (looks_like_scene(file)) {
      const auto scene = scene::load_scene_file(
          file, nullptr, {.allow_outside_paths = options.allow_outside_paths});
      const auto& diagnostics = scene.diagnostics();
      const bool file_failed = !scene.ok() || (options.werror && diagnostics.warning_count() > 0);
      failed = failed || file_failed;
      if (options.format == "json") {
        report.push_back({{"file", file},
                          {"kind", "scene"},
                          {"valid", !file_failed},
                          {"diagnostics", diagnostics.to_json()}});
        continue;
      }
      for (const auto& d : diagnostics) {
        if (d.severity != base::Severity::note)
          std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
      }
      std::printf("%s: %s (%zu error(s), %zu warning(s)%s)\n", file.c_str(),
                  file_failed ? "invalid" : "valid", diagnostics.error_count(),
                  diagnostics.warning_count(),
                  scene.ok() ? scene_summary(scene.value()).c_str() : "");
      continue;
    }
    const auto result = fg::compile_graph(fg::GraphSource::from_file(file), registry.reflection());
    const auto& diagnostics = result.diagnostics();
    const bool file_failed = !result.ok() || (options.werror && diagnostics.warning_count() > 0);
    failed = failed || file_failed;
    unreadable = unreadable || runtime::exit_code_for(diagnostics) == runtime::kExitUsage;
    // The memory the plan asks for, without a device (formats' texel sizes, no driver
    // padding): a CI job sees a graph grow before a GPU does.
    const fg::CompileOptions defaults;
    std::string memory;
    if (result.ok()) {
      memory = "; memory at " + std::to_string(defaults.viewport.width) + "x" +
               std::to_string(defaults.viewport.height) + ": " +
               fg::describe_plan_memory(result.value());
    }
    if (options.format == "json") {
      nlohmann::json item{
          {"file", file}, {"valid", !file_failed}, {"diagnostics", diagnostics.to_json()}};
      if (result.ok()) {
        item["memoryBytes"] = fg::plan_memory_bytes(result.value());
        item["transientHeapBytes"] = result.value().aliasing.heap_bytes;
        item["viewport"] = {defaults.viewport.width, defaults.viewport.height};
      }
      report.push_back(std::move(item));
      continue;
    }
    for (const auto& d : diagnostics) {
      if (d.severity == base::Severity::note) continue;
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
    }
    std::printf("%s: %s (%zu error(s), %zu warning(s)%s)\n", file.c_str(),
                file_failed ? "invalid" : "valid", diagnostics.error_count(),
                diagnostics.warning_count(), memory.c_str());
  }
  if (options.format == "json") std::cout << nlohmann::json{{"files", report}}.dump(2) << '\n';
  if (unreadable) return runtime::kExitUsage;  // a file that cannot be read: like a bad argument
  return failed ? runtime::kExitDiagnostics : runtime::kExitOk;
}

int run_plan(const PlanOptions& options) {
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(options.size, width, height)) {
    std::fprintf(stderr, "antumbra plan: --size must be WxH with 1..16384, got \"%s\"\n",
                 options.size.c_str());
    return runtime::kExitUsage;
  }
  const auto registry = runtime::pass_registry({});
  fg::CompileOptions compile_options;
  compile_options.viewport = {width, height};
  const auto result = fg::compile_graph(fg::GraphSource::from_file(options.file),
                                        registry.reflection(), compile_options);
  for (const auto& d : result.diagnostics()) {
    if (d.severity != base::Severity::note)
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
  if (!result.ok()) return runtime::exit_code_for(result.diagnostics());
  const fg::Plan& plan = result.value();
  if (options.format == "dot") {
    std::cout << fg::plan_to_dot(plan);
    return runtime::kExitOk;
  }
  PlanTimes times{fg::unit_weights(plan), "unit"};
  if (!options.times.empty()) {
    try {
      times = load_plan_times(plan, options.times, options.scenario);
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "antumbra plan: --times: %s\n", e.what());
      return runtime::kExitUsage;
    }
  }
  const fg::Schedule schedule = fg::analyse_schedule(fg::schedule_input(plan, times.ms));
  if (options.format == "text") {
    print_plan_text(plan);
    std::cout << fg::schedule_summary_text(plan, schedule, times.source);
  } else {
    // The canonical plan, then what its dependencies allow (docs/architecture.md, section 3).
    base::Json json = fg::plan_to_json(plan);
    json["schedule"] = fg::schedule_to_json(plan, schedule, times.source);
    std::cout << json.dump(2) << '\n';
  }
  return runtime::kExitOk;
}

int run_schema(const SchemaOptions& options) {
  // Both scene outputs come from the scene format's table (scene_format.hpp).
  if (options.markdown) {
    std::cout << scene::scene_reference_markdown();
    return runtime::kExitOk;
  }
  if (options.scene) {
    std::cout << scene::scene_schema().dump(2) << '\n';
    return runtime::kExitOk;
  }
  const auto registry = runtime::pass_registry({});
  std::cout << fg::generate_schema(registry.reflection()).dump(2) << '\n';
  return runtime::kExitOk;
}

}  // namespace antumbra::app
