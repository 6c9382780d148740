#pragma once
// Reflection shared by every compute lighting pass (tiled-lighting and its shadow
// baselines, shadow-reference, deferred-lighting): the same G-buffer inputs, HDR output and
// lighting parameters, so the variants stay comparable and a graph can swap one for another.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"

namespace antumbra::passes {

// An image input read through a sampler by a compute shader: the most common port of
// the screen-space passes (G-buffer depth and normals above all).
fg::PortDesc compute_input(fg::PortId name, std::vector<fg::Format> formats,
                           std::string description, std::string size_group = {});

// A layered image (texture array: shadow faces, layered screen images) sampled in
// compute, with at least `min_layers` and at most `max_layers` (0: any number) layers.
fg::PortDesc compute_array_input(fg::PortId name, std::vector<fg::Format> formats,
                                 std::uint32_t min_layers, std::uint32_t max_layers,
                                 std::string description, bool optional = false);
// A buffer read as a storage buffer in compute (shadowData, layerTable).
fg::PortDesc compute_buffer_input(fg::PortId name, std::string description);
// The optional `pageTables` input of a pass that reads the shadow atlas: bound to a paged
// atlas's tables (point-shadow-atlas's pagePool), its lookups go through them
// (interface/shared/page_tables.h); unbound, they are compiled out.
fg::PortDesc page_tables_input();

// The G-buffer's optional emission + occlusion image (gbuffer's `emissive`), sampled at
// `stage`: every lighting pass adds the emission unshadowed and scales its ambient term
// by the occlusion (docs/technique.md, "The G-buffer").
fg::PortDesc emissive_input(fg::Stage stage);

// depth, normal, albedo (and optionally emissive) sampled in compute; hdr written as a
// storage image, last.
std::vector<fg::PortDesc> lighting_ports();
// exposure, ambient, specular: the lighting terms every lighting pass shares.
struct LightingParams {
  float exposure = 1.0f;
  float ambient = 1.0f;
  float specular = 0.25f;
};
const fg::ParamTable<LightingParams>& lighting_param_table();

}  // namespace antumbra::passes
