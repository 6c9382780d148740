#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "common/rasterizer_choice.hpp"
#include "common/shadow_data.hpp"
#include "pages.h"
#include "point_shadow_atlas_pass.hpp"
#include "pool_fit.hpp"

namespace antumbra::passes {
namespace {

// A reader of a paged atlas that does not bind its tables would read pages as squares.
void check_pool_readers(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
                        base::Diagnostics& diagnostics) {
  const int atlas = bound_index(pass, port::kAtlas);
  const int colour = bound_index(pass, port::kColour);  // paged alike
  const int tables = bound_index(pass, port::kPageTables);
  for (const fg::PlanPass& reader : plan.passes) {
    if (&reader == &pass) continue;
    const auto reads =
        std::find_if(reader.bindings.begin(), reader.bindings.end(), [&](const fg::PlanBinding& b) {
          return b.resource == atlas || (colour >= 0 && b.resource == colour);
        });
    if (reads == reader.bindings.end()) continue;
    const auto port =
        std::find_if(reader.bindings.begin(), reader.bindings.end(),
                     [](const fg::PlanBinding& b) { return b.port == port::kPageTables.name(); });
    if (port != reader.bindings.end() && port->resource == tables) continue;
    const std::string atlas_name = plan.resources[static_cast<std::size_t>(reads->resource)].name;
    const std::string owner = "'" + atlas_name + "' is paged (pagePool of '" + pass.name + "')";
    if (port == reader.bindings.end()) {
      add_pass_error(graph, reader, codes::graph::kPortUnbound,
                     owner + ", and a " + reader.type +
                         " pass has no pageTables input to read its pages through: read an "
                         "atlas without pagePool",
                     "/in/" + reads->port, diagnostics);
    } else {
      add_pass_error(graph, reader, codes::graph::kPortUnbound,
                     owner + ": bind its pageTables output '" +
                         plan.resources[static_cast<std::size_t>(tables)].name +
                         "' to this pass's pageTables, through which its pages are found",
                     "/in/pageTables", diagnostics);
    }
  }
}

// pagePool's needs (docs/technique.md, "Page pool").
void check_pool(const fg::PlanPass& pass, const PointShadowAtlasParams& params,
                const fg::PlanResource& atlas, const fg::Plan& plan, const fg::GraphDesc& graph,
                base::Diagnostics& diagnostics) {
  if (!params.page_pool) return;
  std::vector<std::string> wants;
  if (params.rasterizer != ShadowRasterizer::compute) {
    wants.emplace_back("rasterizer \"compute\" (its resolve writes the pool's pages)");
  }
  if (atlas.format != fg::Format::r32f) wants.emplace_back("an r32f atlas");
  if (!params.receiver_culling || !params.receiver_pages || bound_index(pass, port::kDepth) < 0) {
    wants.emplace_back(
        "receiverCulling and receiverPages with `depth` bound (a page gets a place when a "
        "visible pixel needs it)");
  }
  const std::uint32_t size = atlas.extent.width;
  if (size != atlas.extent.height || size % shared::kPageSize != 0 || size > 4096) {
    wants.emplace_back("a square atlas of whole " + std::to_string(shared::kPageSize) +
                       "-texel pages, at most 4096 wide (it is " + std::to_string(size) + "x" +
                       std::to_string(atlas.extent.height) + ")");
  }
  const fg::PlanResource* tables = bound_resource(pass, plan, port::kPageTables);
  if (tables == nullptr)
    wants.emplace_back("`pageTables` bound (the readers find pages through it)");
  const fg::PlanResource* data = bound_resource(pass, plan, port::kShadowData);
  const std::uint32_t records = face_records(data != nullptr ? data->buffer_size : 0, atlas.layers);
  const std::uint64_t side = (size + shared::kPageSize - 1) / shared::kPageSize;
  const std::uint64_t pages = std::uint64_t{atlas.layers} * side * side;
  const std::uint32_t fallback = params.page_fallback ? pool_fallback_pages(records) : 0u;
  if (params.page_fallback && pages <= fallback) {
    wants.emplace_back("more than the " + std::to_string(fallback) + " pages its " +
                       std::to_string(records) + " face records' fallback tiles take (the " +
                       "atlas has " + std::to_string(pages) + "): more layers or fewer records");
  }
  for (const std::string& want : wants) {
    add_pass_error(graph, pass, codes::graph::kParamRange, "pagePool needs " + want,
                   "/params/pagePool", diagnostics);
  }
  if (tables == nullptr) return;
  const std::uint64_t needed = std::uint64_t{records} * side * side * 4;
  if (tables->buffer_size < needed) {
    add_pass_error(graph, pass, codes::shadow_atlas::kShadowDataTooSmall,
                   "the pageTables buffer '" + tables->name + "' holds " +
                       std::to_string(tables->buffer_size) + " bytes; a table of " +
                       std::to_string(side * side) + " words for each face record needs " +
                       std::to_string(needed),
                   "/out/pageTables", diagnostics);
  }
  check_pool_readers(pass, plan, graph, diagnostics);
}

// Buffer and colour-map sizes against the atlas: compiler checks, so validate sees them.
void check(const fg::PlanPass& pass, const PointShadowAtlasParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* data = bound_resource(pass, plan, port::kShadowData);
  if (atlas == nullptr) return;  // a required port: the compiler has reported it
  check_kept_between_frames(pass, plan, port::kAtlas, "the faces it caches", graph, diagnostics);
  check_kept_between_frames(pass, plan, port::kColour, "the tints of the faces it caches", graph,
                            diagnostics);
  if (atlas->layers > kMaxAtlasLayers) {
    add_pass_error(graph, pass, codes::shadow_atlas::kTooManyLayers,
                   "the atlas '" + atlas->name + "' has " + std::to_string(atlas->layers) +
                       " layers; a face record names at most " + std::to_string(kMaxAtlasLayers) +
                       " (passes/interface/shared/shadow_data.h)",
                   "/out/atlas", diagnostics);
  }
  const std::size_t needed = shadow_data_bytes(atlas->layers);
  if (data != nullptr && data->buffer_size < needed) {
    add_pass_error(graph, pass, codes::shadow_atlas::kShadowDataTooSmall,
                   "the shadowData buffer '" + data->name + "' holds " +
                       std::to_string(data->buffer_size) + " bytes; " +
                       std::to_string(atlas->layers) + " atlas layers need " +
                       std::to_string(needed) + " (shadow_data_bytes(layers))",
                   "/out/shadowData", diagnostics);
  }
  const bool compute = params.rasterizer == ShadowRasterizer::compute;
  if (compute && std::max(atlas->extent.width, atlas->extent.height) > shared::kMaxPagedFace) {
    add_pass_error(graph, pass, codes::shadow_atlas::kFaceTooLarge,
                   "rasterizer \"compute\" draws faces of at most " +
                       std::to_string(shared::kMaxPagedFace) + " texels (its page lists name " +
                       "their 128^2 pages in 15 bits); the atlas '" + atlas->name + "' is " +
                       std::to_string(atlas->extent.width) + "x" +
                       std::to_string(atlas->extent.height),
                   "/out/atlas", diagnostics);
  }
  if (compute && atlas->format == fg::Format::d16) {
    add_pass_error(graph, pass, codes::shadow_atlas::kRasterizerFormat,
                   "rasterizer \"compute\" writes 32-bit float depth; the atlas '" + atlas->name +
                       "' is d16: make it r32f (written by the compute shader, fastest) or d32f "
                       "(filled by copies), or use rasterizer \"hardware\"",
                   "/params/rasterizer", diagnostics);
  }
  if (!compute && !fg::is_depth_format(atlas->format)) {
    add_pass_error(graph, pass, codes::shadow_atlas::kRasterizerFormat,
                   "rasterizer \"hardware\" renders into a depth attachment; the atlas '" +
                       atlas->name + "' is " + std::string(fg::to_string(atlas->format)) +
                       ": make it d32f or d16, or use rasterizer \"compute\"",
                   "/params/rasterizer", diagnostics);
  }
  check_pool(pass, params, *atlas, plan, graph, diagnostics);
  const std::uint32_t minimum = params.min_resolution;
  if ((minimum & (minimum - 1)) != 0) {
    add_pass_error(graph, pass, codes::graph::kParamRange,
                   "minResolution " + std::to_string(minimum) +
                       " is not a power of two: faces are 16, 32, 64 ... texels wide",
                   "/params/minResolution", diagnostics);
  }
}

// The compute rasteriser writes an r32f atlas and the colour map from a compute shader
// (storage images; it keeps the cached layers, so read-write) and fills a depth atlas by
// copies from its own buffers (compute_raster.hpp); the graph's barriers follow.
std::optional<fg::PortUse> port_use(const fg::PortDesc& port, const PointShadowAtlasParams& params,
                                    fg::Format format) {
  if (params.rasterizer != ShadowRasterizer::compute) return std::nullopt;
  // The GPU's face decision publishes the shadow data and the page tables (face_decision.hpp).
  if (port.name == port::kShadowData.name() || port.name == port::kPageTables.name()) {
    return fg::PortUse{fg::Access::storage_write, fg::Stage::compute};
  }
  const bool storage = (port.name == port::kAtlas.name() && format == fg::Format::r32f) ||
                       port.name == port::kColour.name();
  if (storage) return fg::PortUse{fg::Access::storage_read_write, fg::Stage::compute};
  if (port.name == port::kAtlas.name()) {
    return fg::PortUse{fg::Access::transfer_dst, fg::Stage::transfer};
  }
  return std::nullopt;
}

// "auto" (or absent) becomes the rasteriser the atlas's format and the device call for
// (rasterizer_choice.hpp); anything else is the parameter check's to judge.
std::vector<std::string> resolve_atlas_rasterizer(PointShadowAtlasParams& params,
                                                  const fg::PassInstanceDesc& pass,
                                                  const fg::GraphDesc& graph,
                                                  const fg::DeviceTraits* device) {
  return resolve_auto_rasterizer(params.rasterizer, pass, graph, port::kAtlas,
                                 &choose_atlas_rasterizer, device);
}

}  // namespace

fg::PassDesc PointShadowAtlasPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::ResourceKind;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "point-shadow-atlas";
  desc.description =
      "Renders the six 90-degree faces of every shadow-casting point light into one layered "
      "depth atlas (face k of light slot s at layer 6s+k) with one instanced draw, culls faces "
      "the camera cannot see, re-renders only faces whose light or geometry changed, and "
      "writes the per-light/per-face shadowData table.";
  desc.ports = {
      {.name = port::kDepth,
       .direction = PortDirection::input,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::d32f, Format::d16},
       .optional = true,
       .description =
           "G-buffer depth, for receiver culling (parameter receiverCulling): with rasterizer "
           "\"compute\" and an r32f atlas, a face is drawn only when a visible pixel lies in "
           "its frustum and its light's range (docs/technique.md). Otherwise unused."},
      {.name = port::kAtlas,
       .direction = PortDirection::output,
       .access = Access::depth_attachment,
       .stage = Stage::graphics,
       .formats = {Format::d32f, Format::d16, Format::r32f},
       .min_layers = 6,
       .max_layers = 0,
       .size_group = "atlas",
       .description =
           "Face depths (0 near .. 1 at the light's range); declare it persistent "
           "so that cached faces survive between frames. r32f with rasterizer \"compute\" "
           "(written by its compute shader; d32f works too, filled by slower copies)."},
      {.name = port::kColour,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::graphics,
       .formats = {Format::rgba8},
       .min_layers = 6,
       .max_layers = 0,
       .optional = true,
       .size_group = "atlas",
       .layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least},
       .description = "Shadow colour per face: product of the transmittances of the translucent "
                      "casters along the ray (white = clear); translucent casters then stay out "
                      "of the depth atlas. Persistent too. With "
                      "rasterizer \"compute\": written by its compute shader (storage image)."},
      {.name = port::kShadowData,
       .direction = PortDirection::output,
       .kind = ResourceKind::buffer,
       .access = Access::transfer_dst,
       .stage = Stage::transfer,
       .description =
           "Header, ShadowLight for each of up to 4096 scene lights and ShadowFace records "
           "(passes/interface/shared/shadow_data.h); at least shadow_data_bytes(layers) = 16 + "
           "64 * 4096 + 80 * layers bytes, one record per layer. Faces smaller than a layer "
           "share layers, so more records (80 bytes each, up to 6 per light) let more lights "
           "cast shadows than the layers hold whole faces."},
      {.name = port::kPageTables,
       .direction = PortDirection::output,
       .kind = ResourceKind::buffer,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .optional = true,
       .description =
           "With pagePool: each face record's page table (passes/interface/shared/"
           "page_tables.h), 4 bytes per 128^2 page of an atlas face per record (records x "
           "(size / 128)^2 x 4). Every pass that reads the atlas binds it."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  desc.port_use = table.port_use(&port_use);
  desc.resolve = table.resolve(&resolve_atlas_rasterizer);
  return desc;
}

namespace {

// Who draws the faces ("auto": resolved when the graph compiles, common/rasterizer_choice.hpp).
void add_rasterizer_param(fg::ParamTable<PointShadowAtlasParams>& table) {
  table.choice(
      {.name = "rasterizer",
       .type = fg::ParamType::enumeration,
       .default_value = "auto",
       .choices = {"auto", "hardware", "compute"},
       .description =
           "Who draws the faces: \"hardware\" renders them (vertex shader, depth "
           "attachment); \"compute\" culls scene clusters per face and rasterises them in "
           "compute shaders (atomic min into a buffer copied into the atlas), for GPUs "
           "with few raster units; \"auto\" picks per device from measurements when the "
           "graph compiles (compute on NVIDIA Hopper GPUs, hardware elsewhere; an r32f "
           "atlas is always compute, d16 hardware) and says why in note FG076 "
           "(docs/technique.md)."},
      &PointShadowAtlasParams::rasterizer,
      {ShadowRasterizer::automatic, ShadowRasterizer::hardware, ShadowRasterizer::compute});
}

// Which faces are drawn and at what size (receiver culling, per-light resolution).
void add_face_choice_params(fg::ParamTable<PointShadowAtlasParams>& table) {
  table
      .add({.name = "receiverCulling",
            .type = fg::ParamType::boolean,
            .default_value = true,
            .description =
                "With `depth` bound, rasterizer \"compute\" and an r32f atlas: draw only "
                "the faces some visible pixel needs, decided on the GPU each frame (a face "
                "that gains a receiver is drawn that frame). Otherwise every face the "
                "camera's frustum may need is drawn."},
           &PointShadowAtlasParams::receiver_culling)
      .add({.name = "receiverPages",
            .type = fg::ParamType::boolean,
            .default_value = true,
            .description =
                "With receiverCulling: draw only the 128^2 pages of a face that some visible "
                "pixel's lookups may read (within 72 texels of where it falls, plus the "
                "blocker searches' reach: pageReach times the light's size over the "
                "distance, at most a quarter face), each kept until its face changes; the "
                "face's other pages hold far depth. Off: every page of a face some pixel "
                "needs (docs/technique.md, \"Receiver-driven pages\")."},
           &PointShadowAtlasParams::receiver_pages)
      .add({.name = "pageReach",
            .type = fg::ParamType::number,
            .default_value = 1.0,
            .min = 0.0,
            .max = 16.0,
            .description =
                "With receiverPages: the blocker-search scale the drawn pages cover around "
                "each visible pixel, in units of the light's size over its distance (the "
                "searches of layered-penumbra and the moment lookups at searchScale x "
                "lightSizeScale 1; set it to at least their product). Larger values draw "
                "more pages."},
           &PointShadowAtlasParams::page_reach)
      .choice(
          {.name = "resolution",
           .type = fg::ParamType::enumeration,
           .default_value = "fixed",
           .choices = {"fixed", "screen"},
           .description = "Face size: \"fixed\" gives every light the atlas's; \"screen\" picks "
                          "each light's from the screen radius of its range sphere times "
                          "resolutionScale, a power of two from minResolution up to the atlas's, "
                          "with a quarter-octave band against flicker; its faces fill the corner "
                          "square of their layers (docs/technique.md)."},
          &PointShadowAtlasParams::resolution, {FaceResolution::fixed, FaceResolution::screen})
      .add({.name = "resolutionScale",
            .type = fg::ParamType::number,
            .default_value = 1.0,
            .min = 0.0625,
            .max = 16.0,
            .description = "With resolution \"screen\": face texels per pixel of the light's "
                           "projected radius (1: a texel per pixel at half its range)."},
           &PointShadowAtlasParams::resolution_scale)
      .add({.name = "minResolution",
            .type = fg::ParamType::integer,
            .default_value = 64,
            .min = 16.0,
            .max = 4096.0,
            .description = "With resolution \"screen\": the smallest face size, a power of "
                           "two (faces are never larger than the atlas's)."},
           &PointShadowAtlasParams::min_resolution);
}

// The page pool (docs/technique.md, "Page pool").
void add_pool_params(fg::ParamTable<PointShadowAtlasParams>& table) {
  table
      .add({.name = "pagePool",
            .type = fg::ParamType::boolean,
            .default_value = false,
            .description =
                "The atlas's layers become one pool of 128^2 pages, and a light's faces "
                "(each its own size, up to the atlas's) take pages only where a visible "
                "pixel needs them, through page tables (`pageTables`, which every reader of "
                "the atlas binds). A full pool gives the least recently needed pages to the "
                "needed ones; a needed page left without one reads its face's coarser level "
                "(pageFallback), and SHD010 counts it. Needs rasterizer \"compute\", an r32f "
                "square atlas, receiverCulling and receiverPages with `depth` bound "
                "(docs/technique.md, \"Page pool\")."},
           &PointShadowAtlasParams::page_pool)
      .add({.name = "pageFallback",
            .type = fg::ParamType::boolean,
            .default_value = true,
            .description =
                "With pagePool: every face record keeps a 32^2 tile of its face in pages "
                "reserved at the pool's end (a page per 16 records), and a needed page the "
                "full pool has no place for is drawn there at a coarser level (the farthest "
                "depth of the texels each tile texel covers) and read from it, instead of "
                "reading as lit until the faces shrink (docs/technique.md, \"Page pool\")."},
           &PointShadowAtlasParams::page_fallback);
}

// How much is drawn per frame when much changes (dynamic meshes, moving lights).
void add_update_params(fg::ParamTable<PointShadowAtlasParams>& table) {
  table
      .add({.name = "staticCache",
            .type = fg::ParamType::boolean,
            .default_value = true,
            .description =
                "With rasterizer \"hardware\" and the layered draw: a face that dynamic meshes "
                "(the scene's \"dynamic\" objects) touch keeps its static meshes' depth in a "
                "private cache and redraws only the dynamic meshes over a copy of it when they "
                "move. Faces they do not touch are never redrawn for them."},
           &PointShadowAtlasParams::static_cache)
      .add({.name = "faceBudget",
            .type = fg::ParamType::integer,
            .default_value = 65536,
            .min = 1.0,
            .max = 1048576.0,
            .description =
                "Faces drawn per frame at most, besides those that must be: never drawn, or "
                "maxStaleFrames behind. Lights that wait show the shadow they were last drawn "
                "with; the longest waiting go first, then the largest on screen."},
           &PointShadowAtlasParams::face_budget)
      .add({.name = "maxStaleFrames",
            .type = fg::ParamType::integer,
            .default_value = 4,
            .min = 0.0,
            .max = 1000.0,
            .description = "A light's shadow is never more than this many frames behind it: "
                           "then it is drawn whatever the budget (0: never behind)."},
           &PointShadowAtlasParams::max_stale);
}

// The directional light's cascaded shadow maps (light_faces.hpp).
void add_sun_params(fg::ParamTable<PointShadowAtlasParams>& table) {
  table
      .add({.name = "sunDistance",
            .type = fg::ParamType::number,
            .default_value = 40.0,
            .min = 1.0,
            .max = 10000.0,
            .description = "The directional light's cascades cover the camera frustum up to this "
                           "distance in metres (beyond it the sun is unshadowed)."},
           &PointShadowAtlasParams::sun_distance)
      .add({.name = "sunCascades",
            .type = fg::ParamType::integer,
            .default_value = 4,
            .min = 1.0,
            .max = 4.0,
            .description = "Cascaded shadow maps of the directional light: one atlas layer "
                           "each, nearest first (fewer when the atlas is full)."},
           &PointShadowAtlasParams::sun_cascades)
      .add({.name = "sunSplitLambda",
            .type = fg::ParamType::number,
            .default_value = 0.75,
            .min = 0.0,
            .max = 1.0,
            .description = "PSSM split blend between cascades: 0 uniform, 1 logarithmic "
                           "split distances."},
           &PointShadowAtlasParams::sun_split_lambda)
      .add({.name = "sunCascadeBlend",
            .type = fg::ParamType::number,
            .default_value = 0.1,
            .min = 0.0,
            .max = 0.45,
            .description = "Band at a cascade's edge, as a fraction of its half width, over "
                           "which lookups blend into the next cascade (0: a hard switch)."},
           &PointShadowAtlasParams::sun_cascade_blend);
}

}  // namespace

const fg::ParamTable<PointShadowAtlasParams>& PointShadowAtlasPass::param_table() {
  static const auto kTable = [] {
    fg::ParamTable<PointShadowAtlasParams> table;
    table
        .add({.name = "nearPlane",
              .type = fg::ParamType::number,
              .default_value = 0.05,
              .min = 0.001,
              .max = 10.0,
              .description = "Near plane of every face in metres (capped at half the range)."},
             &PointShadowAtlasParams::near_plane)

        .add({.name = "depthBias",
              .type = fg::ParamType::number,
              .default_value = 2.0,
              .min = 0.0,
              .max = 1000.0,
              .description =
                  "Constant raster depth bias (depthBiasConstantFactor: units of the depth "
                  "format's resolution)."},
             &PointShadowAtlasParams::depth_bias)
        .add({.name = "slopeBias",
              .type = fg::ParamType::number,
              .default_value = 1.75,
              .min = 0.0,
              .max = 16.0,
              .description = "Slope-scaled raster depth bias (depthBiasSlopeFactor)."},
             &PointShadowAtlasParams::slope_bias)
        .add(
            {.name = "cullFaces",
             .type = fg::ParamType::boolean,
             .default_value = true,
             .description = "Skip faces whose frustum (to the light's range) misses the camera's."},
            &PointShadowAtlasParams::cull_faces)
        .add(
            {.name = "cache",
             .type = fg::ParamType::boolean,
             .default_value = true,
             .description = "Keep faces whose light and geometry did not change (static caching)."},
            &PointShadowAtlasParams::cache)
        .add({.name = "translucentColour",
              .type = fg::ParamType::boolean,
              .default_value = true,
              .description =
                  "With `colour` bound: translucent casters tint the colour map instead of "
                  "writing depth. Off (or `colour` unbound): they cast opaque shadows."},
             &PointShadowAtlasParams::translucent_colour)
        .add({.name = "layeredDraw",
              .type = fg::ParamType::boolean,
              .default_value = true,
              .description =
                  "One instanced draw writing gl_Layer where the device supports it "
                  "(shaderOutputLayer). Off forces the fallback such devices take, one draw per "
                  "face into a single-layer view, on any device: to reproduce or time their path "
                  "(hardware rasteriser only)."},
             &PointShadowAtlasParams::layered_draw);
    add_rasterizer_param(table);
    add_sun_params(table);
    add_face_choice_params(table);
    add_pool_params(table);
    add_update_params(table);
    return table;
  }();
  return kTable;
}

}  // namespace antumbra::passes
