#include "rasterizer_choice.hpp"

#include <algorithm>
#include <array>

namespace antumbra::passes {
namespace {

constexpr std::uint32_t kVendorNvidia = 0x10DE;

}  // namespace

fg::Format bound_output_format(const fg::GraphDesc& graph, const fg::PassInstanceDesc& pass,
                               std::string_view port) {
  for (const auto& out : pass.outputs) {
    if (out.port != port) continue;
    const int r = graph.find_resource(out.resource);
    if (r >= 0) return graph.resources[static_cast<std::size_t>(r)].format;
  }
  return fg::Format::d32f;
}

bool has_few_raster_units(const fg::DeviceTraits& device) {
  constexpr std::array<std::string_view, 4> kHopper = {"H100", "H200", "H800", "GH200"};
  return device.vendor_id == kVendorNvidia &&
         std::any_of(kHopper.begin(), kHopper.end(), [&](std::string_view model) {
           return device.name.find(model) != std::string::npos;
         });
}

RasterizerPick pick_rasterizer(const fg::DeviceTraits& device) {
  if (device.cpu) {
    return {false,
            "a CPU device: llvmpipe's tiled rasteriser beats per-texel atomics (lavapipe, "
            "92 atrium faces of 1024^2 redrawn at 480x270: 272 ms hardware, 6800 ms compute)"};
  }
  if (has_few_raster_units(device)) {  // measured on an H200
    return {true,
            "an NVIDIA Hopper compute GPU, whose raster units are few (H200, 92 atrium faces "
            "of 1024^2 redrawn at 1080p: 19.6 ms hardware, 8.0 ms compute into d32f, 4.1 ms "
            "into r32f)"};
  }
  return {false,
          "not measured on this device; GPUs with their full raster units draw faces fastest "
          "in hardware. Compare with `antumbra bench --scenario moving/hard/1080p/16l` and set "
          "\"rasterizer\" to keep the faster"};
}

RasterizerPick choose_atlas_rasterizer(fg::Format atlas, const fg::DeviceTraits* device) {
  if (atlas == fg::Format::r32f) {
    return {true, "its atlas is r32f, which only the compute rasteriser writes"};
  }
  if (atlas == fg::Format::d16) {
    return {false, "its atlas is d16, which only the hardware rasteriser writes"};
  }
  if (device == nullptr) return {false, "no device to choose for (a depth atlas: hardware)"};
  RasterizerPick pick = pick_rasterizer(*device);
  pick.reason = device->name + " is " + pick.reason;
  return pick;
}

RasterizerPick choose_gbuffer_rasterizer(fg::Format depth, const fg::DeviceTraits* device) {
  if (depth != fg::Format::d32f) {
    return {false, "its depth is not d32f, which only the hardware rasteriser writes otherwise"};
  }
  if (device == nullptr) return {false, "no device to choose for"};
  if (device->cpu) {
    return {false, device->name +
                       " is a CPU device: llvmpipe rasterises faster than its compute shaders "
                       "(lavapipe, atrium at 480x270: 7 ms hardware, 48 ms compute)"};
  }
  if (has_few_raster_units(*device)) {
    return {true, device->name +
                      " is an NVIDIA Hopper compute GPU, whose raster units are few (H200, "
                      "1080p: atrium 1.81 ms hardware, 0.69 ms compute; 1.3 M-triangle district "
                      "3.66 ms, 0.95 ms)"};
  }
  return {false, device->name +
                     " was not measured; GPUs with their full raster units draw the G-buffer "
                     "fastest in hardware. Compare with `antumbra bench --scenario "
                     "compute/screen` (the /vis rows) and set \"rasterizer\" to keep the faster"};
}

std::string auto_choice_line(const fg::PassInstanceDesc& pass, const RasterizerPick& pick) {
  const char* chosen = pick.compute ? "compute" : "hardware";
  return "pass '" + pass.name + "': rasterizer \"auto\" draws with \"" + chosen +
         "\": " + pick.reason;
}

}  // namespace antumbra::passes
