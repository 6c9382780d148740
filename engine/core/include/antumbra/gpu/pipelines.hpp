#pragma once
// Pipeline helpers for dynamic rendering and compute, descriptor set layouts and
// pipeline layouts.
//
// Descriptor style: push descriptors (VK_KHR_push_descriptor, required at device
// selection; supported by NVIDIA, AMD, Intel and lavapipe). A pass pushes its
// bindings with PushDescriptors right before its draw/dispatch: no pools, no set
// lifetime, nothing to reset per frame, and hot reload can drop a layout at any time.
// Set 0 is the push set; larger, long-lived tables (bindless arrays) may use a
// regular set from a DescriptorPool at set 1.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::gpu {

struct ShaderBinary;

class DescriptorSetLayoutBuilder {
 public:
  DescriptorSetLayoutBuilder& add(std::uint32_t binding, VkDescriptorType type,
                                  VkShaderStageFlags stages, std::uint32_t count = 1);
  DescriptorSetLayoutBuilder& sampled_image(std::uint32_t binding, VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, stages);
  }
  DescriptorSetLayoutBuilder& combined_image_sampler(std::uint32_t binding,
                                                     VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages);
  }
  DescriptorSetLayoutBuilder& storage_image(std::uint32_t binding, VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, stages);
  }
  DescriptorSetLayoutBuilder& uniform_buffer(std::uint32_t binding, VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages);
  }
  DescriptorSetLayoutBuilder& storage_buffer(std::uint32_t binding, VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, stages);
  }
  DescriptorSetLayoutBuilder& sampler(std::uint32_t binding, VkShaderStageFlags stages) {
    return add(binding, VK_DESCRIPTOR_TYPE_SAMPLER, stages);
  }
  // push = true (the default style) sets VK_..._PUSH_DESCRIPTOR_BIT_KHR.
  DescriptorSetLayout build(Context& context, std::string_view name, bool push = true) const;
  [[nodiscard]] const std::vector<VkDescriptorSetLayoutBinding>& bindings() const {
    return bindings_;
  }

 private:
  std::vector<VkDescriptorSetLayoutBinding> bindings_;
};

PipelineLayout create_pipeline_layout(Context& context,
                                      std::span<const VkDescriptorSetLayout> set_layouts,
                                      std::span<const VkPushConstantRange> push_constants,
                                      std::string_view name);

// Collects descriptor writes for one push-descriptor set and records them.
// Holds pointers to its own info arrays: do not copy while writes are pending.
class PushDescriptors {
 public:
  PushDescriptors& storage_image(std::uint32_t binding, VkImageView view,
                                 VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL);
  PushDescriptors& sampled_image(std::uint32_t binding, VkImageView view,
                                 VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  PushDescriptors& combined_image_sampler(
      std::uint32_t binding, VkImageView view, VkSampler sampler,
      VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  PushDescriptors& sampler(std::uint32_t binding, VkSampler sampler);
  // An array of descriptors: elements 0.. of `binding`.
  PushDescriptors& sampled_images(std::uint32_t binding, std::span<const VkImageView> views,
                                  VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  PushDescriptors& uniform_buffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                                  VkDeviceSize range = VK_WHOLE_SIZE);
  PushDescriptors& storage_buffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                                  VkDeviceSize range = VK_WHOLE_SIZE);
  void push(const Context& context, VkCommandBuffer cmd, VkPipelineBindPoint bind_point,
            VkPipelineLayout layout, std::uint32_t set = 0);
  void clear();

 private:
  struct Write {
    std::uint32_t binding;
    VkDescriptorType type;
    std::size_t info;  // index into images_ or buffers_
    std::uint32_t count = 1;
  };
  std::vector<Write> writes_;
  std::vector<VkDescriptorImageInfo> images_;
  std::vector<VkDescriptorBufferInfo> buffers_;
};

// Graphics pipeline for dynamic rendering. Defaults: triangle list, back-face culling
// off, depth test/write off, no blending, dynamic viewport and scissor.
class GraphicsPipelineBuilder {
 public:
  GraphicsPipelineBuilder& shader(VkShaderStageFlagBits stage, VkShaderModule module,
                                  const char* entry = "main");
  GraphicsPipelineBuilder& vertex_binding(std::uint32_t binding, std::uint32_t stride,
                                          VkVertexInputRate rate = VK_VERTEX_INPUT_RATE_VERTEX);
  GraphicsPipelineBuilder& vertex_attribute(std::uint32_t location, std::uint32_t binding,
                                            VkFormat format, std::uint32_t offset);
  GraphicsPipelineBuilder& cull(VkCullModeFlags mode,
                                VkFrontFace front = VK_FRONT_FACE_COUNTER_CLOCKWISE);
  GraphicsPipelineBuilder& depth(bool test, bool write,
                                 VkCompareOp op = VK_COMPARE_OP_LESS_OR_EQUAL);
  GraphicsPipelineBuilder& depth_bias(float constant, float slope);  // shadow maps
  GraphicsPipelineBuilder& color_formats(std::vector<VkFormat> formats);
  GraphicsPipelineBuilder& depth_format(VkFormat format);
  // Transmittance maps: rgb = dst * src (stacked panes compose by multiplication),
  // a = min(dst, src) (the nearest pane's distance, so a pane tints only what lies
  // behind it).
  GraphicsPipelineBuilder& tint_blend(std::uint32_t attachment);
  GraphicsPipelineBuilder& color_write_mask(std::uint32_t attachment, VkColorComponentFlags mask);
  GraphicsPipelineBuilder& layout(VkPipelineLayout layout);
  GraphicsPipelineBuilder& cache(VkPipelineCache cache);
  Pipeline build(Context& context, std::string_view name) const;
  // What vertex_attribute() declared, for checking against the vertex shader's inputs.
  [[nodiscard]] const std::vector<VkVertexInputAttributeDescription>& vertex_attributes() const {
    return attributes_;
  }

 private:
  std::vector<VkPipelineShaderStageCreateInfo> stages_;
  std::vector<std::string> entries_;
  std::vector<VkVertexInputBindingDescription> bindings_;
  std::vector<VkVertexInputAttributeDescription> attributes_;
  VkCullModeFlags cull_ = VK_CULL_MODE_NONE;
  VkFrontFace front_ = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  bool depth_test_ = false;
  bool depth_write_ = false;
  VkCompareOp depth_op_ = VK_COMPARE_OP_LESS_OR_EQUAL;
  bool depth_bias_ = false;
  float bias_constant_ = 0.0f;
  float bias_slope_ = 0.0f;
  std::vector<VkFormat> color_formats_;
  std::vector<VkPipelineColorBlendAttachmentState> blend_;
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
};

Pipeline create_compute_pipeline(Context& context, VkPipelineLayout layout, VkShaderModule module,
                                 std::string_view name, VkPipelineCache cache = VK_NULL_HANDLE,
                                 const char* entry = "main");

}  // namespace antumbra::gpu
