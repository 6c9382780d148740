// Which device features Antumbra enables, which of them a pass chooses a path by, and the
// check of a host's device (docs/integration.md, "The host's device"). One list serves
// the own device, device_setup() and the host check, so they cannot disagree.
#include <array>
#include <string>
#include <vector>

#include "device_selection.hpp"

namespace antumbra::gpu {
namespace {

using FeatureRef = VkBool32& (*)(FeatureChain&);
struct NamedFeature {
  const char* name;
  FeatureRef get;
};

VkBool32 value(const FeatureChain& chain, FeatureRef get) {
  // The accessors take a mutable chain so that one table serves reading and writing.
  return get(const_cast<FeatureChain&>(chain));
}

#define ANTUMBRA_FEATURE(block, field)                                  \
  NamedFeature {                                                        \
#field, [](FeatureChain & c) -> VkBool32& { return c.block.field; } \
  }

// Enabled whenever offered, and read by no path choice: the shaders and pipelines assume
// them where the device has them, so a host's device must enable them too when offered.
const std::array kUsedWhenOffered = {
    ANTUMBRA_FEATURE(features2.features, independentBlend),
    ANTUMBRA_FEATURE(features2.features, depthClamp),
    ANTUMBRA_FEATURE(features2.features, fragmentStoresAndAtomics),
    ANTUMBRA_FEATURE(features2.features, vertexPipelineStoresAndAtomics),
    ANTUMBRA_FEATURE(features2.features, drawIndirectFirstInstance),
    ANTUMBRA_FEATURE(features2.features, shaderImageGatherExtended),
    ANTUMBRA_FEATURE(v12, shaderOutputViewportIndex),
    ANTUMBRA_FEATURE(v12, drawIndirectCount),
    ANTUMBRA_FEATURE(v12, samplerFilterMinmax),
};

// Optional: a pass takes another path without them (DeviceFeatures).
const std::array kOptional = {
    ANTUMBRA_FEATURE(features2.features, samplerAnisotropy),
    ANTUMBRA_FEATURE(features2.features, shaderStorageImageWriteWithoutFormat),
    ANTUMBRA_FEATURE(features2.features, shaderStorageImageReadWithoutFormat),
    ANTUMBRA_FEATURE(features2.features, geometryShader),
    ANTUMBRA_FEATURE(features2.features, imageCubeArray),
    ANTUMBRA_FEATURE(features2.features, fillModeNonSolid),
    ANTUMBRA_FEATURE(features2.features, multiDrawIndirect),
    ANTUMBRA_FEATURE(features2.features, shaderClipDistance),
    ANTUMBRA_FEATURE(v11, multiview),
    ANTUMBRA_FEATURE(v11, shaderDrawParameters),
    ANTUMBRA_FEATURE(v12, hostQueryReset),
    ANTUMBRA_FEATURE(v12, shaderOutputLayer),
    ANTUMBRA_FEATURE(v12, scalarBlockLayout),
};

// Optional, all or none: 64-bit atomics need 64-bit integers in the shader; descriptor
// indexing is the four together (and variable counts where offered).
const std::array kInt64Atomics = {ANTUMBRA_FEATURE(features2.features, shaderInt64),
                                  ANTUMBRA_FEATURE(v12, shaderBufferInt64Atomics)};
const std::array kDescriptorIndexing = {
    ANTUMBRA_FEATURE(v12, descriptorIndexing), ANTUMBRA_FEATURE(v12, runtimeDescriptorArray),
    ANTUMBRA_FEATURE(v12, descriptorBindingPartiallyBound),
    ANTUMBRA_FEATURE(v12, shaderSampledImageArrayNonUniformIndexing)};

#undef ANTUMBRA_FEATURE

template <std::size_t kN>
bool all_of(const FeatureChain& chain, const std::array<NamedFeature, kN>& group) {
  for (const auto& f : group) {
    if (value(chain, f.get) != VK_TRUE) return false;
  }
  return true;
}

template <std::size_t kN>
void take_group(const FeatureChain& supported, FeatureChain& wanted,
                const std::array<NamedFeature, kN>& group) {
  if (!all_of(supported, group)) return;
  for (const auto& f : group) f.get(wanted) = VK_TRUE;
}

bool on(const FeatureChain& chain, const char* name) {
  for (const auto& f : kOptional) {
    if (std::string(f.name) == name) return value(chain, f.get) == VK_TRUE;
  }
  return false;
}

// Copies a feature struct's fields, keeping the target's own sType and pNext.
template <class T>
void copy_fields(const void* from, T& to) {
  void* next = to.pNext;
  to = *static_cast<const T*>(from);
  to.pNext = next;
}

}  // namespace

void want_features(const FeatureChain& supported, FeatureChain& wanted) {
  const bool core13 = wanted.v12.pNext == &wanted.v13;
  // Required (checked during selection). maintenance4's commands
  // (vkGetDeviceImageMemoryRequirements, for aliasing) come with 1.3 or the extension;
  // its feature bit only adds guarantees, so it is taken where offered.
  if (core13) {
    wanted.v13.dynamicRendering = VK_TRUE;
    wanted.v13.synchronization2 = VK_TRUE;
    wanted.v13.maintenance4 = supported.v13.maintenance4;
  } else {
    wanted.dynamic_rendering.dynamicRendering = VK_TRUE;
    wanted.synchronization2.synchronization2 = VK_TRUE;
    wanted.maintenance4.maintenance4 = supported.maintenance4.maintenance4;
  }
  wanted.v12.timelineSemaphore = VK_TRUE;
  for (const auto& f : kUsedWhenOffered) f.get(wanted) = value(supported, f.get);
  for (const auto& f : kOptional) f.get(wanted) = value(supported, f.get);
  take_group(supported, wanted, kInt64Atomics);
  take_group(supported, wanted, kDescriptorIndexing);
  if (all_of(supported, kDescriptorIndexing)) {
    wanted.v12.descriptorBindingVariableDescriptorCount =
        supported.v12.descriptorBindingVariableDescriptorCount;
  }
}

DeviceFeatures enabled_features(const FeatureChain& enabled) {
  DeviceFeatures f;
  f.sampler_anisotropy = on(enabled, "samplerAnisotropy");
  f.storage_image_write_without_format = on(enabled, "shaderStorageImageWriteWithoutFormat");
  f.storage_image_read_without_format = on(enabled, "shaderStorageImageReadWithoutFormat");
  f.geometry_shader = on(enabled, "geometryShader");
  f.image_cube_array = on(enabled, "imageCubeArray");
  f.fill_mode_non_solid = on(enabled, "fillModeNonSolid");
  f.multi_draw_indirect = on(enabled, "multiDrawIndirect");
  f.shader_clip_distance = on(enabled, "shaderClipDistance");
  f.multiview = on(enabled, "multiview");
  f.shader_draw_parameters = on(enabled, "shaderDrawParameters");
  f.host_query_reset = on(enabled, "hostQueryReset");
  f.shader_output_layer = on(enabled, "shaderOutputLayer");
  f.scalar_block_layout = on(enabled, "scalarBlockLayout");
  f.int64_buffer_atomics = all_of(enabled, kInt64Atomics);
  f.descriptor_indexing = all_of(enabled, kDescriptorIndexing);
  return f;
}

void read_host_chain(const void* chain, FeatureChain& out) {
  for (auto* s = static_cast<const VkBaseInStructure*>(chain); s != nullptr; s = s->pNext) {
    switch (s->sType) {
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2:
        out.features2.features = reinterpret_cast<const VkPhysicalDeviceFeatures2*>(s)->features;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES:
        copy_fields(s, out.v11);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES:
        copy_fields(s, out.v12);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES:
        copy_fields(s, out.v13);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR:
        copy_fields(s, out.dynamic_rendering);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES_KHR:
        copy_fields(s, out.synchronization2);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES_KHR:
        copy_fields(s, out.maintenance4);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES:
        out.v12.timelineSemaphore |=
            reinterpret_cast<const VkPhysicalDeviceTimelineSemaphoreFeatures*>(s)
                ->timelineSemaphore;
        break;
      default:
        break;  // a struct Antumbra reads nothing from
    }
  }
}

std::string missing_host_features(const FeatureChain& supported, const FeatureChain& enabled,
                                  bool core13) {
  std::vector<std::string> missing;
  const bool dynamic = enabled.v13.dynamicRendering == VK_TRUE ||
                       enabled.dynamic_rendering.dynamicRendering == VK_TRUE;
  const bool sync2 = enabled.v13.synchronization2 == VK_TRUE ||
                     enabled.synchronization2.synchronization2 == VK_TRUE;
  const char* block = core13 ? "VkPhysicalDeviceVulkan13Features" : "the KHR extension's struct";
  if (!dynamic) missing.push_back(std::string("dynamicRendering (") + block + ")");
  if (!sync2) missing.push_back(std::string("synchronization2 (") + block + ")");
  if (enabled.v12.timelineSemaphore != VK_TRUE) {
    missing.emplace_back("timelineSemaphore (VkPhysicalDeviceVulkan12Features)");
  }
  for (const auto& f : kUsedWhenOffered) {
    if (value(supported, f.get) == VK_TRUE && value(enabled, f.get) != VK_TRUE) {
      missing.push_back(std::string(f.name) + " (the device offers it and the shaders use it)");
    }
  }
  std::string text;
  for (std::size_t i = 0; i < missing.size(); ++i) text += (i ? ", " : "") + missing[i];
  return text;
}

}  // namespace antumbra::gpu
