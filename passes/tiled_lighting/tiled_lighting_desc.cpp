#include "common/layer_table.hpp"
#include "common/lighting_reflection.hpp"
#include "common/moment_technique.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "tiled_lighting_pass.hpp"

namespace antumbra::passes {
namespace {

using fg::Access;
using fg::Format;
using fg::PortDirection;
using fg::ResourceKind;
using fg::Stage;

std::vector<fg::PortDesc> atlas_ports(bool optional) {
  return {
      {.name = port::kAtlas,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::d32f, Format::d16, Format::r32f},
       .min_layers = 6,
       .max_layers = 0,
       .optional = optional,
       .description = "Point-shadow atlas: face k of light slot s at layer 6s+k "
                      "(point-shadow-atlas)."},
      {.name = port::kShadowData,
       .kind = ResourceKind::buffer,
       .access = Access::storage_read,
       .stage = Stage::compute,
       .optional = optional,
       .description = "Per-light atlas slots and face matrices (interface/shared/shadow_data.h)."},
      page_tables_input(),
  };
}

using Table = fg::ParamTable<TiledLightingParams>;

Table& add_kernel(Table& table, const char* what) {
  // An enumeration rather than an integer: the filter sizes of the technique are exactly
  // these three, and the graph compiler then rejects any other value (with suggestions).
  return table.choice(
      {.name = "kernel",
       .type = fg::ParamType::enumeration,
       .default_value = "11",
       .choices = {"5", "11", "23"},
       .description = std::string("Filter taps per side of the ") + what + " (5x5, 11x11, 23x23)."},
      &TiledLightingParams::kernel, {5, 11, 23});
}

Table& add_pcss(Table& table) {
  return table
      .add({.name = "blockerSearch",
            .type = fg::ParamType::integer,
            .default_value = 5,
            .min = 1.0,
            .max = 23.0,
            .description = "PCSS blocker-search taps per side (even values round up to "
                           "odd); the region they span scales with the light size."},
           &TiledLightingParams::blocker_search)
      .add({.name = "lightSizeScale",
            .type = fg::ParamType::number,
            .default_value = 1.0,
            .min = 0.0,
            .max = 16.0,
            .description = "Multiplies each light's size (w_light) in the PCSS, VSSM and SDF "
                           "penumbra estimates."},
           &TiledLightingParams::light_size_scale);
}

// Same names, ranges and defaults as deferred-lighting, so images match with shadows off.
Table lighting_table() {
  return Table().include(&TiledLightingParams::lighting, lighting_param_table());
}

Table tiled_table() {
  Table table = lighting_table();
  table.choice(
      {.name = "shadows",
       .type = fg::ParamType::enumeration,
       .default_value = "none",
       .description = "Shadow term: none; hard, pcf or pcss from the atlas (atlas + shadowData "
                      "required); layered from the blurred layer buffer (layerTable + shadow "
                      "required); vsm, evsm2, evsm4, msm or vssm from shadow-moments' map of "
                      "the same technique (moments + atlas + shadowData required); sdf by "
                      "sphere tracing scene-sdf's distance field (sdf + sdfInfo required); "
                      "penumbra-map from penumbra-wedges' map and depth layers (penumbraMap + "
                      "atlas + shadowData required, peeled optional)."},
      &TiledLightingParams::shadows,
      {ShadowMode::none, ShadowMode::hard, ShadowMode::pcf, ShadowMode::pcss, ShadowMode::layered,
       ShadowMode::vsm, ShadowMode::evsm2, ShadowMode::evsm4, ShadowMode::msm, ShadowMode::vssm,
       ShadowMode::sdf, ShadowMode::penumbra_map});
  add_kernel(table, "PCF / PCSS filter and the layered fallback");
  add_pcss(table);
  table.choice(
      {.name = "fallback",
       .type = fg::ParamType::enumeration,
       .default_value = "pcf",
       .choices = {"hard", "pcf"},
       .description = "Layered mode: atlas lookup for lights without a layer (needs the atlas)."},
      &TiledLightingParams::pcf_fallback, {false, true});
  table.add({.name = "lightBleedReduction",
             .type = fg::ParamType::number,
             .default_value = 0.2,
             .min = 0.0,
             .max = 0.95,
             .description = "Moment modes: visibilities below this become shadow and the rest "
                            "are rescaled, removing light bleeding where occluders overlap at "
                            "the cost of darker, thinner penumbrae (0: off)."},
            &TiledLightingParams::bleeding_reduction);
  table.choice(
      {.name = "wedgeWidth",
       .type = fg::ParamType::enumeration,
       .default_value = "receiver",
       .choices = {"receiver", "fixed"},
       .description = "Penumbra-map mode: receiver rescales each wedge's ramp by how far the "
                      "receiver lies behind the wedge (similar triangles, so penumbrae widen "
                      "with distance); fixed uses the ramp as drawn, as the seed does."},
      &TiledLightingParams::wedge_receiver, {true, false});
  return table;
}

Table pcf_table() {
  Table table = lighting_table();
  add_kernel(table, "PCF box filter");
  return table;
}

Table pcss_table() {
  Table table = lighting_table();
  add_kernel(table, "PCF step (the largest penumbra it can draw)");
  add_pcss(table);
  return table;
}

// Moment modes read shadow-moments' map through the atlas's face data, and the map
// must hold the technique the mode decodes (the producer's `technique`).
void check_moments(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
                   ShadowMode mode, const std::string& mode_at, base::Diagnostics& diagnostics) {
  const int moments = bound_index(pass, port::kMoments);
  if (moments < 0 || bound_resource(pass, plan, port::kAtlas) == nullptr) {
    add_pass_error(graph, pass, codes::lighting::kMomentsInputs,
                   "shadows = " + std::string(to_string(mode)) +
                       " needs the `moments` (shadow-moments), `atlas` and `shadowData` inputs",
                   mode_at, diagnostics);
    return;
  }
  for (const fg::PlanPass& producer : plan.passes) {
    if (producer.type != kShadowMomentsType || bound_index(producer, port::kMoments) != moments) {
      continue;
    }
    const auto technique = moment_storage_table().read(producer.params).technique;
    if (static_cast<int>(technique) != moment_technique_index(mode)) {
      add_pass_error(graph, pass, codes::lighting::kMomentsTechnique,
                     "shadows = " + std::string(to_string(mode)) + " but '" + producer.name +
                         "' stores " + std::string(to_string(technique)) +
                         " moments; use the same technique in both",
                     mode_at, diagnostics);
    }
  }
}

// What the shadow mode needs bound, checked by the compiler (validate) rather than when the
// executor prepares the pass (render), so that both accept the same graphs.
void check(const fg::PlanPass& pass, const TiledLightingParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const ShadowMode mode = TiledLightingPass::mode_of(pass.type, params);
  const std::string mode_at = pass.type == TiledLightingPass::kType ? "/params/shadows" : "/type";
  const auto error = [&](const char* code, const std::string& message, const std::string& at) {
    add_pass_error(graph, pass, code, message, at, diagnostics);
  };
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* shadow_data = bound_resource(pass, plan, port::kShadowData);
  if ((atlas == nullptr) != (shadow_data == nullptr)) {
    error(codes::lighting::kAtlasWithoutData, "bind both `atlas` and `shadowData`, or neither",
          atlas == nullptr ? "/in/shadowData" : "/in/atlas");
  }
  const bool needs_atlas =
      mode == ShadowMode::hard || mode == ShadowMode::pcf || mode == ShadowMode::pcss;
  if (needs_atlas && (atlas == nullptr || shadow_data == nullptr)) {
    error(
        codes::lighting::kModeNeedsAtlas,
        "shadows = " + std::string(to_string(mode)) + " needs the `atlas` and `shadowData` inputs",
        mode_at);
  }
  if (atlas != nullptr && shadow_data != nullptr && mode != ShadowMode::none &&
      shadow_data->buffer_size < shadow_data_bytes(atlas->layers)) {
    error(codes::lighting::kShadowDataTooSmall,
          "`shadowData` ('" + shadow_data->name + "') holds " +
              std::to_string(shadow_data->buffer_size) + " bytes; an atlas of " +
              std::to_string(atlas->layers) + " layers needs " +
              std::to_string(shadow_data_bytes(atlas->layers)),
          "/in/shadowData");
  }
  if (is_moment_mode(mode)) {
    check_moments(pass, plan, graph, mode, mode_at, diagnostics);
    return;
  }
  if (mode == ShadowMode::penumbra_map) {
    if (bound_resource(pass, plan, port::kPenumbraMap) == nullptr || atlas == nullptr ||
        shadow_data == nullptr) {
      error(codes::lighting::kPenumbraMapInputs,
            "shadows = penumbra-map needs the `penumbraMap` (penumbra-wedges), `atlas` and "
            "`shadowData` inputs",
            mode_at);
    }
    return;
  }
  if (mode == ShadowMode::sdf) {
    const bool field = bound_resource(pass, plan, port::kSdf) != nullptr;
    if (!field || bound_resource(pass, plan, port::kSdfInfo) == nullptr) {
      error(codes::lighting::kSdfInputs,
            std::string("shadows = sdf needs the `sdf` and `sdfInfo` inputs (scene-sdf); `") +
                (field ? "sdfInfo" : "sdf") + "` is not bound",
            mode_at);
    }
    return;
  }
  if (mode != ShadowMode::layered) return;
  const auto* table = bound_resource(pass, plan, port::kLayerTable);
  const auto* shadow = bound_resource(pass, plan, port::kShadow);
  if (table == nullptr || shadow == nullptr) {
    error(codes::lighting::kLayeredInputs,
          std::string("shadows = layered needs the `layerTable` and `shadow` inputs; `") +
              (table == nullptr ? "layerTable" : "shadow") + "` is not bound",
          mode_at);
  }
  if (table != nullptr && table->buffer_size < kLayerTableBytes) {
    error(codes::lighting::kLayerTableTooSmall,
          "`layerTable` ('" + table->name + "') holds " + std::to_string(table->buffer_size) +
              " bytes; it must hold at least " + std::to_string(kLayerTableBytes),
          "/in/layerTable");
  }
}

}  // namespace

fg::PassDesc TiledLightingPass::describe() {
  fg::PassDesc desc;
  desc.type = kType;
  desc.description =
      "Tiled deferred shading (compute, 16x16 tiles with depth bounds and per-tile light "
      "lists) of every scene point light, with an optional shadow term per light.";
  desc.ports = lighting_ports();
  for (auto& port : atlas_ports(true)) desc.ports.push_back(std::move(port));
  desc.ports.push_back(
      {.name = port::kLayerTable,
       .kind = ResourceKind::buffer,
       .access = Access::storage_read,
       .stage = Stage::compute,
       .optional = true,
       .description =
           "Light -> shadow layer table (light-layering, interface/shared/layer_table.h); "
           "shadows = layered."});
  desc.ports.push_back(
      compute_array_input(port::kShadow, {Format::rgba16f, Format::rgba8, Format::rgba32f}, 1, 8,
                          "Blurred layered shadow (1 lit .. 0 shadowed): layer L in channel L%4 of "
                          "array layer L/4; shadows = layered.",
                          true));
  // The upsample steps through whole blocks of pixels per shadow texel.
  desc.ports.back().size_of = fg::SizeContract{port::kDepth, fg::SizeRelation::fraction};
  desc.ports.push_back(
      compute_array_input(port::kColour, {Format::rgba32ui}, 1, 8,
                          "Layered shadow colour of translucent occluders, rgba8 packed "
                          "r<<24|g<<16|b<<8|a per channel like `shadow`; shadows = layered.",
                          true));
  desc.ports.push_back(compute_array_input(
      port::kMoments,
      {Format::rgba32f, Format::rgba16f, Format::rg32f, Format::rg16f, Format::rg32ui}, 1, 0,
      "Filtered moments of every shadow face (shadow-moments); shadows = vsm | evsm2 | evsm4 "
      "| msm | vssm.",
      true));
  desc.ports.push_back(compute_array_input(port::kSdf, {Format::r16f, Format::r32f}, 1, 0,
                                           "The scene's signed distance field (scene-sdf); "
                                           "shadows = sdf.",
                                           true));
  desc.ports.push_back(compute_array_input(port::kPenumbraMap, {Format::rg16f, Format::rg32f}, 1, 0,
                                           "Penumbra map of every shadow face "
                                           "(penumbra-wedges); shadows = penumbra-map.",
                                           true));
  desc.ports.push_back(compute_array_input(port::kPeeled, {Format::d32f}, 1, 0,
                                           "Third depth layer of every shadow face "
                                           "(penumbra-wedges, peelingDepth 3); shadows = "
                                           "penumbra-map.",
                                           true));
  desc.ports.push_back(compute_buffer_input(port::kSdfInfo,
                                            "Where the field lies (scene-sdf); "
                                            "shadows = sdf."));
  desc.ports.back().optional = true;
  desc.ports.push_back(
      {.name = port::kHardShadow,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::r32ui},
       .optional = true,
       .size_group = "screen",
       .description =
           "Hard-shadow bits (layered-penumbra's `hardShadow`); shadows = "
           "layered: where a layer changes by more than 0.35 between the low-resolution "
           "texels of the pixel's surface (a shadow edge sharper than the layers hold, as "
           "at contact), the upsample also weighs each texel by its agreement with the "
           "pixel's own hard bit."});
  desc.params = param_table(kType).descs();
  desc.check = param_table(kType).check(&check);
  return desc;
}

fg::PassDesc TiledLightingPass::describe_hard() {
  fg::PassDesc desc;
  desc.type = kHardType;
  desc.description = "Baseline: tiled lighting with one hard shadow-map test per light.";
  desc.ports = lighting_ports();
  for (auto& port : atlas_ports(false)) desc.ports.push_back(std::move(port));
  desc.params = param_table(kHardType).descs();
  desc.check = param_table(kHardType).check(&check);
  return desc;
}

fg::PassDesc TiledLightingPass::describe_pcf() {
  fg::PassDesc desc = describe_hard();
  desc.type = kPcfType;
  desc.description = "Baseline: tiled lighting with percentage-closer filtering (box kernel).";
  desc.params = param_table(kPcfType).descs();
  desc.check = param_table(kPcfType).check(&check);
  return desc;
}

fg::PassDesc TiledLightingPass::describe_pcss() {
  fg::PassDesc desc = describe_hard();
  desc.type = kPcssType;
  desc.description = "Baseline: tiled lighting with PCSS (blocker search, penumbra estimate, PCF).";
  desc.params = param_table(kPcssType).descs();
  desc.check = param_table(kPcssType).check(&check);
  return desc;
}

const fg::ParamTable<TiledLightingParams>& TiledLightingPass::param_table(std::string_view type) {
  static const Table kTiled = tiled_table();
  static const Table kHard = lighting_table();
  static const Table kPcf = pcf_table();
  static const Table kPcss = pcss_table();
  if (type == kHardType) return kHard;
  if (type == kPcfType) return kPcf;
  if (type == kPcssType) return kPcss;
  return kTiled;
}

}  // namespace antumbra::passes
