// The prelude of every header in passes/interface/shared: those headers are valid GLSL and
// C++ at once, so a struct, constant or layout shared by the shaders and the passes that
// fill their buffers is written once (docs/architecture.md, "One source for CPU and GPU").
//
// In C++ the GLSL type names map to GLM's inside namespace antumbra::shared, constants are
// inline constexpr, and ANTUMBRA_INIT(value) gives a member its C++ default (GLSL has no
// member initialisers). Only vec4, uvec4, mat4 and scalars are used in buffers, so std140,
// std430 and the C++ layout agree without padding (static_asserts in the C++ headers).
//
// Each pass's *_interface.h (beside its shaders) writes its push-constant block and its
// descriptor binding numbers once with these, so the shader, the C++ set layout and the
// descriptor writes cannot disagree (docs/architecture.md, "One source for CPU and GPU"):
//   ANTUMBRA_BINDING(kTonemapHdr, 0)
//   ANTUMBRA_PUSH_CONSTANTS(TonemapPush) {
//     float exposure;
//   };
// The macro names only the block's head, so the body stays ordinary braces that
// clang-format indents. The runtime SPIR-V check (check_shader_interface) still compares
// both sides, which catches a shader that declares its own block or binding instead.
#ifndef ANTUMBRA_GLSL_CPP_H
#define ANTUMBRA_GLSL_CPP_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/glm.hpp>

namespace antumbra::shared {
using uint = std::uint32_t;
// Push-constant blocks are std430, which aligns a two-component vector to 8 bytes where
// GLM aligns it to 4; the attribute gives C++ the std430 offsets, so a float after a
// vec2/uvec2 lands where the shader reads it. (A typedef attribute is dropped when the
// type is a template argument, with a warning: keep these out of templates.)
typedef glm::vec2 vec2 __attribute__((aligned(8)));
typedef glm::uvec2 uvec2 __attribute__((aligned(8)));
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
}  // namespace antumbra::shared

#define ANTUMBRA_SHARED_BEGIN namespace antumbra::shared {
#define ANTUMBRA_SHARED_END }
#define ANTUMBRA_INIT(value) = value
// C++: a plain struct the pass fills and hands to vkCmdPushConstants (sizeof = the
// block's size, compared with the shader's by check_shader_interface).
#define ANTUMBRA_PUSH_CONSTANTS(name) struct name
// C++: the number the set-layout builder and the descriptor writes use.
#define ANTUMBRA_BINDING(name, number) inline constexpr std::uint32_t name = number;
#else
#define ANTUMBRA_SHARED_BEGIN
#define ANTUMBRA_SHARED_END
#define ANTUMBRA_INIT(value)
// GLSL: the block has no instance name, so the shader reads its members by their bare
// names. The struct name is the block name (one push-constant block per stage).
#define ANTUMBRA_PUSH_CONSTANTS(name) layout(push_constant) uniform name
// GLSL: a constant integral expression, which layout(binding = ...) accepts.
#define ANTUMBRA_BINDING(name, number) const uint name = number;
#endif

#endif
