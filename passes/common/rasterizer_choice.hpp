#pragma once
// `rasterizer: "auto"` (the default of point-shadow-atlas and gbuffer), Vulkan-free:
// which rasteriser draws on a given device, from what we measured (docs/technique.md,
// "Which rasteriser"). The choice is made when the graph compiles (PassDesc::resolve),
// since the two write their images differently (attachments, storage images or copies)
// and the graph's barriers follow; RenderSession compiles for its device and the note
// (FG076) says why. Compiled for no device (validate, plan), "auto" follows the format.
// Shared by both passes, so it lives here rather than in either pass's folder.

#include <cstdint>
#include <string>
#include <string_view>
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

// The rasteriser a device draws shadow faces fastest with, for an atlas that allows both.
RasterizerPick pick_rasterizer(const fg::DeviceTraits& device);

// The shadow atlas's "auto": constrained by the atlas's format (d16: hardware; r32f:
// compute; d32f without a device: hardware), else the device's pick. `reason` is the
// whole explanation (with the device's name where the device decided).
RasterizerPick choose_atlas_rasterizer(fg::Format atlas, const fg::DeviceTraits* device);

// The G-buffer's "auto": compute (a visibility buffer) on GPUs with few raster units and
// a d32f depth, else hardware (docs/technique.md, "Compute G-buffer").
RasterizerPick choose_gbuffer_rasterizer(fg::Format depth, const fg::DeviceTraits* device);

// The format of the resource the graph binds to `pass`'s output `port` (d32f when unbound:
// the port's first format, which both passes default to).
fg::Format bound_output_format(const fg::GraphDesc& graph, const fg::PassInstanceDesc& pass,
                               std::string_view port);

// The FG076 line: what "auto" became for `pass`, and why.
std::string auto_choice_line(const fg::PassInstanceDesc& pass, const RasterizerPick& pick);

// The resolve step both passes share: "auto" becomes what `choose` picks for the format
// of the pass's output `port` and the device, and the FG076 line says why; any other value
// is left to the parameter check.
template <class Rasterizer>
std::vector<std::string> resolve_auto_rasterizer(
    Rasterizer& rasterizer, const fg::PassInstanceDesc& pass, const fg::GraphDesc& graph,
    fg::PortId port, RasterizerPick (*choose)(fg::Format, const fg::DeviceTraits*),
    const fg::DeviceTraits* device) {
  if (rasterizer != Rasterizer::automatic) return {};
  const RasterizerPick pick = choose(bound_output_format(graph, pass, port.name()), device);
  rasterizer = pick.compute ? Rasterizer::compute : Rasterizer::hardware;
  return {auto_choice_line(pass, pick)};
}

}  // namespace antumbra::passes
