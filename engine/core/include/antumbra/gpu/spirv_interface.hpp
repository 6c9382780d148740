#pragma once
// What a SPIR-V module expects from its pipeline: the descriptor bindings it declares
// (set, binding, descriptor type), the size of its push-constant block and, for a vertex
// shader, the inputs its vertex attributes must feed. Read straight from the module's
// decorations and types, so the check of a pass's C++ declaration against its shaders
// (passes/common/pass_support.hpp) needs no reflection library.

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

// The numeric type of a vertex input's components: a vertex attribute's format must give
// the same one (Vulkan reads the attribute as float, signed or unsigned integer).
enum class SpirvScalar { float32, sint32, uint32, other };

// A vertex-shader input with a Location (built-ins such as gl_VertexIndex have none).
struct SpirvVertexInput {
  std::uint32_t location = 0;
  std::uint32_t components = 0;  // 1 scalar, 2-4 vector; 0 neither (a matrix or array)
  SpirvScalar scalar = SpirvScalar::other;
  std::string name;
};

struct SpirvInterface {
  std::vector<SpirvBinding> bindings;           // in the order the module declares them
  std::uint32_t push_constant_bytes = 0;        // 0: no push-constant block
  std::vector<SpirvVertexInput> vertex_inputs;  // vertex shaders only; by location
};

// Throws std::runtime_error for a module that is not SPIR-V.
SpirvInterface reflect_spirv(std::span<const std::uint32_t> words);

// "combined image sampler", "storage buffer", ...
std::string descriptor_type_name(VkDescriptorType type);

// The GLSL type of `components` values of `scalar`: "float", "uvec3", "ivec2", ...; for
// an input reflect_spirv does not describe (other, 0), "non-32-bit or composite type".
std::string glsl_type_name(SpirvScalar scalar, std::uint32_t components);

}  // namespace antumbra::gpu
