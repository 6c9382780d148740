#pragma once
// What a SPIR-V module expects from its pipeline layout: the descriptor bindings it
// declares (set, binding, descriptor type) and the size of its push-constant block. Read
// straight from the module's decorations and types, so the check of a pass's C++ layout
// against its shaders (passes/common/shader_interface.hpp) needs no reflection library.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

struct SpirvBinding {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  std::string name;  // the variable's or its block's name when the module keeps names
};

struct SpirvInterface {
  std::vector<SpirvBinding> bindings;     // in the order the module declares them
  std::uint32_t push_constant_bytes = 0;  // 0: no push-constant block
};

// Throws std::runtime_error for a module that is not SPIR-V.
SpirvInterface reflect_spirv(std::span<const std::uint32_t> words);

// "combined image sampler", "storage buffer", ...
std::string descriptor_type_name(VkDescriptorType type);

}  // namespace antumbra::gpu
