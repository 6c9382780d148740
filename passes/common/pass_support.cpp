#include "pass_support.hpp"

#include "frame_data.hpp"

#include <algorithm>
#include <array>
#include <filesystem>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/gpu/context.hpp"

namespace antumbra::passes {
namespace {

// The first of the shader folders that holds `relative` (docs/adding-a-pass.md, "A pass type
// from outside the tree"). None: an SH000 diagnostic at the pass's type in the graph (the
// session locates it in the file) naming the shader and every folder searched.
std::filesystem::path find_shader(const fgvk::PrepareContext& context, std::string_view relative) {
  std::string searched;
  for (const auto& dir : context.shader_dirs) {
    std::filesystem::path path = dir / relative;
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error)) return path;
    if (!searched.empty()) searched += ", ";
    searched += base::quote_name(dir.string());
  }
  const std::string message =
      "pass " + base::quote_name(context.pass.name) + " (type " +
      base::quote_name(context.pass.type) + "): shader " + base::quote_name(relative) +
      " is in none of the shader folders searched: " + (searched.empty() ? "none given" : searched);
  base::Diagnostics diagnostics;
  diagnostics.add({.code = codes::shader::kUnreadable,
                   .severity = base::Severity::error,
                   .message = message,
                   .pointer = context.pass.source_index >= 0
                                  ? "/passes/" + std::to_string(context.pass.source_index) + "/type"
                                  : ""});
  throw fgvk::PassError("shader " + std::string(relative) + " not found", diagnostics);
}

}  // namespace

Shader load_shader(fgvk::PrepareContext& context, std::string_view relative,
                   std::vector<std::string>& dependencies,
                   const std::vector<gpu::ShaderDefine>& defines, gpu::Fnv1a64* code) {
  gpu::ShaderRequest request;
  request.path = find_shader(context, relative);
  request.defines = defines;
  auto result = context.shaders.compile(request);
  if (!result.ok()) {
    throw fgvk::PassError("shader " + request.path.string() + " failed to compile",
                          result.diagnostics());
  }
  for (const auto& dep : result->dependencies) {
    const std::string file = dep.string();
    if (std::find(dependencies.begin(), dependencies.end(), file) == dependencies.end()) {
      dependencies.push_back(file);
    }
  }
  if (code != nullptr) {
    code->update(result->spirv.data(), result->spirv.size() * sizeof(std::uint32_t));
  }
  return {gpu::create_shader_module(context.gpu, result->spirv,
                                    context.pass.name + ":" + std::string(relative)),
          gpu::reflect_spirv(result->spirv), request.path.string()};
}

namespace {

[[noreturn]] void interface_error(std::string_view pass, const Shader& shader,
                                  const std::string& message) {
  base::Diagnostics diagnostics;
  diagnostics.add({.code = codes::shader::kInterfaceMismatch,
                   .severity = base::Severity::error,
                   .message = "pass '" + std::string(pass) + "', " + message,
                   .file = shader.file});
  throw fgvk::PassError("shader " + shader.file + " does not match its pass", diagnostics);
}

}  // namespace

void check_shader_interface(std::string_view pass, const Shader& shader,
                            const gpu::DescriptorSetLayoutBuilder& layout,
                            std::uint32_t push_constant_bytes) {
  for (const gpu::SpirvBinding& used : shader.interface.bindings) {
    const std::string what = shader.file + ": binding " + std::to_string(used.binding) +
                             (used.name.empty() ? "" : " ('" + used.name + "')");
    if (used.set != 0) {
      interface_error(
          pass, shader,
          what + " is in set " + std::to_string(used.set) + "; passes declare one set, set 0");
    }
    const auto& declared = layout.bindings();
    const auto it = std::find_if(declared.begin(), declared.end(),
                                 [&](const auto& b) { return b.binding == used.binding; });
    if (it == declared.end()) {
      interface_error(pass, shader,
                      what + " is a " + gpu::descriptor_type_name(used.type) +
                          " in the shader and missing from the C++ layout");
    }
    if (it->descriptorType != used.type) {
      interface_error(pass, shader,
                      what + " is a " + gpu::descriptor_type_name(used.type) +
                          " in the shader, a " + gpu::descriptor_type_name(it->descriptorType) +
                          " in the C++ layout");
    }
  }
  if (shader.interface.push_constant_bytes != push_constant_bytes) {
    interface_error(pass, shader,
                    shader.file + ": the push-constant block is " +
                        std::to_string(shader.interface.push_constant_bytes) +
                        " bytes in the shader, " + std::to_string(push_constant_bytes) + " in C++");
  }
}

namespace {

// The components and numeric type a vertex attribute of `format` feeds its input with
// (normalised formats read as float); components 0 for a format the table does not know.
struct FormatInput {
  std::uint32_t components = 0;
  gpu::SpirvScalar scalar = gpu::SpirvScalar::other;
};

FormatInput format_input(VkFormat format) {
  using gpu::SpirvScalar;
  constexpr SpirvScalar kFloat = SpirvScalar::float32;
  constexpr SpirvScalar kUint = SpirvScalar::uint32;
  constexpr SpirvScalar kSint = SpirvScalar::sint32;
  struct Row {
    VkFormat format;
    FormatInput input;
  };
  static constexpr std::array<Row, 21> kRows{{
      {VK_FORMAT_R32_SFLOAT, {1, kFloat}},          {VK_FORMAT_R32G32_SFLOAT, {2, kFloat}},
      {VK_FORMAT_R32G32B32_SFLOAT, {3, kFloat}},    {VK_FORMAT_R32G32B32A32_SFLOAT, {4, kFloat}},
      {VK_FORMAT_R16_SFLOAT, {1, kFloat}},          {VK_FORMAT_R16G16_SFLOAT, {2, kFloat}},
      {VK_FORMAT_R16G16B16A16_SFLOAT, {4, kFloat}}, {VK_FORMAT_R16G16_UNORM, {2, kFloat}},
      {VK_FORMAT_R16G16B16A16_SNORM, {4, kFloat}},  {VK_FORMAT_R8_UNORM, {1, kFloat}},
      {VK_FORMAT_R8G8_UNORM, {2, kFloat}},          {VK_FORMAT_R8G8B8A8_UNORM, {4, kFloat}},
      {VK_FORMAT_R8G8B8A8_SNORM, {4, kFloat}},      {VK_FORMAT_R32_UINT, {1, kUint}},
      {VK_FORMAT_R32G32_UINT, {2, kUint}},          {VK_FORMAT_R32G32B32_UINT, {3, kUint}},
      {VK_FORMAT_R32G32B32A32_UINT, {4, kUint}},    {VK_FORMAT_R32_SINT, {1, kSint}},
      {VK_FORMAT_R32G32_SINT, {2, kSint}},          {VK_FORMAT_R32G32B32_SINT, {3, kSint}},
      {VK_FORMAT_R32G32B32A32_SINT, {4, kSint}},
  }};
  const auto it = std::find_if(kRows.begin(), kRows.end(),
                               [&](const Row& row) { return row.format == format; });
  return it == kRows.end() ? FormatInput{} : it->input;
}

// One vertex input of `shader` against the pipeline's attributes.
void check_vertex_input(std::string_view pass, const Shader& shader,
                        const gpu::SpirvVertexInput& input,
                        std::span<const VkVertexInputAttributeDescription> attributes) {
  const std::string shader_type = gpu::glsl_type_name(input.scalar, input.components);
  const std::string what = shader.file + ": vertex input location " +
                           std::to_string(input.location) +
                           (input.name.empty() ? "" : " ('" + input.name + "')");
  const auto it = std::find_if(attributes.begin(), attributes.end(),
                               [&](const auto& a) { return a.location == input.location; });
  if (it == attributes.end()) {
    interface_error(pass, shader,
                    what + " is a " + shader_type +
                        " in the shader and has no vertex attribute in the C++ pipeline");
  }
  const FormatInput fed = format_input(it->format);
  if (fed.components == 0) {
    interface_error(pass, shader,
                    what + ": the C++ attribute's format (VkFormat " +
                        std::to_string(static_cast<int>(it->format)) +
                        ") is not one the check knows; add it to format_input()");
  }
  if (input.components != fed.components || input.scalar != fed.scalar) {
    interface_error(pass, shader,
                    what + " is a " + shader_type + " in the shader, a " +
                        gpu::glsl_type_name(fed.scalar, fed.components) +
                        " in the C++ vertex attribute (VkFormat " +
                        std::to_string(static_cast<int>(it->format)) + ")");
  }
}

}  // namespace

void check_vertex_inputs(std::string_view pass, const Shader& shader,
                         std::span<const VkVertexInputAttributeDescription> attributes) {
  for (const gpu::SpirvVertexInput& input : shader.interface.vertex_inputs) {
    check_vertex_input(pass, shader, input, attributes);
  }
}

ComputePipeline build_compute_pipeline(fgvk::PrepareContext& context, const Shader& shader,
                                       const gpu::DescriptorSetLayoutBuilder& bindings,
                                       std::uint32_t push_constant_bytes) {
  check_shader_interface(context.pass.name, shader, bindings, push_constant_bytes);
  ComputePipeline out;
  out.set_layout = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{out.set_layout};
  const std::array<VkPushConstantRange, 1> push{
      {{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_bytes}}};
  out.layout = gpu::create_pipeline_layout(context.gpu, sets, push, context.pass.name + ".layout");
  out.pipeline = gpu::create_compute_pipeline(
      context.gpu, out.layout, shader, context.pass.name + ".pipeline", context.pipeline_cache);
  return out;
}

void dispatch_groups(VkCommandBuffer cmd, VkExtent2D extent, std::uint32_t group,
                     std::uint32_t depth) {
  vkCmdDispatch(cmd, group_count(extent.width, group), group_count(extent.height, group), depth);
}

gpu::GraphicsPipelineBuilder scene_vertex_attributes(std::vector<std::uint32_t> locations) {
  if (locations.empty()) locations = {0, 1, 2, 3, 4};
  const auto has = [&](std::uint32_t l) {
    return std::find(locations.begin(), locations.end(), l) != locations.end();
  };
  gpu::GraphicsPipelineBuilder b;
  b.vertex_binding(0, sizeof(GpuVertex));
  if (has(3) || has(4)) b.vertex_binding(1, sizeof(GpuVertexAttributes));
  if (has(0)) b.vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position));
  if (has(1)) b.vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal));
  if (has(2)) b.vertex_attribute(2, 0, VK_FORMAT_R32_UINT, offsetof(GpuVertex, material));
  if (has(3)) {
    b.vertex_attribute(3, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertexAttributes, uv));
  }
  if (has(4)) {
    b.vertex_attribute(4, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertexAttributes, tangent));
  }
  return b;
}

bool draws_class(const fgvk::FrameResources& frame, fgvk::DrawClass draw_class,
                 std::array<bool, 2> halves) {
  const auto c = static_cast<std::size_t>(draw_class);
  return (halves[0] && frame.draw_ranges[0][c].count > 0) ||
         (halves[1] && frame.draw_ranges[1][c].count > 0);
}

std::array<VkPipeline, fgvk::kDrawClasses> needed_pipelines(
    const fgvk::FrameResources& frame, std::span<LazyPipeline, fgvk::kDrawClasses> lazy,
    std::array<bool, 2> halves) {
  std::array<VkPipeline, fgvk::kDrawClasses> out{};
  for (std::size_t c = 0; c < fgvk::kDrawClasses; ++c) {
    out[c] = draws_class(frame, static_cast<fgvk::DrawClass>(c), halves) ? lazy[c].get()
                                                                         : VK_NULL_HANDLE;
  }
  return out;
}

void bind_scene_geometry(VkCommandBuffer cmd, const fgvk::FrameResources& frame) {
  const std::array<VkBuffer, 2> streams{frame.vertices, frame.vertex_attributes};
  const std::array<VkDeviceSize, 2> offsets{0, 0};
  vkCmdBindVertexBuffers(cmd, 0, 2, streams.data(), offsets.data());
  vkCmdBindIndexBuffer(cmd, frame.indices, 0, VK_INDEX_TYPE_UINT32);
}

void draw_by_class(VkCommandBuffer cmd, const fgvk::FrameResources& frame,
                   std::span<const VkPipeline, fgvk::kDrawClasses> pipelines,
                   std::array<bool, 2> halves, std::uint32_t instances,
                   std::uint32_t first_instance) {
  VkPipeline bound = VK_NULL_HANDLE;
  for (std::size_t half = 0; half < 2; ++half) {
    if (!halves[half]) continue;
    for (std::size_t c = 0; c < fgvk::kDrawClasses; ++c) {
      const fgvk::IndexRange& range = frame.draw_ranges[half][c];
      if (range.count == 0 || pipelines[c] == VK_NULL_HANDLE) continue;
      if (pipelines[c] != bound) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines[c]);
        bound = pipelines[c];
      }
      vkCmdDrawIndexed(cmd, range.count, instances, range.first, 0, first_instance);
    }
  }
}

void set_viewport(VkCommandBuffer cmd, VkExtent2D extent) {
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace antumbra::passes
