#pragma once
// The engine's own pass after Antumbra's frame: a translucent bar along the bottom of the
// same image with the frame number in blocky digits. One graphics pipeline, no buffers or
// descriptors; its GLSL is compiled by Antumbra's installed gpu::ShaderCompiler.

#include <cstdint>

#include <vulkan/vulkan.h>

class Overlay {
 public:
  Overlay(VkDevice device, VkFormat format);
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;
  ~Overlay();

  // The pixels the bar covers; nothing outside it is touched.
  static VkRect2D bar(VkExtent2D extent);
  // Blends the bar over `view`, which is in COLOR_ATTACHMENT_OPTIMAL and stays there.
  void draw(VkCommandBuffer cmd, VkImageView view, VkExtent2D extent, std::uint32_t number) const;

 private:
  VkDevice device_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  PFN_vkCmdBeginRenderingKHR begin_rendering_ = nullptr;
  PFN_vkCmdEndRenderingKHR end_rendering_ = nullptr;
};
