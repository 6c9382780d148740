#include "antumbra/gpu/pipelines.hpp"

namespace antumbra::gpu {

GraphicsPipelineBuilder& GraphicsPipelineBuilder::shader(VkShaderStageFlagBits stage,
                                                         VkShaderModule module, const char* entry) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = stage;
  info.module = module;
  stages_.push_back(info);
  entries_.emplace_back(entry);  // pName is set in build(), once entries_ stops moving
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::vertex_binding(std::uint32_t binding,
                                                                 std::uint32_t stride,
                                                                 VkVertexInputRate rate) {
  bindings_.push_back({binding, stride, rate});
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::vertex_attribute(std::uint32_t location,
                                                                   std::uint32_t binding,
                                                                   VkFormat format,
                                                                   std::uint32_t offset) {
  attributes_.push_back({location, binding, format, offset});
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::cull(VkCullModeFlags mode, VkFrontFace front) {
  cull_ = mode;
  front_ = front;
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth(bool test, bool write, VkCompareOp op) {
  depth_test_ = test;
  depth_write_ = write;
  depth_op_ = op;
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth_bias(float constant, float slope) {
  depth_bias_ = true;
  bias_constant_ = constant;
  bias_slope_ = slope;
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::color_formats(std::vector<VkFormat> formats) {
  color_formats_ = std::move(formats);
  VkPipelineColorBlendAttachmentState opaque{};
  opaque.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                          VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  blend_.assign(color_formats_.size(), opaque);
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth_format(VkFormat format) {
  depth_format_ = format;
  return *this;
}

namespace {

// An additive-op blend equation for colour and alpha with the given factors.
void enable_blend(VkPipelineColorBlendAttachmentState& b, VkBlendFactor src_color,
                  VkBlendFactor dst_color, VkBlendFactor src_alpha, VkBlendFactor dst_alpha) {
  b.blendEnable = VK_TRUE;
  b.srcColorBlendFactor = src_color;
  b.dstColorBlendFactor = dst_color;
  b.colorBlendOp = VK_BLEND_OP_ADD;
  b.srcAlphaBlendFactor = src_alpha;
  b.dstAlphaBlendFactor = dst_alpha;
  b.alphaBlendOp = VK_BLEND_OP_ADD;
}

}  // namespace

GraphicsPipelineBuilder& GraphicsPipelineBuilder::tint_blend(std::uint32_t attachment) {
  auto& b = blend_.at(attachment);
  enable_blend(b, VK_BLEND_FACTOR_DST_COLOR, VK_BLEND_FACTOR_ZERO, VK_BLEND_FACTOR_ONE,
               VK_BLEND_FACTOR_ONE);
  b.alphaBlendOp = VK_BLEND_OP_MIN;  // factors are ignored by MIN
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::color_write_mask(std::uint32_t attachment,
                                                                   VkColorComponentFlags mask) {
  blend_.at(attachment).colorWriteMask = mask;
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::layout(VkPipelineLayout layout) {
  layout_ = layout;
  return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::cache(VkPipelineCache cache) {
  cache_ = cache;
  return *this;
}

Pipeline GraphicsPipelineBuilder::build(Context& context, std::string_view name) const {
  std::vector<VkPipelineShaderStageCreateInfo> stages = stages_;
  for (std::size_t i = 0; i < stages.size(); ++i) stages[i].pName = entries_[i].c_str();

  VkPipelineVertexInputStateCreateInfo vertex{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex.vertexBindingDescriptionCount = static_cast<std::uint32_t>(bindings_.size());
  vertex.pVertexBindingDescriptions = bindings_.data();
  vertex.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes_.size());
  vertex.pVertexAttributeDescriptions = attributes_.data();

  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = cull_;
  raster.frontFace = front_;
  raster.depthClampEnable = VK_FALSE;
  raster.depthBiasEnable = depth_bias_ ? VK_TRUE : VK_FALSE;
  raster.depthBiasConstantFactor = bias_constant_;
  raster.depthBiasSlopeFactor = bias_slope_;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = depth_test_ ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = depth_write_ ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = depth_op_;

  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<std::uint32_t>(blend_.size());
  blend.pAttachments = blend_.data();

  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(color_formats_.size());
  rendering.pColorAttachmentFormats = color_formats_.data();
  rendering.depthAttachmentFormat = depth_format_;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(context.device(), cache_, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  return {context, pipeline, name};
}

}  // namespace antumbra::gpu
