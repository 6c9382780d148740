#pragma once
// Small helpers every pass uses: shader loading with diagnostics, fullscreen draws.

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/hash.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/spirv_interface.hpp"
#include "common/frame_resources.hpp"
#include "common/lazy_pipeline.hpp"
#include "shared/workgroups.h"

namespace antumbra::passes {

// A compiled shader and what it expects from the pipeline layout (its SPIR-V's bindings
// and push-constant size), so the pass's C++ declaration can be checked against it.
struct Shader {
  gpu::ShaderModule module;
  gpu::SpirvInterface interface;
  std::string file;  // <folder>/<relative>, the file compiled, for messages
  operator VkShaderModule() const { return module; }  // NOLINT(google-explicit-constructor)
};

// Compiles <folder>/<relative> (GLSL) from the first of the context's shader folders that
// holds it (passes/, then a host's), and makes a shader module named after it. Adds the
// file and its includes to `dependencies`. Throws fgvk::PassError with the compiler's
// file:line diagnostics on failure, and with SH000 naming every folder searched when none
// holds the file. `code`, when given, is fed the SPIR-V (passes that keep caches across
// reloads tell by it whether they draw the same way).
Shader load_shader(fgvk::PrepareContext& context, std::string_view relative,
                   std::vector<std::string>& dependencies,
                   const std::vector<gpu::ShaderDefine>& defines = {},
                   gpu::Fnv1a64* code = nullptr);

// Binds the scene's two vertex streams (positions, attributes) and its index buffer.
void bind_scene_geometry(VkCommandBuffer cmd, const fgvk::FrameResources& frame);

// A pipeline builder with the scene's two vertex streams (binding 0 GpuVertex: position
// at location 0, normal 1, material 2; binding 1 GpuVertexAttributes: uv 3, tangent 4),
// all of them unless `locations` lists the ones the vertex shader reads.
gpu::GraphicsPipelineBuilder scene_vertex_attributes(std::vector<std::uint32_t> locations);

// Whether the frame has triangles of `draw_class` in `halves` (static, dynamic).
bool draws_class(const fgvk::FrameResources& frame, fgvk::DrawClass draw_class,
                 std::array<bool, 2> halves);

// The pipelines of `lazy` for the draw classes the frame has in `halves` (built now if
// they were not), VK_NULL_HANDLE for the others.
std::array<VkPipeline, fgvk::kDrawClasses> needed_pipelines(
    const fgvk::FrameResources& frame, std::span<LazyPipeline, fgvk::kDrawClasses> lazy,
    std::array<bool, 2> halves);

// Draws the scene's index ranges by draw class (frame_resources.hpp), each with its
// pipeline (VK_NULL_HANDLE: the class is skipped), for the static half, the dynamic half
// or both (`halves`). Vertex and index buffers and descriptors are the caller's.
void draw_by_class(VkCommandBuffer cmd, const fgvk::FrameResources& frame,
                   std::span<const VkPipeline, fgvk::kDrawClasses> pipelines,
                   std::array<bool, 2> halves, std::uint32_t instances = 1,
                   std::uint32_t first_instance = 0);

// Checks `shader` against the pass's C++ declaration: every binding it declares exists in
// `layout` with the same descriptor type, and its push-constant block is
// `push_constant_bytes` long (0: it has none). A mismatch throws fgvk::PassError with a
// diagnostic (SH010) at the shader's file naming the pass, the binding and both values.
void check_shader_interface(std::string_view pass, const Shader& shader,
                            const gpu::DescriptorSetLayoutBuilder& layout,
                            std::uint32_t push_constant_bytes);

// Checks a vertex shader's inputs against the pipeline's vertex attributes: every input
// location has an attribute whose format gives the same number of components of the same
// numeric type (float, int, uint). Fewer or more components are legal Vulkan (padded or
// dropped) but never meant here. Attributes the shader does not read are allowed (the
// shadow atlas's depth pass skips the normal). A mismatch throws fgvk::PassError with a
// diagnostic (SH010) at the shader's file naming the pass, the location and both types.
void check_vertex_inputs(std::string_view pass, const Shader& shader,
                         std::span<const VkVertexInputAttributeDescription> attributes);

// A compute pipeline with one push-descriptor set and a push-constant block; the shader
// is checked against both first (check_shader_interface).
struct ComputePipeline {
  gpu::DescriptorSetLayout set_layout;
  gpu::PipelineLayout layout;
  gpu::Pipeline pipeline;
};
ComputePipeline build_compute_pipeline(fgvk::PrepareContext& context, const Shader& shader,
                                       const gpu::DescriptorSetLayoutBuilder& bindings,
                                       std::uint32_t push_constant_bytes);

// Workgroups that cover `size` items in groups of `group`.
constexpr std::uint32_t group_count(std::uint32_t size, std::uint32_t group) {
  return (size + group - 1) / group;
}
// Dispatches square `group` x `group` workgroups over `extent` (workgroups.h sizes),
// `depth` deep.
void dispatch_groups(VkCommandBuffer cmd, VkExtent2D extent, std::uint32_t group,
                     std::uint32_t depth = 1);

// Sets a full-image viewport and scissor.
void set_viewport(VkCommandBuffer cmd, VkExtent2D extent);

}  // namespace antumbra::passes
