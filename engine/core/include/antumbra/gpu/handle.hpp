#pragma once
// Move-only owner of one Vulkan handle. The destructor hands the handle to the
// context's deferred-destruction queue, so dropping an object that a frame in flight
// still uses is safe.

#include <utility>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"

namespace antumbra::gpu {

template <class T, VkObjectType kType>
class Handle {
 public:
  Handle() = default;
  // Takes ownership of `handle` (and names it when a name is given).
  Handle(Context& context, T handle, std::string_view name = {})
      : context_(&context), handle_(handle) {
    if (!name.empty()) context.set_name(handle, kType, name);
  }
  Handle(Handle&& other) noexcept
      : context_(std::exchange(other.context_, nullptr)),
        handle_(std::exchange(other.handle_, T{VK_NULL_HANDLE})) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      context_ = std::exchange(other.context_, nullptr);
      handle_ = std::exchange(other.handle_, T{VK_NULL_HANDLE});
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  void reset() {
    if (context_ && handle_ != T{VK_NULL_HANDLE}) {
      context_->destroy_deferred(kType, handle_bits(handle_));
    }
    handle_ = T{VK_NULL_HANDLE};
  }
  [[nodiscard]] T get() const { return handle_; }
  operator T() const { return handle_; }  // NOLINT(google-explicit-constructor)
  explicit operator bool() const { return handle_ != T{VK_NULL_HANDLE}; }

 private:
  Context* context_ = nullptr;
  T handle_ = VK_NULL_HANDLE;
};

using ImageView = Handle<VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW>;
using Sampler = Handle<VkSampler, VK_OBJECT_TYPE_SAMPLER>;
using Pipeline = Handle<VkPipeline, VK_OBJECT_TYPE_PIPELINE>;
using PipelineLayout = Handle<VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT>;
using DescriptorSetLayout = Handle<VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT>;
using DescriptorPool = Handle<VkDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL>;
using ShaderModule = Handle<VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE>;
using CommandPool = Handle<VkCommandPool, VK_OBJECT_TYPE_COMMAND_POOL>;
using Semaphore = Handle<VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE>;
using Fence = Handle<VkFence, VK_OBJECT_TYPE_FENCE>;
using QueryPool = Handle<VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL>;
// The windowed editor's presentation objects (its swapchain outlives no surface: the
// owner drains the queue with Context::wait_idle() before the surface goes).
using RenderPass = Handle<VkRenderPass, VK_OBJECT_TYPE_RENDER_PASS>;
using Framebuffer = Handle<VkFramebuffer, VK_OBJECT_TYPE_FRAMEBUFFER>;
using Swapchain = Handle<VkSwapchainKHR, VK_OBJECT_TYPE_SWAPCHAIN_KHR>;

// Factories for the simple objects (each names what it creates).
Semaphore create_binary_semaphore(Context& context, std::string_view name);
CommandPool create_command_pool(Context& context, VkCommandPoolCreateFlags flags,
                                std::string_view name);
QueryPool create_timestamp_query_pool(Context& context, std::uint32_t count, std::string_view name);
ShaderModule create_shader_module(Context& context, const std::vector<std::uint32_t>& spirv,
                                  std::string_view name);

struct SamplerDesc {
  VkFilter filter = VK_FILTER_LINEAR;
  VkSamplerMipmapMode mipmap = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  float max_anisotropy = 1.0f;  // > 1 only when the feature is enabled (else ignored)
  bool compare = false;         // depth comparison (shadow sampler), LESS_OR_EQUAL
  VkBorderColor border = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
};
Sampler create_sampler(Context& context, const SamplerDesc& desc, std::string_view name);

}  // namespace antumbra::gpu
