#pragma once
// point-shadow-atlas's `rasterizer: "auto"` (the default), Vulkan-free: which rasteriser
// draws the faces on a given device, from what we measured (docs/technique.md, "Which
// rasteriser"). The choice is made when the graph compiles (PassDesc::resolve), since the
// two write the atlas differently (depth attachment, storage image or copies) and the
// graph's barriers follow; RenderSession compiles for its device and the note (FG076)
// says why. Compiled for no device (validate, plan), "auto" follows the atlas's format.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/fg/reflection.hpp"

namespace antumbra::passes {

struct RasterizerPick {
  bool compute = false;
  std::string reason;  // what we measured on such devices, or that we did not
};

// An NVIDIA Hopper compute GPU (H100, H200, H800, GH200): 2 of its TPCs run vertex and
// fragment shaders (NVIDIA's H100 documentation), so raster passes are slow there.
bool has_few_raster_units(const fg::DeviceTraits& device);

// The rasteriser a device draws faces fastest with, for an atlas that allows both (d32f).
RasterizerPick pick_rasterizer(const fg::DeviceTraits& device);

// gbuffer's PassDesc::resolve: "auto" (or absent) becomes "compute" (a visibility buffer)
// on GPUs with few raster units and a d32f depth, else "hardware", with the line that
// says why (docs/technique.md, "Compute G-buffer").
std::vector<std::string> resolve_gbuffer_rasterizer(fg::PassInstanceDesc& pass,
                                                    const fg::GraphDesc& graph,
                                                    const fg::DeviceTraits* device);

// PassDesc::resolve: replaces "auto" (or an absent "rasterizer") with the device's pick,
// constrained by the atlas's format (d16: hardware; r32f: compute; d32f without a device:
// hardware). Returns the line that says what and why.
std::vector<std::string> resolve_rasterizer(fg::PassInstanceDesc& pass, const fg::GraphDesc& graph,
                                            const fg::DeviceTraits* device);

}  // namespace antumbra::passes
