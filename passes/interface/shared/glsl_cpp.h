// The prelude of every header in passes/interface/shared: those headers are valid GLSL and
// C++ at once, so a struct, constant or layout shared by the shaders and the passes that
// fill their buffers is written once (docs/architecture.md, "One source for CPU and GPU").
//
// In C++ the GLSL type names map to GLM's inside namespace antumbra::shared, constants are
// inline constexpr, and ANTUMBRA_INIT(value) gives a member its C++ default (GLSL has no
// member initialisers). Only vec4, uvec4, mat4 and scalars are used in buffers, so std140,
// std430 and the C++ layout agree without padding (static_asserts in the C++ headers).
#ifndef ANTUMBRA_GLSL_CPP_H
#define ANTUMBRA_GLSL_CPP_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/glm.hpp>

namespace antumbra::shared {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
}  // namespace antumbra::shared

#define ANTUMBRA_SHARED_BEGIN namespace antumbra::shared {
#define ANTUMBRA_SHARED_END }
#define ANTUMBRA_INIT(value) = value
#else
#define ANTUMBRA_SHARED_BEGIN
#define ANTUMBRA_SHARED_END
#define ANTUMBRA_INIT(value)
#endif

#endif
