#include "antumbra/fgvk/vk_sync.hpp"

#include <string>

namespace antumbra::fgvk {
namespace {

std::string hex(std::uint64_t value) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  do {
    out.insert(out.begin(), kDigits[value % 16]);
    value /= 16;
  } while (value != 0);
  return "0x" + out;
}

// The raw masks and layout: a mismatch is a programming error, read beside the
// Vulkan headers.
std::string describe(const SyncState& state) {
  return "stages " + hex(state.stages) + ", access " + hex(state.access) + ", layout " +
         std::to_string(static_cast<int>(state.layout));
}

VkPipelineStageFlags2 shader_stages(fg::Stage stage) {
  switch (stage) {
    case fg::Stage::vertex:
      return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
    case fg::Stage::fragment:
      return VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    case fg::Stage::compute:
      return VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    case fg::Stage::graphics:
      return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    case fg::Stage::transfer:
      return VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    case fg::Stage::host:
      return VK_PIPELINE_STAGE_2_HOST_BIT;
    case fg::Stage::shader:
      return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    case fg::Stage::none:
      break;
  }
  return VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
}

}  // namespace

SyncState sync_state(fg::Access access, fg::Stage stage, bool depth) {
  using fg::Access;
  switch (access) {
    case Access::none:
      return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::sampled:
      return {shader_stages(stage), VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                    : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case Access::storage_read:
      return {shader_stages(stage), VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case Access::storage_write:
      return {shader_stages(stage), VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case Access::storage_read_write:
      return {shader_stages(stage),
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
              VK_IMAGE_LAYOUT_GENERAL};
    case Access::color_attachment:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    case Access::depth_attachment:
      return {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                  VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL};
    case Access::depth_read:
      return {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                  VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
              VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL};
    case Access::uniform_read:
      return {shader_stages(stage), VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::transfer_src:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    case Access::transfer_dst:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
  }
  return {};
}

SyncState barrier_source(const fg::PlanBarrier& barrier, bool depth) {
  if (barrier.source == fg::BarrierSource::aliased_memory) {
    // Earlier users of the memory are several resources, some in the previous frame,
    // still in flight: wait for every earlier command and write, not for one of them.
    return {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
            VK_IMAGE_LAYOUT_UNDEFINED};
  }
  SyncState source = sync_state(barrier.from, barrier.from_stage, depth);
  if (barrier.discard) source.layout = VK_IMAGE_LAYOUT_UNDEFINED;
  return source;
}

std::string source_mismatch(const fg::PlanBarrier& barrier, const SyncState& tracked, bool depth) {
  // Aliased memory's source is the heap's history, not the resource's own state.
  if (barrier.source == fg::BarrierSource::aliased_memory) return {};
  const SyncState planned = sync_state(barrier.from, barrier.from_stage, depth);
  if (planned.stages == tracked.stages && planned.access == tracked.access &&
      planned.layout == tracked.layout) {
    return {};
  }
  return "the plan's source (" + std::string(fg::to_string(barrier.source)) + ": " +
         std::string(fg::to_string(barrier.from)) + " at " +
         std::string(fg::to_string(barrier.from_stage)) + ", " + describe(planned) +
         ") is not the executor's tracked state (" + describe(tracked) + ")";
}

VkFormat to_vk_format(fg::Format format) {
  using fg::Format;
  switch (format) {
    case Format::undefined:
      return VK_FORMAT_UNDEFINED;
    case Format::r8:
      return VK_FORMAT_R8_UNORM;
    case Format::rg8:
      return VK_FORMAT_R8G8_UNORM;
    case Format::rgba8:
      return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::rgba8_srgb:
      return VK_FORMAT_R8G8B8A8_SRGB;
    case Format::bgra8:
      return VK_FORMAT_B8G8R8A8_UNORM;
    case Format::bgra8_srgb:
      return VK_FORMAT_B8G8R8A8_SRGB;
    case Format::r16f:
      return VK_FORMAT_R16_SFLOAT;
    case Format::rg16f:
      return VK_FORMAT_R16G16_SFLOAT;
    case Format::rgba16f:
      return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::r32f:
      return VK_FORMAT_R32_SFLOAT;
    case Format::rg32f:
      return VK_FORMAT_R32G32_SFLOAT;
    case Format::rgba32f:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::r32ui:
      return VK_FORMAT_R32_UINT;
    case Format::rg32ui:
      return VK_FORMAT_R32G32_UINT;
    case Format::rgba32ui:
      return VK_FORMAT_R32G32B32A32_UINT;
    case Format::r11g11b10f:
      return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
    case Format::d16:
      return VK_FORMAT_D16_UNORM;
    case Format::d32f:
      return VK_FORMAT_D32_SFLOAT;
    case Format::d24s8:
      return VK_FORMAT_D24_UNORM_S8_UINT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkImageAspectFlags aspect_of(fg::Format format) {
  // A barrier covers every aspect the image has: depth and stencil together for d24s8
  // (VUID-VkImageMemoryBarrier2-image-03320), though views sample its depth alone.
  if (format == fg::Format::d24s8) return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  return fg::is_depth_format(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImageUsageFlags image_usage(const fg::PlanResource& resource) {
  // Every image can be copied out, so any resource can be written with --output.
  VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  for (const fg::Access access : resource.usages) {
    switch (access) {
      case fg::Access::sampled:
        usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
        // Sampled depth waits in DEPTH_STENCIL_READ_ONLY_OPTIMAL (sync_state), which needs
        // attachment usage even when only copies write it (a compute-rasterised atlas).
        if (fg::is_depth_format(resource.format)) {
          usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        }
        break;
      case fg::Access::storage_read:
      case fg::Access::storage_write:
      case fg::Access::storage_read_write:
        usage |= VK_IMAGE_USAGE_STORAGE_BIT;
        break;
      case fg::Access::color_attachment:
        usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        break;
      case fg::Access::depth_attachment:
      case fg::Access::depth_read:
        usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        break;
      case fg::Access::transfer_dst:
        usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        break;
      default:
        break;
    }
  }
  return usage;
}

VkBufferUsageFlags buffer_usage(const fg::PlanResource& resource) {
  VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  for (const fg::Access access : resource.usages) {
    switch (access) {
      case fg::Access::uniform_read:
        usage |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        break;
      case fg::Access::storage_read:
      case fg::Access::storage_write:
      case fg::Access::storage_read_write:
      case fg::Access::sampled:
        usage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        break;
      default:
        break;
    }
  }
  return usage;
}

}  // namespace antumbra::fgvk
