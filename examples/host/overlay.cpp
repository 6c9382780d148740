// The engine's own pass (overlay.hpp): drawn after Antumbra's frame into the same image,
// which Antumbra leaves as a colour attachment (the `after` state main.cpp binds with it).
#include "overlay.hpp"

#include <algorithm>
#include <stdexcept>

#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/vk_check.hpp"

namespace gpu = antumbra::gpu;
using gpu::check;

namespace {

// One triangle over the whole image; the scissor keeps the bar.
constexpr const char* kVertex = R"(#version 450
void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";

// Six digits of 3x5 cells (a digit's bits row by row, top row highest), one cell of margin.
constexpr const char* kFragment = R"(#version 450
layout(push_constant) uniform Bar { ivec2 origin; int scale; uint number; } bar;
layout(location = 0) out vec4 color;
const uint kDigits[10] = uint[](0x7B6Fu, 0x2C97u, 0x73E7u, 0x73CFu, 0x5BC9u, 0x79CFu, 0x79EFu,
                                0x7249u, 0x7BEFu, 0x7BCFu);
void main() {
  ivec2 cell = (ivec2(gl_FragCoord.xy) - bar.origin) / bar.scale - 1;
  int digit = cell.x / 4;
  ivec2 at = ivec2(cell.x % 4, cell.y);
  bool lit = false;
  if (cell.x >= 0 && digit < 6 && at.x < 3 && at.y >= 0 && at.y < 5) {
    uint value = bar.number;
    for (int i = digit; i < 5; ++i) value /= 10u;
    lit = ((kDigits[value % 10u] >> uint(14 - at.y * 3 - at.x)) & 1u) != 0u;
  }
  color = lit ? vec4(1.0, 0.85, 0.3, 1.0) : vec4(0.0, 0.0, 0.0, 0.6);
})";

struct Push {
  std::int32_t origin[2];
  std::int32_t scale;
  std::uint32_t number;
};

}  // namespace

Overlay::Overlay(VkDevice device, VkFormat format) : device_(device) {
  // Dynamic rendering, which Antumbra already requires of the device: core in Vulkan 1.3,
  // VK_KHR_dynamic_rendering on 1.2 (gpu::device_setup() enables one or the other).
  begin_rendering_ = reinterpret_cast<PFN_vkCmdBeginRenderingKHR>(
      vkGetDeviceProcAddr(device, "vkCmdBeginRendering"));
  end_rendering_ =
      reinterpret_cast<PFN_vkCmdEndRenderingKHR>(vkGetDeviceProcAddr(device, "vkCmdEndRendering"));
  if (begin_rendering_ == nullptr) {
    begin_rendering_ = reinterpret_cast<PFN_vkCmdBeginRenderingKHR>(
        vkGetDeviceProcAddr(device, "vkCmdBeginRenderingKHR"));
    end_rendering_ = reinterpret_cast<PFN_vkCmdEndRenderingKHR>(
        vkGetDeviceProcAddr(device, "vkCmdEndRenderingKHR"));
  }

  gpu::ShaderCompiler compiler(gpu::ShaderCompilerOptions{.use_cache = false});
  VkPipelineShaderStageCreateInfo stages[2]{};
  const std::pair<const char*, gpu::ShaderStage> sources[] = {
      {kVertex, gpu::ShaderStage::vertex}, {kFragment, gpu::ShaderStage::fragment}};
  for (int i = 0; i < 2; ++i) {
    auto binary = compiler.compile_source(
        sources[i].first, i == 0 ? "overlay.vert" : "overlay.frag", sources[i].second);
    if (!binary.ok()) throw std::runtime_error(binary.diagnostics().to_text());
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = binary.value().spirv.size() * sizeof(std::uint32_t);
    info.pCode = binary.value().spirv.data();
    stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[i].stage = gpu::to_vk(sources[i].second);
    stages[i].pName = "main";
    check(vkCreateShaderModule(device, &info, nullptr, &stages[i].module), "shader module");
  }

  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
  VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout.pushConstantRangeCount = 1;
  layout.pPushConstantRanges = &push;
  check(vkCreatePipelineLayout(device, &layout, nullptr, &layout_), "vkCreatePipelineLayout");

  VkPipelineVertexInputStateCreateInfo vertices{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  // Translucent: the bar darkens what Antumbra drew under it; the image's alpha stays.
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = VK_TRUE;
  blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
  blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blending{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blending.attachmentCount = 1;
  blending.pAttachments = &blend;
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &format;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertices;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blending;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
        "vkCreateGraphicsPipelines");
  for (const auto& stage : stages) vkDestroyShaderModule(device, stage.module, nullptr);
}

Overlay::~Overlay() {
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
}

VkRect2D Overlay::bar(VkExtent2D extent) {
  // 5 rows of digit cells and a margin; a cell is a pixel up to 240 rows, then grows.
  const std::uint32_t height = std::min(extent.height, 7 * std::max(1u, extent.height / 120));
  return {{0, static_cast<std::int32_t>(extent.height - height)}, {extent.width, height}};
}

void Overlay::draw(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent,
                   std::uint32_t number) const {
  const VkRect2D area = bar(extent);
  VkRenderingAttachmentInfo target{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  target.imageView = view;
  target.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  target.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // blended over Antumbra's frame
  target.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = area;
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &target;
  begin_rendering_(cmd, &info);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  const VkViewport full{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, &full);
  vkCmdSetScissor(cmd, 0, 1, &area);
  const Push push{{area.offset.x, area.offset.y},
                  static_cast<std::int32_t>(std::max(1u, area.extent.height / 7)),
                  number};
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  end_rendering_(cmd);
}
