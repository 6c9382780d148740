#pragma once
// A minimal host for the integration tests (docs/integration.md): its own instance (with
// validation and synchronization validation), device created from gpu::device_setup(),
// queue, command buffer and images with memory of their own, as an engine would have them.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/fgvk/executor.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/device_setup.hpp"

namespace antumbra::render_testing {

struct HostOptions {
  // Leave out of the device what Antumbra needs, to test the check's message.
  bool skip_push_descriptor = false;
  bool skip_timeline = false;
};

class TestHost {
 public:
  // Throws gpu::NoVulkanDeviceError when there is no Vulkan device.
  explicit TestHost(const HostOptions& options = {});
  TestHost(const TestHost&) = delete;
  TestHost& operator=(const TestHost&) = delete;
  ~TestHost();

  [[nodiscard]] const gpu::HostDevice& device() const { return host_; }
  [[nodiscard]] std::size_t validation_messages() const { return messages_.load(); }
  [[nodiscard]] const std::string& last_message() const { return last_message_; }
  [[nodiscard]] VkCommandBuffer command_buffer() const { return cmd_; }

  // An image of the host's with its own memory and a view.
  struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkImageUsageFlags usage = 0;
  };
  Image create_image(VkFormat format, VkExtent2D extent, VkImageUsageFlags usage);
  // `image` as an import, before UNDEFINED, after TRANSFER_SRC (read back by the host).
  static fgvk::ImportedImage as_import(const Image& image);

  // Begins the host's command buffer, lets `record` fill it, copies `read_back` (left in
  // TRANSFER_SRC_OPTIMAL) into host memory, submits signalling `signal` and waits.
  // Returns the RGBA8 texels.
  template <class Record>
  std::vector<std::uint8_t> frame(const Record& record, const Image& read_back);

 private:
  void begin();
  std::vector<std::uint8_t> end_and_read(VkSemaphore semaphore, std::uint64_t value,
                                         const Image& read_back);
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user);
  std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags flags) const;

  gpu::HostDevice host_;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  std::vector<Image> images_;
  std::atomic<std::size_t> messages_{0};
  std::string last_message_;
  std::unique_ptr<gpu::FeatureChain> setup_features_;  // what the device was created with
};

template <class Record>
std::vector<std::uint8_t> TestHost::frame(const Record& record, const Image& read_back) {
  begin();
  const auto [semaphore, value] = record(cmd_);
  return end_and_read(semaphore, value, read_back);
}

}  // namespace antumbra::render_testing
