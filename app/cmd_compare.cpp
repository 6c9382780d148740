// antumbra compare: image-quality metrics of two HDR frames (PFM), optionally over
// penumbra / overlap masks. antumbra quality: renders the reference and one or more
// technique graphs in one session and prints the same metrics for each.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/timing.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "build_commit.hpp"
#include "commands.hpp"
#include "driver_summary.hpp"
#include "error_map.hpp"
#include "image_metrics.hpp"

namespace antumbra::app {
namespace {

nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json metrics_json(const std::vector<Comparison>& comparisons) {
  nlohmann::json regions = nlohmann::json::object();
  for (const auto& c : comparisons) {
    regions[std::string(to_string(c.region))] = {{"pixels", c.metrics.pixels},
                                                 {"rmse", number_or_null(c.metrics.rmse)},
                                                 {"psnr", number_or_null(c.metrics.psnr)},
                                                 {"ssim", number_or_null(c.metrics.ssim)}};
  }
  return regions;
}

void print_row(const std::string& label, const Comparison& c) {
  if (c.metrics.pixels == 0) {
    std::printf("%-24s %-9s %8zu %10s %9s %8s\n", label.c_str(),
                std::string(to_string(c.region)).c_str(), c.metrics.pixels, "-", "-", "-");
    return;
  }
  std::printf("%-24s %-9s %8zu %10.6f %9.3f %8.5f\n", label.c_str(),
              std::string(to_string(c.region)).c_str(), c.metrics.pixels, c.metrics.rmse,
              c.metrics.psnr, c.metrics.ssim);
}

void print_header() {
  std::printf("%-24s %-9s %8s %10s %9s %8s\n", "image", "region", "pixels", "rmse", "psnr dB",
              "ssim");
}

constexpr const char* kMetricNote =
    "metrics on Rec.709 luminance clamped to [0,1]; PSNR peak 1.0 (capped at 100 dB); SSIM "
    "11x11 Gaussian (sigma 1.5), C1=0.01^2, C2=0.03^2";

// Regions to report: the one asked for, else all those the inputs allow.
std::optional<std::vector<MaskRegion>> regions_for(const std::string& mask, bool has_mask_image) {
  if (mask.empty()) {
    if (!has_mask_image) return std::vector<MaskRegion>{MaskRegion::all};
    return std::vector<MaskRegion>{MaskRegion::all, MaskRegion::penumbra, MaskRegion::overlap};
  }
  const auto region = parse_mask_region(mask);
  if (!region || (*region != MaskRegion::all && !has_mask_image)) return std::nullopt;
  return std::vector<MaskRegion>{*region};
}

FloatImage to_float_image(const gpu::HostImage& host) {
  FloatImage image{host.width, host.height, host.channels == 1 ? 1u : 3u, {}};
  image.texels.reserve(std::size_t{host.width} * host.height * image.channels);
  for (std::uint32_t y = 0; y < host.height; ++y) {
    for (std::uint32_t x = 0; x < host.width; ++x) {
      for (std::uint32_t c = 0; c < image.channels; ++c) image.texels.push_back(host.at(x, y, c));
    }
  }
  return image;
}

}  // namespace

namespace {

// A file that cannot be opened is a usage error (2), as for graphs and scenes; a file
// that opens but is no PFM is a problem in the file (1).
int unreadable_exit(const std::string& error) {
  return error.rfind("cannot open ", 0) == 0 ? runtime::kExitUsage : runtime::kExitDiagnostics;
}

}  // namespace

int run_compare(const CompareOptions& options) {
  const auto regions = regions_for(options.mask, !options.mask_image.empty());
  if (!regions) {
    std::fprintf(stderr,
                 "antumbra compare: --mask %s needs --mask-image (penumbra/overlap pick pixels "
                 "by its values)\n",
                 options.mask.c_str());
    return runtime::kExitUsage;
  }
  std::string error;
  const auto a = read_pfm(options.a, error);
  if (!a) {
    std::fprintf(stderr, "antumbra compare: error: %s\n", error.c_str());
    return unreadable_exit(error);
  }
  const auto b = read_pfm(options.b, error);
  if (!b) {
    std::fprintf(stderr, "antumbra compare: error: %s\n", error.c_str());
    return unreadable_exit(error);
  }
  std::optional<FloatImage> mask;
  if (!options.mask_image.empty()) {
    mask = read_pfm(options.mask_image, error);
    if (!mask) {
      std::fprintf(stderr, "antumbra compare: error: %s\n", error.c_str());
      return unreadable_exit(error);
    }
  }
  std::vector<Comparison> comparisons;
  try {
    comparisons = compare_images(*a, *b, mask ? &*mask : nullptr, *regions);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "antumbra compare: error: %s (%s, %s)\n", e.what(), options.a.c_str(),
                 options.b.c_str());
    return runtime::kExitDiagnostics;
  }
  if (options.format == "json") {
    const nlohmann::json report{{"a", options.a},
                                {"b", options.b},
                                {"mask", options.mask_image},
                                {"width", a->width},
                                {"height", a->height},
                                {"signal", kMetricNote},
                                {"regions", metrics_json(comparisons)}};
    std::printf("%s\n", report.dump(2).c_str());
    return runtime::kExitOk;
  }
  print_header();
  for (const auto& c : comparisons) print_row(std::filesystem::path(options.b).filename(), c);
  std::printf("(%s)\n", kMetricNote);
  return runtime::kExitOk;
}

namespace {

// Parses a graph and makes `resource` its output (kept alive, never aliased); the
// extra resources named in `keep` are marked persistent so they stay readable too.
std::optional<fg::GraphDesc> load_for_quality(const std::string& path, const std::string& resource,
                                              const std::vector<std::string>& keep) {
  auto graph = fg::read_graph(fg::GraphSource::from_file(path));  // the one load path's read
  if (!graph.ok()) {
    for (const auto& d : graph.diagnostics())
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
    return std::nullopt;
  }
  if (graph->find_resource(resource) < 0) {
    std::fprintf(stderr, "antumbra quality: %s has no resource \"%s\"\n", path.c_str(),
                 resource.c_str());
    return std::nullopt;
  }
  graph->output = resource;
  for (const auto& name : keep) {
    const int index = graph->find_resource(name);
    if (index >= 0) graph->resources[static_cast<std::size_t>(index)].persistent = true;
  }
  return std::move(graph.value());
}

// File stems name the error maps; a repeated stem gets its position appended.
std::vector<std::string> unique_labels(const std::vector<std::string>& graphs) {
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < graphs.size(); ++i) {
    std::string label = std::filesystem::path(graphs[i]).stem().string();
    if (std::find(labels.begin(), labels.end(), label) != labels.end()) {
      label += '-' + std::to_string(i + 1);
    }
    labels.push_back(label);
  }
  return labels;
}

void print_error_maps(const ErrorMaps& maps) {
  if (maps.files.empty()) return;
  std::printf(
      "error maps (technique - reference, display luminance): blue = darker by %g or more, "
      "white = equal, red = brighter by %g or more\n",
      maps.scale, maps.scale);
  for (const auto& file : maps.files) std::printf("wrote %s\n", file.string().c_str());
}

}  // namespace

namespace {

// The reference's region mask: channel 0 its penumbraCount (0 where the graph has none),
// channel 1 the silhouette pixels of its depth (when it has a depth resource).
std::optional<FloatImage> reference_mask(const std::optional<FloatImage>& penumbra,
                                         const std::optional<FloatImage>& depth,
                                         const scene::Camera& camera) {
  if (!penumbra && !depth) return std::nullopt;
  if (!depth) return penumbra;
  FloatImage mask;
  mask.width = depth->width;
  mask.height = depth->height;
  mask.channels = 2;
  mask.texels.assign(std::size_t{mask.width} * mask.height * 2, 0.0f);
  const auto edges = silhouette_mask(*depth, camera.near, camera.far);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (penumbra && penumbra->width == mask.width && penumbra->height == mask.height) {
      mask.texels[i * 2] = penumbra->texels[i * penumbra->channels];
    }
    mask.texels[i * 2 + 1] = edges[i];
  }
  return mask;
}

// Before minutes of rendering (lavapipe), not after. False (after saying why) when the
// folder for the error maps cannot be made.
bool create_error_map_folder(const std::string& out) {
  if (std::error_code failure;
      !out.empty() && !std::filesystem::create_directories(out, failure) && failure) {
    std::fprintf(stderr, "antumbra quality: cannot create %s: %s\n", out.c_str(),
                 failure.message().c_str());
    return false;
  }
  return true;
}

// What quality reads from disk, all of it checked before the GPU is touched.
struct QualityInputs {
  std::string reference_path;
  std::string scene_path;
  fg::GraphDesc reference;
  std::vector<fg::GraphDesc> graphs;  // in the order of --graph
  scene::Scene scene;
};

// False (after printing the diagnostics) when a graph or the scene does not load.
bool load_quality_inputs(const QualityOptions& options, const runtime::DataPaths& paths,
                         QualityInputs& inputs) {
  inputs.reference_path =
      options.reference.empty() ? (paths.graphs() / "reference.json").string() : options.reference;
  inputs.scene_path =
      options.scene.empty() ? (paths.scenes() / "atrium.json").string() : options.scene;
  auto reference =
      load_for_quality(inputs.reference_path, options.resource, {"penumbraCount", "depth"});
  if (!reference) return false;
  inputs.reference = std::move(*reference);
  for (const auto& path : options.graphs) {
    auto graph = load_for_quality(path, options.resource, {});
    if (!graph) return false;
    inputs.graphs.push_back(std::move(*graph));
  }
  auto scene = scene::load_scene_file(inputs.scene_path, nullptr,
                                      {.allow_outside_paths = options.allow_outside_paths});
  for (const auto& d : scene.diagnostics())
    std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  if (!scene.ok()) return false;
  inputs.scene = std::move(scene.value());
  return true;
}

// The session quality and techniques render in, with the inputs' scene moved into it.
std::unique_ptr<runtime::RenderSession> open_quality_session(const QualityOptions& options,
                                                             const runtime::DataPaths& paths,
                                                             unsigned width, unsigned height,
                                                             QualityInputs& inputs) {
  runtime::SessionOptions session_options;
  session_options.device = options.device;
  session_options.validation = options.validation;
  session_options.viewport = {width, height};
  auto session = std::make_unique<runtime::RenderSession>(paths, session_options);
  session->set_scene(std::move(inputs.scene));
  return session;
}

// One frame of `graph`; its `resource` read back. Nothing when the graph does not load
// (its diagnostics printed).
std::optional<FloatImage> render_hdr(runtime::RenderSession& session, const fg::GraphDesc& graph,
                                     const std::string& path, const std::string& resource,
                                     double& ms) {
  const auto diagnostics = session.load_graph(graph);
  for (const auto& d : diagnostics) {
    if (d.severity != base::Severity::note)
      std::fprintf(stderr, "%s\n", base::format_text(d).c_str());
  }
  if (diagnostics.has_errors()) {
    std::fprintf(stderr, "antumbra quality: %s does not load\n", path.c_str());
    return std::nullopt;
  }
  gpu::CpuTimer clock;
  session.render(1, nullptr);
  ms = clock.elapsed_ms();
  const auto* image = session.executor().gpu_image(resource);
  const auto* bound = session.executor().image(resource);
  return to_float_image(gpu::read_image(session.gpu(), *image, bound->layout));
}

// Nothing when the loaded graph has no resource of that name.
std::optional<FloatImage> read_back(runtime::RenderSession& session, const char* name) {
  const auto* image = session.executor().gpu_image(name);
  if (image == nullptr) return std::nullopt;
  return to_float_image(
      gpu::read_image(session.gpu(), *image, session.executor().image(name)->layout));
}

// The reference's frame and the regions every technique is measured over.
struct ReferenceFrame {
  FloatImage hdr;
  std::optional<FloatImage> mask;
  std::vector<MaskRegion> regions;
  double ms = 0.0;
};

// Renders the reference while its graph is loaded, so that its penumbra and depth
// resources can still be read back for the region mask.
std::optional<ReferenceFrame> render_reference(runtime::RenderSession& session,
                                               const QualityOptions& options,
                                               const QualityInputs& inputs,
                                               const scene::Camera& camera) {
  double reference_ms = 0.0;
  auto reference_hdr =
      render_hdr(session, inputs.reference, inputs.reference_path, options.resource, reference_ms);
  if (!reference_hdr) return std::nullopt;
  auto mask =
      reference_mask(read_back(session, "penumbraCount"), read_back(session, "depth"), camera);
  auto regions = regions_for("", mask.has_value()).value();
  if (mask && mask->channels >= 2) regions.push_back(MaskRegion::silhouette);
  return ReferenceFrame{std::move(*reference_hdr), std::move(mask), std::move(regions),
                        reference_ms};
}

// MiB of the plan's resources a technique adds to the G-buffer and the output (every
// graph has depth, normal, albedo, hdr and ldr).
double technique_resource_mib(const fg::Plan& plan) {
  double bytes = 0.0;
  for (const auto& r : plan.resources) {
    if (r.name == "depth" || r.name == "normal" || r.name == "albedo" || r.name == "hdr" ||
        r.name == "ldr") {
      continue;
    }
    bytes += r.kind == fg::ResourceKind::buffer
                 ? static_cast<double>(r.buffer_size)
                 : static_cast<double>(r.extent.width) * r.extent.height * r.layers *
                       fg::bytes_per_texel(r.format);
  }
  return bytes / (1024.0 * 1024.0);
}

// What passes keep of their own beside the graph's resources, as their frame reports
// state it (a "privateMiB" detail: penumbra-wedges' second depth layer and wedge buffers).
double private_resource_mib(const fgvk::FrameReport& report) {
  double mib = 0.0;
  for (const auto& m : report.messages()) {
    if (m.details.is_object() && m.details.contains("privateMiB") &&
        m.details["privateMiB"].is_number()) {
      mib += m.details["privateMiB"].get<double>();
    }
  }
  return mib;
}

// Per technique: its JSON result (JSON reports) and its signed error (error maps).
struct TechniqueResults {
  nlohmann::json graphs = nlohmann::json::array();
  std::vector<std::vector<float>> errors;
};

// Renders the technique graph `index` and measures it against the reference. False when
// it does not load.
bool compare_technique(runtime::RenderSession& session, const QualityOptions& options,
                       const QualityInputs& inputs, std::size_t index,
                       const ReferenceFrame& reference, const std::string& label, bool json,
                       TechniqueResults& results) {
  double ms = 0.0;
  const auto hdr =
      render_hdr(session, inputs.graphs[index], options.graphs[index], options.resource, ms);
  if (!hdr) return false;
  const auto comparisons = compare_images(
      reference.hdr, *hdr, reference.mask ? &*reference.mask : nullptr, reference.regions);
  if (!options.out.empty()) results.errors.push_back(signed_error(reference.hdr, *hdr));
  if (json) {
    results.graphs.push_back({{"graph", options.graphs[index]},
                              {"renderMs", ms},
                              {"regions", metrics_json(comparisons)}});
  } else {
    for (const auto& c : comparisons) print_row(label, c);
  }
  return true;
}

// False (after saying why) when a map cannot be written.
bool write_quality_error_maps(const QualityOptions& options, const std::vector<std::string>& labels,
                              unsigned width, unsigned height, bool json, TechniqueResults& results,
                              ErrorMaps& maps) {
  try {
    maps = write_error_maps(options.out, labels, results.errors, width, height);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "antumbra quality: %s\n", e.what());
    return false;
  }
  for (std::size_t i = 0; json && i < maps.files.size(); ++i) {
    results.graphs[i]["errorMap"] = maps.files[i].string();
  }
  return true;
}

// The reference graph's shadow-reference passes with their parameters as the file gives
// them (the pass's defaults fill the rest): a results file then says which ruler measured
// it, rays or shadow maps (docs/measuring.md).
nlohmann::json reference_passes_json(const fg::GraphDesc& graph) {
  auto passes = nlohmann::json::array();
  for (const auto& pass : graph.passes) {
    if (pass.enabled && pass.type == "shadow-reference") {
      passes.push_back({{"name", pass.name}, {"params", pass.params}});
    }
  }
  return passes;
}

void print_quality_json(runtime::RenderSession& session, const QualityInputs& inputs,
                        const ReferenceFrame& reference, unsigned width, unsigned height,
                        const TechniqueResults& results, const ErrorMaps& maps,
                        const base::Diagnostics& report_diagnostics) {
  // What measured it (commit, device, driver): docs-tables publishes from this file.
  nlohmann::json report{{"commit", build_commit()},
                        {"device", session.gpu().device_name()},
                        {"driver", driver_summary(session.gpu())},
                        {"reference", inputs.reference_path},
                        {"referencePasses", reference_passes_json(inputs.reference)},
                        {"referenceMs", reference.ms},
                        {"scene", inputs.scene_path},
                        {"width", width},
                        {"height", height},
                        {"signal", kMetricNote},
                        {"graphs", results.graphs},
                        {"diagnostics", report_diagnostics.to_json()}};
  if (!maps.files.empty()) report["errorMapScale"] = maps.scale;
  std::printf("%s\n", report.dump(2).c_str());
}

}  // namespace

int run_quality(const QualityOptions& options) {
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(options.size, width, height)) {
    std::fprintf(stderr, "antumbra quality: --size must be WxH with 1..16384, got \"%s\"\n",
                 options.size.c_str());
    return runtime::kExitUsage;
  }
  const bool json = options.format == "json";
  base::Diagnostics report_diagnostics;
  if (auto warning = ranking_size_warning(width, height)) {
    std::fprintf(stderr, "%s\n", base::format_text(*warning).c_str());
    report_diagnostics.add(std::move(*warning));
  }
  if (!create_error_map_folder(options.out)) return runtime::kExitRuntime;
  const runtime::DataPaths paths = runtime::find_data_paths();
  QualityInputs inputs;
  if (!load_quality_inputs(options, paths, inputs)) return runtime::kExitDiagnostics;

  const scene::Camera camera = inputs.scene.camera;
  const auto owned = open_quality_session(options, paths, width, height, inputs);
  runtime::RenderSession& session = *owned;

  const auto reference = render_reference(session, options, inputs, camera);
  if (!reference) return runtime::kExitDiagnostics;
  if (!json) {
    std::printf("device: %s; reference %s rendered in %.0f ms at %ux%u\n",
                session.gpu().device_name().c_str(), inputs.reference_path.c_str(), reference->ms,
                width, height);
    print_header();
  }
  const auto labels = unique_labels(options.graphs);
  TechniqueResults results;
  for (std::size_t i = 0; i < inputs.graphs.size(); ++i) {
    if (!compare_technique(session, options, inputs, i, *reference, labels[i], json, results)) {
      return runtime::kExitDiagnostics;
    }
  }
  ErrorMaps maps;
  if (!options.out.empty() &&
      !write_quality_error_maps(options, labels, width, height, json, results, maps)) {
    return runtime::kExitRuntime;
  }
  if (json) {
    print_quality_json(session, inputs, *reference, width, height, results, maps,
                       report_diagnostics);
  } else {
    std::printf("(%s)\n", kMetricNote);
    print_error_maps(maps);
  }
  if (options.validation && session.gpu().validation_error_count() > 0) {
    std::fprintf(stderr, "antumbra quality: %zu validation error(s)\n",
                 session.gpu().validation_error_count());
    return runtime::kExitRuntime;
  }
  return runtime::kExitOk;
}

std::optional<QualityFrames> render_quality_frames(const QualityOptions& options) {
  unsigned width = 0;
  unsigned height = 0;
  if (!parse_size(options.size, width, height)) {
    std::fprintf(stderr, "antumbra: --size must be WxH with 1..16384, got \"%s\"\n",
                 options.size.c_str());
    return std::nullopt;
  }
  const runtime::DataPaths paths = runtime::find_data_paths();
  QualityInputs inputs;
  if (!load_quality_inputs(options, paths, inputs)) return std::nullopt;
  const scene::Camera camera = inputs.scene.camera;
  const auto owned = open_quality_session(options, paths, width, height, inputs);
  runtime::RenderSession& session = *owned;
  auto reference = render_reference(session, options, inputs, camera);
  if (!reference) return std::nullopt;
  QualityFrames frames;
  frames.device = session.gpu().device_name();
  for (std::size_t i = 0; i < inputs.graphs.size(); ++i) {
    std::fprintf(stderr, "antumbra: [%zu/%zu] %s\n", i + 1, inputs.graphs.size(),
                 options.graphs[i].c_str());
    double ms = 0.0;
    auto hdr = render_hdr(session, inputs.graphs[i], options.graphs[i], options.resource, ms);
    if (!hdr) return std::nullopt;
    frames.comparisons.push_back(compare_images(
        reference->hdr, *hdr, reference->mask ? &*reference->mask : nullptr, reference->regions));
    frames.resource_mib.push_back(technique_resource_mib(session.executor().plan()) +
                                  private_resource_mib(session.last_report()));
    frames.frames.push_back(std::move(*hdr));
  }
  frames.reference = std::move(reference->hdr);
  frames.mask = std::move(reference->mask);
  return frames;
}

// Below this many pixels quality's ranking of techniques is not to be trusted. Measured
// on lavapipe, atrium, hard / PCSS / layered SSSS (README, "Quality and bench
// reports"): ranked by RMSE over all pixels, PCSS < hard < layered at 160x90, 320x180
// and 480x270, PCSS < layered < hard at 640x360, layered < PCSS < hard at 960x540 and
// 1280x720 (penumbra pixels alike). The layered technique estimates penumbrae and blurs
// at half resolution, so a small frame measures a blur of a few dozen texels more than
// the technique.
constexpr unsigned kStableRankingWidth = 960;
constexpr unsigned kStableRankingHeight = 540;

std::optional<base::Diagnostic> ranking_size_warning(unsigned width, unsigned height) {
  if (std::uint64_t{width} * height >= std::uint64_t{kStableRankingWidth} * kStableRankingHeight) {
    return std::nullopt;
  }
  char message[240];
  std::snprintf(message, sizeof message,
                "at %ux%u the ranking of techniques is not reliable: on the atrium it changes up "
                "to %ux%u; use --size %ux%u (or as many pixels) or larger to rank them",
                width, height, kStableRankingWidth, kStableRankingHeight, kStableRankingWidth,
                kStableRankingHeight);
  return base::Diagnostic{
      codes::quality::kRankingUnreliable, base::Severity::warning, message, "", "", 0, 0};
}

}  // namespace antumbra::app
