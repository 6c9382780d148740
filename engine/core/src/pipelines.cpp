#include "antumbra/gpu/pipelines.hpp"

namespace antumbra::gpu {

DescriptorSetLayoutBuilder& DescriptorSetLayoutBuilder::add(std::uint32_t binding,
                                                            VkDescriptorType type,
                                                            VkShaderStageFlags stages,
                                                            std::uint32_t count) {
  bindings_.push_back({binding, type, count, stages, nullptr});
  return *this;
}

DescriptorSetLayout DescriptorSetLayoutBuilder::build(Context& context, std::string_view name,
                                                      bool push) const {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.flags =
      push
          ? VkDescriptorSetLayoutCreateFlags{VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR}
          : 0u;
  info.bindingCount = static_cast<std::uint32_t>(bindings_.size());
  info.pBindings = bindings_.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(context.device(), &info, nullptr, &layout),
        "vkCreateDescriptorSetLayout");
  return {context, layout, name};
}

PipelineLayout create_pipeline_layout(Context& context,
                                      std::span<const VkDescriptorSetLayout> set_layouts,
                                      std::span<const VkPushConstantRange> push_constants,
                                      std::string_view name) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<std::uint32_t>(set_layouts.size());
  info.pSetLayouts = set_layouts.data();
  info.pushConstantRangeCount = static_cast<std::uint32_t>(push_constants.size());
  info.pPushConstantRanges = push_constants.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout),
        "vkCreatePipelineLayout");
  return {context, layout, name};
}

PushDescriptors& PushDescriptors::storage_image(std::uint32_t binding, VkImageView view,
                                                VkImageLayout layout) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, images_.size()});
  images_.push_back({VK_NULL_HANDLE, view, layout});
  return *this;
}

PushDescriptors& PushDescriptors::sampled_image(std::uint32_t binding, VkImageView view,
                                                VkImageLayout layout) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, images_.size()});
  images_.push_back({VK_NULL_HANDLE, view, layout});
  return *this;
}

PushDescriptors& PushDescriptors::combined_image_sampler(std::uint32_t binding, VkImageView view,
                                                         VkSampler sampler, VkImageLayout layout) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images_.size()});
  images_.push_back({sampler, view, layout});
  return *this;
}

PushDescriptors& PushDescriptors::sampled_images(std::uint32_t binding,
                                                 std::span<const VkImageView> views,
                                                 VkImageLayout layout) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, images_.size(),
                     static_cast<std::uint32_t>(views.size())});
  for (const VkImageView view : views) images_.push_back({VK_NULL_HANDLE, view, layout});
  return *this;
}

PushDescriptors& PushDescriptors::sampler(std::uint32_t binding, VkSampler sampler) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_SAMPLER, images_.size()});
  images_.push_back({sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
  return *this;
}

PushDescriptors& PushDescriptors::uniform_buffer(std::uint32_t binding, VkBuffer buffer,
                                                 VkDeviceSize offset, VkDeviceSize range) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffers_.size()});
  buffers_.push_back({buffer, offset, range});
  return *this;
}

PushDescriptors& PushDescriptors::storage_buffer(std::uint32_t binding, VkBuffer buffer,
                                                 VkDeviceSize offset, VkDeviceSize range) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers_.size()});
  buffers_.push_back({buffer, offset, range});
  return *this;
}

void PushDescriptors::push(const Context& context, VkCommandBuffer cmd,
                           VkPipelineBindPoint bind_point, VkPipelineLayout layout,
                           std::uint32_t set) {
  // Pointers are taken only now, when the info vectors no longer grow.
  std::vector<VkWriteDescriptorSet> writes;
  writes.reserve(writes_.size());
  for (const Write& w : writes_) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = w.binding;
    write.descriptorCount = w.count;
    write.descriptorType = w.type;
    const bool buffer =
        w.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || w.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (buffer) {
      write.pBufferInfo = &buffers_[w.info];
    } else {
      write.pImageInfo = &images_[w.info];
    }
    writes.push_back(write);
  }
  context.ext().cmd_push_descriptor_set(cmd, bind_point, layout, set,
                                        static_cast<std::uint32_t>(writes.size()), writes.data());
}

void PushDescriptors::clear() {
  writes_.clear();
  images_.clear();
  buffers_.clear();
}

Pipeline create_compute_pipeline(Context& context, VkPipelineLayout layout, VkShaderModule module,
                                 std::string_view name, VkPipelineCache cache, const char* entry) {
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = entry;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateComputePipelines(context.device(), cache, 1, &info, nullptr, &pipeline),
        "vkCreateComputePipelines");
  return {context, pipeline, name};
}

}  // namespace antumbra::gpu
