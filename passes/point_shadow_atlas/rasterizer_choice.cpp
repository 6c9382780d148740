#include "rasterizer_choice.hpp"

#include <algorithm>
#include <array>
#include <string_view>

namespace antumbra::passes {
namespace {

constexpr std::uint32_t kVendorNvidia = 0x10DE;

bool is_auto(const fg::Json& params) {
  const auto it = params.find("rasterizer");
  return it == params.end() || (it->is_string() && *it == "auto");
}

// The format of the resource bound to the pass's output `port` (d32f when unknown).
fg::Format output_format(const fg::GraphDesc& graph, const fg::PassInstanceDesc& pass,
                         std::string_view port) {
  for (const auto& out : pass.outputs) {
    if (out.port != port) continue;
    const int r = graph.find_resource(out.resource);
    if (r >= 0) return graph.resources[static_cast<std::size_t>(r)].format;
  }
  return fg::Format::d32f;
}

}  // namespace

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

std::vector<std::string> resolve_rasterizer(fg::PassInstanceDesc& pass, const fg::GraphDesc& graph,
                                            const fg::DeviceTraits* device) {
  // Anything but "auto" (or absent) is the parameter check's to judge.
  if (!pass.params.is_object() || !is_auto(pass.params)) return {};
  const fg::Format format = output_format(graph, pass, "atlas");
  std::string why;
  bool compute = false;
  if (format == fg::Format::r32f) {
    compute = true;
    why = "its atlas is r32f, which only the compute rasteriser writes";
  } else if (format == fg::Format::d16) {
    why = "its atlas is d16, which only the hardware rasteriser writes";
  } else if (device == nullptr) {
    why = "no device to choose for (a depth atlas: hardware)";
  } else {
    const RasterizerPick pick = pick_rasterizer(*device);
    compute = pick.compute;
    why = device->name + " is " + pick.reason;
  }
  const char* chosen = compute ? "compute" : "hardware";
  pass.params["rasterizer"] = chosen;
  return {"pass '" + pass.name + "': rasterizer \"auto\" draws with \"" + chosen + "\": " + why};
}

std::vector<std::string> resolve_gbuffer_rasterizer(fg::PassInstanceDesc& pass,
                                                    const fg::GraphDesc& graph,
                                                    const fg::DeviceTraits* device) {
  if (!pass.params.is_object() || !is_auto(pass.params)) return {};
  bool compute = false;
  std::string why;
  if (output_format(graph, pass, "depth") != fg::Format::d32f) {
    why = "its depth is not d32f, which only the hardware rasteriser writes otherwise";
  } else if (device == nullptr) {
    why = "no device to choose for";
  } else if (device->cpu) {
    why = device->name +
          " is a CPU device: llvmpipe rasterises faster than its compute shaders (lavapipe, "
          "atrium at 480x270: 7 ms hardware, 48 ms compute)";
  } else if (has_few_raster_units(*device)) {
    compute = true;
    why = device->name +
          " is an NVIDIA Hopper compute GPU, whose raster units are few (H200, 1080p: atrium "
          "1.81 ms hardware, 0.69 ms compute; 1.3 M-triangle district 3.66 ms, 0.95 ms)";
  } else {
    why = device->name +
          " was not measured; GPUs with their full raster units draw the G-buffer fastest in "
          "hardware. Compare with `antumbra bench --scenario compute/screen` (the /vis rows) "
          "and set \"rasterizer\" to keep the faster";
  }
  const char* chosen = compute ? "compute" : "hardware";
  pass.params["rasterizer"] = chosen;
  return {"pass '" + pass.name + "': rasterizer \"auto\" draws with \"" + chosen + "\": " + why};
}

}  // namespace antumbra::passes
