// antumbra: the command-line entry point.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/runtime/data_paths.hpp"
#include "bench_baseline.hpp"
#include "bench_scenarios.hpp"
#include "commands.hpp"
#include "edit_script.hpp"

namespace {

// The spellings of `plan --format` from before the option existed.
struct DeprecatedPlanFlags {
  bool dot = false;
  bool json = false;
  bool text = false;
};

int run_plan_with_deprecated_flags(antumbra::app::PlanOptions plan,
                                   const DeprecatedPlanFlags& flags, bool format_given) {
  const char* flag = flags.dot ? "dot" : (flags.text ? "text" : (flags.json ? "json" : nullptr));
  if (flag != nullptr) {
    // Silently letting one of two contradicting choices win would hide a script's bug.
    if (format_given && plan.format != flag) {
      std::fprintf(stderr, "antumbra plan: --%s contradicts --format %s\n", flag,
                   plan.format.c_str());
      return antumbra::runtime::kExitUsage;
    }
    std::fprintf(stderr, "antumbra plan: --%s is deprecated; use --format %s\n", flag, flag);
    plan.format = flag;
  }
  return antumbra::app::run_plan(plan);
}

// Scene files may name glTF and scene files outside their own folder only when asked
// (docs/robustness.md, "Paths").
void add_outside_paths_flag(CLI::App* cmd, bool& allow) {
  cmd->add_flag("--allow-outside-paths", allow,
                "Let scene files (and their glTFs) read files outside their own folder: absolute "
                "paths and paths climbing out through '..' (a warning instead of an error)");
}

CLI::App* add_techniques_command(CLI::App& cli, antumbra::app::TechniquesOptions& options) {
  auto* cmd = cli.add_subcommand(
      "techniques",
      "Compare every shadow technique with the reference; write one Markdown table and crops");
  cmd->add_option("--graph", options.graphs,
                  "Technique graph (repeatable; default: every shipped technique graph)");
  cmd->add_option("--scene", options.scene, "Scene JSON (default: data/scenes/atrium.json)");
  cmd->add_option("--size", options.size, "Viewport WxH of the quality frames")
      ->capture_default_str();
  cmd->add_option("--gpu-bench", options.gpu_bench,
                  "bench.json of `bench --scenario table1/` on the GPU (the GPU ms column)");
  cmd->add_option("--cpu-bench", options.cpu_bench,
                  "bench.json of `bench --scenario table1/` on lavapipe (the ratio column)");
  cmd->add_option("--out", options.out,
                  "Markdown file; crops go to techniques/ beside it (docs/techniques.md, the "
                  "committed table, is written only when named)")
      ->capture_default_str();
  cmd->add_option("--device", options.device, "auto|cpu|gpu|N|<name substring>")
      ->capture_default_str();
  add_outside_paths_flag(cmd, options.allow_outside_paths);
  return cmd;
}

CLI::App* add_docs_tables_command(CLI::App& cli, antumbra::app::DocsTablesOptions& options) {
  auto* cmd = cli.add_subcommand(
      "docs-tables", "Generate the measured tables of README.md and docs/ from docs/results/");
  cmd->add_flag("--check", options.check, "Write nothing; exit 1 naming each table that differs");
  cmd->add_option("--root", options.root, "Repository root")->capture_default_str();
  return cmd;
}

// `bench --fail-slower PCT`: a finite percentage >= 0. CLI11's Range lets NaN through
// (every comparison with NaN is false), and a NaN threshold would never fail anything.
CLI::Validator slower_percent() {
  return {
      [](std::string& text) {
        double value = 0.0;
        if (CLI::detail::lexical_cast(text, value) && antumbra::app::valid_slower_percent(value)) {
          return std::string();
        }
        return "expected a percentage >= 0, got " + text;
      },
      "PCT >= 0"};
}

// `bench --quick`'s help, from the preset itself so that it cannot go stale.
std::string quick_help() {
  using namespace antumbra::app;
  char text[400];
  std::snprintf(text, sizeof text,
                "Preset for CPU devices (lavapipe; the moving table in under 10 minutes on 2 "
                "cores): --frames %d --warmup %d --scale %g, and the district's rows at %g of "
                "that scale with %d lights, %d moving (not %d, %d: rows named "
                "'%dl-district'); an explicit --frames, --warmup or --scale wins",
                kQuickFrames, kQuickWarmup, kQuickScale, kQuickDistrict.scale,
                kQuickDistrict.lights, kQuickDistrict.moving, kDistrictLights,
                kDistrictMovingLights, kQuickDistrict.lights);
  return text;
}

// The CLI option table: one block of CLI11 declarations per subcommand, then the dispatch.
// Long by nature, and only declarations (the logic is in cmd_*.cpp).
// NOLINTNEXTLINE(readability-function-size)
int dispatch(int argc, char** argv) {
  using namespace antumbra::app;
  CLI::App cli{"Antumbra: a JSON frame graph for many-light soft shadows on Vulkan 1.3"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "antumbra 0.1.0");

  RenderOptions render;
  auto* render_cmd = cli.add_subcommand("render", "Render frames and write an image");
  render_cmd->add_option("--graph", render.graph,
                         "Frame graph JSON (default: data/graphs/layered-ssss.json)");
  render_cmd->add_option("--scene", render.scene, "Scene JSON (default: data/scenes/atrium.json)");
  add_outside_paths_flag(render_cmd, render.allow_outside_paths);
  render_cmd->add_option("--size", render.size, "Viewport WxH")->capture_default_str();
  render_cmd->add_option("--frames", render.frames, "Frames to render")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  render_cmd->add_option("--out", render.out, "PNG to write")->capture_default_str();
  render_cmd->add_option("--output", render.output,
                         "Graph resource to write (default: the graph output)");
  render_cmd->add_option("--hdr-out", render.hdr_out, "Also write this resource as PFM (float)");
  render_cmd->add_option("--device", render.device, "auto|cpu|gpu|N|<name substring>")
      ->capture_default_str();
  render_cmd->add_flag("--validation", render.validation,
                       "Khronos validation + synchronization validation");
  render_cmd->add_option("--trace", render.trace, "Write a Chrome/Perfetto trace JSON");
  render_cmd->add_flag("--watch", render.watch,
                       "Keep running: reload the graph, scene and shaders when they change");
  render_cmd
      ->add_option("--watch-seconds", render.watch_seconds,
                   "With --watch: stop after this many seconds (0 = until interrupted)")
      ->check(CLI::Range(0.0, 1e9));
  render_cmd->add_option("--format", render.format, "text|json report on stdout")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  render_cmd->add_flag("--werror", render.werror,
                       "Exit 1 when the graph or a pass (e.g. the layer cap) warns");

  ValidateOptions validate;
  auto* validate_cmd =
      cli.add_subcommand("validate", "Check frame graph and scene files (no GPU needed)");
  validate_cmd
      ->add_option("files", validate.files,
                   "Graph files, and scene files (told apart by their keys or $schema)")
      ->required();
  validate_cmd->add_option("--format", validate.format, "text|json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  validate_cmd->add_flag("--werror", validate.werror, "Treat warnings as errors");
  add_outside_paths_flag(validate_cmd, validate.allow_outside_paths);

  PlanOptions plan;
  auto* plan_cmd = cli.add_subcommand("plan", "Print the compiled plan of a graph");
  plan_cmd->add_option("file", plan.file, "Graph file")->required();
  plan_cmd->add_option("--format", plan.format, "json (canonical) | dot (Graphviz) | text")
      ->check(CLI::IsMember({"json", "dot", "text"}))
      ->capture_default_str();
  // The spellings from before --format, kept so that existing scripts keep working.
  auto* plan_format =
      plan_cmd->add_option_group("deprecated", "Spellings of --format kept for old scripts");
  DeprecatedPlanFlags plan_flags;
  plan_format->add_flag("--dot", plan_flags.dot, "Same as --format dot (deprecated)");
  plan_format->add_flag("--json", plan_flags.json, "Same as --format json (deprecated)");
  plan_format->add_flag("--text", plan_flags.text, "Same as --format text (deprecated)");
  plan_format->require_option(0, 1);
  plan_cmd->add_option("--size", plan.size, "Viewport WxH the plan is compiled for")
      ->capture_default_str();
  auto* plan_times = plan_cmd->add_option(
      "--times", plan.times,
      "bench.json (antumbra bench): its per-pass GPU medians weigh the schedule (default: 1 "
      "per pass)");
  plan_cmd->add_option("--scenario", plan.scenario, "The --times scenario (when it has several)")
      ->needs(plan_times);

  EditOptions edit;
  auto* edit_cmd = cli.add_subcommand(
      "edit", "Edit lights and graph parameters with live layer-cap warnings (headless: scripted)");
  edit_cmd->add_option("--graph", edit.graph, "Frame graph JSON (default: layered-ssss.json)");
  edit_cmd->add_option("--scene", edit.scene, "Scene JSON (default: data/scenes/atrium.json)");
  add_outside_paths_flag(edit_cmd, edit.allow_outside_paths);
  edit_cmd->add_option("--device", edit.device, "auto|cpu|gpu|N|<name substring>")
      ->capture_default_str();
  edit_cmd->add_flag("--validation", edit.validation,
                     "Khronos validation + synchronization validation");
  edit_cmd->add_option("--frames", edit.frames, "Render N more frames, then close")
      ->check(CLI::Range(0, 1000000));
  edit_cmd->add_option("--script", edit.script, "JSON script of edits and expectations");
  edit_cmd->add_flag("--headless", edit.headless, "No window: run the script offscreen");
  edit_cmd->add_option("--select", edit.select, "Window: the light selected at start (by name)");
  edit_cmd->add_flag("--frame-log", edit.frame_log,
                     "Window: print a line per presented frame and where the node view's ports "
                     "and the graph panel's fields are (for scripts driving it)");
  edit_cmd->add_option("--shots", edit.shots,
                       "Window: a folder; F12 writes the window as presented to shot-N.png there");
  edit_cmd->add_option("--size", edit.size, "Window WxH (headless: the viewport)")
      ->capture_default_str();
  edit_cmd->add_option("--layout-file", edit.layout_file,
                       "Window: layout file (default: $ANTUMBRA_CONFIG_DIR/editor.ini, else "
                       "$XDG_CONFIG_HOME/antumbra/editor.ini or ~/.config/antumbra/editor.ini)");
  edit_cmd->add_option("--ui-scale", edit.ui_scale, "Window: UI scale instead of the screen's DPI")
      ->check(CLI::Range(0.5f, 4.0f));
  edit_cmd->add_option("--layout-report", edit.layout_report,
                       "Window: JSON of the panels', viewport's and image's rectangles on exit");
  edit_cmd->add_option("--out,--screenshot", edit.out,
                       "PNG of the last frame (windowed: the window as presented, UI included)");

  BenchOptions bench;
  auto* bench_cmd =
      cli.add_subcommand("bench", "Run named benchmark scenarios; write CSV, JSON and a plot");
  bench_cmd->add_option("--scenario", bench.filters,
                        "Substring of scenario names (repeatable); --list lists those it selects");
  auto* bench_frames = bench_cmd->add_option("--frames", bench.frames, "Timed frames per scenario")
                           ->check(CLI::Range(1, 100000))
                           ->capture_default_str();
  auto* bench_warmup =
      bench_cmd
          ->add_option("--warmup", bench.warmup,
                       "Untimed warm-up frames before each scenario's timed ones (0: none)")
          ->check(CLI::Range(0, 100000))
          ->capture_default_str();
  auto* bench_scale =
      bench_cmd->add_option("--scale", bench.scale, "Resolution scale (e.g. 0.25 on lavapipe)")
          ->check(CLI::Range(0.01, 4.0))
          ->capture_default_str();
  bench_cmd->add_flag("--quick", bench.quick, quick_help());
  bench_cmd->add_option("--out", bench.out, "Output folder")->capture_default_str();
  bench_cmd->add_option("--device", bench.device, "auto|cpu|gpu|N|<name substring>")
      ->capture_default_str();
  bench_cmd->add_flag("--validation", bench.validation, "Khronos validation (slow)");
  bench_cmd->add_flag("--list", bench.list, "List the scenarios and exit");
  bench_cmd->add_flag("--steps", bench.steps,
                      "Also time the steps inside passes (e.g. shadowMaps.rasterDepth): rows of "
                      "type step in the CSV, \"steps\" in the JSON");
  auto* baseline_opt = bench_cmd->add_option(
      "--baseline", bench.baseline,
      "bench.json of an earlier run (re-run it now: times drift): medians, ratios, slower flags");
  bench_cmd
      ->add_option(
          "--fail-slower", bench.fail_slower,
          "With --baseline: flag at >= PCT % (not 5 %) and >= 0.02 ms slower; exit 1 on a flag")
      ->check(slower_percent())
      ->needs(baseline_opt);

  SchemaOptions schema;
  auto* schema_cmd =
      cli.add_subcommand("schema", "Print the JSON Schema of graph files (or of scene files)");
  auto* scene_flag = schema_cmd->add_flag(
      "--scene", schema.scene, "The JSON Schema of scene files (data/schema/scene.schema.json)");
  schema_cmd
      ->add_flag("--markdown", schema.markdown,
                 "With --scene: the scene file reference instead (docs/scenes.md)")
      ->needs(scene_flag);

  PassesOptions passes;
  auto* passes_cmd = cli.add_subcommand(
      "passes", "List the pass types, or print one type's ports, parameters and description");
  passes_cmd->add_option("type", passes.type, "Pass type to describe (default: list them all)");
  passes_cmd->add_option("--format", passes.format, "text|json|markdown")
      ->check(CLI::IsMember({"text", "json", "markdown"}))
      ->capture_default_str();

  std::string devices_device = "auto";
  bool devices_validation = false;
  auto* devices_cmd =
      cli.add_subcommand("devices", "List Vulkan devices and the one --device picks");
  devices_cmd->add_option("--device", devices_device, "Selection to explain")
      ->capture_default_str();
  devices_cmd->add_flag("--validation", devices_validation, "Enable validation while probing");

  CompareOptions compare;
  auto* compare_cmd =
      cli.add_subcommand("compare", "Quality metrics (RMSE, PSNR, SSIM) of two HDR frames (PFM)");
  compare_cmd->add_option("a", compare.a, "Reference PFM")->required();
  compare_cmd->add_option("b", compare.b, "PFM to compare")->required();
  compare_cmd->add_option("--mask-image", compare.mask_image,
                          "PFM mask (e.g. penumbraCount): penumbra >= 1, overlap >= 2");
  compare_cmd->add_option("--mask", compare.mask, "all|penumbra|overlap (default: all available)")
      ->check(CLI::IsMember({"all", "penumbra", "overlap"}));
  compare_cmd->add_option("--format", compare.format, "text|json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();

  QualityOptions quality;
  auto* quality_cmd = cli.add_subcommand(
      "quality", "Render the reference and technique graphs; print their errors against it");
  quality_cmd->add_option("--graph", quality.graphs, "Technique graph (repeatable)")->required();
  quality_cmd->add_option("--reference", quality.reference,
                          "Reference graph (default: data/graphs/reference.json)");
  quality_cmd->add_option("--scene", quality.scene,
                          "Scene JSON (default: data/scenes/atrium.json)");
  add_outside_paths_flag(quality_cmd, quality.allow_outside_paths);
  quality_cmd->add_option("--size", quality.size, "Viewport WxH")->capture_default_str();
  quality_cmd->add_option("--out", quality.out,
                          "Folder for per-technique error heat maps (<graph>-error.png)");
  quality_cmd->add_option("--resource", quality.resource, "HDR resource of every graph")
      ->capture_default_str();
  quality_cmd->add_option("--device", quality.device, "auto|cpu|gpu|N|<name substring>")
      ->capture_default_str();
  quality_cmd->add_flag("--validation", quality.validation, "Khronos validation (slow)");
  quality_cmd->add_option("--format", quality.format, "text|json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();

  antumbra::app::TechniquesOptions techniques;
  auto* techniques_cmd = add_techniques_command(cli, techniques);

  DocsTablesOptions docs_tables;
  auto* docs_tables_cmd = add_docs_tables_command(cli, docs_tables);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    cli.exit(e);
    return antumbra::runtime::kExitUsage;
  }

  if (edit_cmd->parsed()) return run_edit(edit);
  if (render_cmd->parsed()) return run_render(render);
  if (validate_cmd->parsed()) return run_validate(validate);
  if (plan_cmd->parsed()) {
    return run_plan_with_deprecated_flags(plan, plan_flags, plan_cmd->count("--format") > 0);
  }
  if (passes_cmd->parsed()) return run_passes(passes);
  if (devices_cmd->parsed()) return run_devices(devices_device, devices_validation);
  if (bench_cmd->parsed()) {
    apply_quick_preset(
        bench, {bench_frames->count() > 0, bench_warmup->count() > 0, bench_scale->count() > 0});
    return run_bench(bench);
  }
  if (compare_cmd->parsed()) return run_compare(compare);
  if (quality_cmd->parsed()) return run_quality(quality);
  if (techniques_cmd->parsed()) return run_techniques(techniques);
  if (docs_tables_cmd->parsed()) return run_docs_tables(docs_tables);
  return run_schema(schema);
}

}  // namespace

int main(int argc, char** argv) {
  // Logs go to stderr: stdout carries what tools parse (plans, schemas, JSON reports).
  spdlog::set_default_logger(spdlog::stderr_color_mt("antumbra"));
  try {
    return dispatch(argc, argv);
  } catch (const antumbra::runtime::DataPathsError& e) {
    std::fprintf(stderr, "antumbra: error: %s\n", e.what());
    return antumbra::runtime::kExitUsage;
  } catch (const antumbra::gpu::DeviceLostError& e) {
    std::fprintf(stderr, "antumbra: error: %s\n", e.what());
    return antumbra::runtime::kExitRuntime;
  } catch (const antumbra::gpu::VulkanError& e) {
    // Met outside a frame (an upload, a readback): said plainly all the same.
    std::fprintf(stderr, "antumbra: error: %s%s\n",
                 e.result() == VK_ERROR_DEVICE_LOST ? "the GPU device was lost: " : "", e.what());
    return antumbra::runtime::kExitRuntime;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antumbra: error: %s\n", e.what());
    return antumbra::runtime::kExitRuntime;
  } catch (...) {
    std::fprintf(stderr, "antumbra: error: unknown failure\n");
    return antumbra::runtime::kExitRuntime;
  }
}
