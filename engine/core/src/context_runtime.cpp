// Context at run time: debug names and labels, validation counters, submission on the
// timeline, and deferred destruction keyed to timeline values.
#include <string>

#include <spdlog/spdlog.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/vk_commands.hpp"

namespace antumbra::gpu {

void Context::set_name(std::uint64_t handle, VkObjectType type, std::string_view name) const {
  if (!ext_.set_object_name || handle == 0 || !device_) return;
  const std::string text(name);
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = text.c_str();
  check(ext_.set_object_name(device_, &info), "vkSetDebugUtilsObjectNameEXT");
}

void Context::begin_label(VkCommandBuffer cmd, std::string_view name,
                          std::array<float, 4> color) const {
  if (label_listener_ != nullptr) label_listener_->begin(cmd, name);
  if (!ext_.cmd_begin_label) return;
  const std::string text(name);
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = text.c_str();
  for (int i = 0; i < 4; ++i) label.color[i] = color[static_cast<std::size_t>(i)];
  ext_.cmd_begin_label(cmd, &label);
}

void Context::end_label(VkCommandBuffer cmd) const {
  if (label_listener_ != nullptr) label_listener_->end(cmd);
  if (ext_.cmd_end_label) ext_.cmd_end_label(cmd);
}

namespace {

// RenderDoc starts and ends a capture on these queue labels: its in-application capture
// API without linking or loading RenderDoc (Debian's 1.24 has them).
void insert_queue_label(const ExtensionFunctions& ext, VkQueue queue, const char* name) {
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  ext.queue_insert_label(queue, &label);
}

}  // namespace

void Context::begin_debugger_capture() const {
  if (capture_tool_.empty() || !ext_.queue_insert_label) return;
  insert_queue_label(ext_, queue_, "capture-marker,begin_capture");
}

void Context::end_debugger_capture() const {
  if (capture_tool_.empty() || !ext_.queue_insert_label) return;
  insert_queue_label(ext_, queue_, "capture-marker,end_capture");
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::debug_callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Context*>(user);
  const char* id = data->pMessageIdName ? data->pMessageIdName : "";
  const char* text = data->pMessage ? data->pMessage : "";
  const bool log = self->log_validation_;
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    ++self->errors_;
    if (log) spdlog::error("[vulkan] {}: {}", id, text);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    ++self->warnings_;
    if (log) spdlog::warn("[vulkan] {}: {}", id, text);
  } else if (log) {
    spdlog::debug("[vulkan] {}: {}", id, text);
  }
  std::lock_guard lock(self->messages_mutex_);
  self->messages_.push_back({severity, id, text});
  if (self->messages_.size() > kKeptValidationMessages) self->messages_.pop_front();
  return VK_FALSE;  // never abort the call: the count is what tests check
}

std::vector<ValidationMessage> Context::validation_messages() const {
  std::lock_guard lock(messages_mutex_);
  return {messages_.begin(), messages_.end()};
}

void Context::reset_validation_counts() {
  errors_ = 0;
  warnings_ = 0;
  std::lock_guard lock(messages_mutex_);
  messages_.clear();
}

std::uint64_t Context::completed_value() const {
  std::uint64_t value = 0;
  check(vkGetSemaphoreCounterValue(device_, timeline_, &value), "vkGetSemaphoreCounterValue");
  return value;
}

std::uint64_t Context::submit(VkCommandBuffer cmd, const SubmitExtras& extras) {
  if (device_lost_ || (lose_device_at_ != 0 && ++submissions_ >= lose_device_at_)) {
    device_lost_ = true;
    throw VulkanError(VK_ERROR_DEVICE_LOST,
                      lose_device_at_ != 0
                          ? "vkQueueSubmit2 [a device loss injected at submission " +
                                std::to_string(lose_device_at_) + "]"
                          : std::string("vkQueueSubmit2 [the device is lost]"),
                      SourceLocation::current());
  }
  const std::uint64_t value = last_submitted_ + 1;
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = cmd;
  std::vector<VkSemaphoreSubmitInfo> signals = extras.signals;
  VkSemaphoreSubmitInfo timeline_signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  timeline_signal.semaphore = timeline_;
  timeline_signal.value = value;
  timeline_signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  signals.push_back(timeline_signal);

  VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  info.waitSemaphoreInfoCount = static_cast<std::uint32_t>(extras.waits.size());
  info.pWaitSemaphoreInfos = extras.waits.data();
  info.commandBufferInfoCount = cmd ? 1u : 0u;
  info.pCommandBufferInfos = &cmd_info;
  info.signalSemaphoreInfoCount = static_cast<std::uint32_t>(signals.size());
  info.pSignalSemaphoreInfos = signals.data();
  const VkResult result = queue_submit2(queue_, 1, &info, extras.fence);
  if (result == VK_ERROR_DEVICE_LOST) device_lost_ = true;
  check(result, "vkQueueSubmit2");
  last_submitted_ = value;
  return value;
}

std::uint64_t Context::reserve_host_submission() {
  return ++last_submitted_;
}

void Context::wait_for(std::uint64_t timeline_value) const {
  VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  info.semaphoreCount = 1;
  info.pSemaphores = &timeline_;
  info.pValues = &timeline_value;
  check(vkWaitSemaphores(device_, &info, UINT64_MAX), "vkWaitSemaphores");
}

void Context::submit_immediate(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = immediate_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  struct FreeOnExit {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~FreeOnExit() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } free_on_exit{device_, immediate_pool_, cmd};
  set_name(cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, "context.immediate");

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  // The buffer must stay alive until the GPU is done with it: wait before freeing.
  wait_for(submit(cmd));
}

void Context::destroy_deferred(VkObjectType type, std::uint64_t handle,
                               const Allocation& allocation) {
  if (handle == 0 && !allocation.valid()) return;
  // +1: the frame being recorded now may still reference the object.
  pending_.push_back({type, handle, allocation, last_submitted_ + 1});
}

void Context::collect_garbage() {
  if (pending_.empty()) return;
  const std::uint64_t done = completed_value();
  // Records are queued in non-decreasing after_value order.
  while (!pending_.empty() && pending_.front().after_value <= done) {
    destroy_now(pending_.front());
    pending_.pop_front();
  }
}

void Context::wait_idle() {
  // A host's device also runs the host's work, on queues the host synchronises: wait only
  // for what Antumbra submitted or reserved (a host frame not yet submitted would never
  // signal: the host submits before it destroys the session, docs/integration.md).
  VkResult result = VK_SUCCESS;
  if (borrowed_) {
    VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
    info.semaphoreCount = 1;
    info.pSemaphores = &timeline_;
    info.pValues = &last_submitted_;
    result = vkWaitSemaphores(device_, &info, UINT64_MAX);
  } else {
    result = vkDeviceWaitIdle(device_);
  }
  // Even on a lost device everything queued is destroyed, then the error is reported.
  while (!pending_.empty()) {
    destroy_now(pending_.front());
    pending_.pop_front();
  }
  check(result, "vkDeviceWaitIdle");
}

void Context::destroy_now(const PendingDestroy& object) {
  const std::uint64_t h = object.handle;
  switch (object.type) {
    case VK_OBJECT_TYPE_UNKNOWN:
      break;  // memory only (see below)
    case VK_OBJECT_TYPE_BUFFER:
      vkDestroyBuffer(device_, reinterpret_cast<VkBuffer>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE:
      vkDestroyImage(device_, reinterpret_cast<VkImage>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_IMAGE_VIEW:
      vkDestroyImageView(device_, reinterpret_cast<VkImageView>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SAMPLER:
      vkDestroySampler(device_, reinterpret_cast<VkSampler>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE:
      vkDestroyPipeline(device_, reinterpret_cast<VkPipeline>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
      vkDestroyPipelineLayout(device_, reinterpret_cast<VkPipelineLayout>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
      vkDestroyDescriptorSetLayout(device_, reinterpret_cast<VkDescriptorSetLayout>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_DESCRIPTOR_POOL:
      vkDestroyDescriptorPool(device_, reinterpret_cast<VkDescriptorPool>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SHADER_MODULE:
      vkDestroyShaderModule(device_, reinterpret_cast<VkShaderModule>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_COMMAND_POOL:
      vkDestroyCommandPool(device_, reinterpret_cast<VkCommandPool>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SEMAPHORE:
      vkDestroySemaphore(device_, reinterpret_cast<VkSemaphore>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_FENCE:
      vkDestroyFence(device_, reinterpret_cast<VkFence>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_RENDER_PASS:
      vkDestroyRenderPass(device_, reinterpret_cast<VkRenderPass>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_FRAMEBUFFER:
      vkDestroyFramebuffer(device_, reinterpret_cast<VkFramebuffer>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_SWAPCHAIN_KHR:
      vkDestroySwapchainKHR(device_, reinterpret_cast<VkSwapchainKHR>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_QUERY_POOL:
      vkDestroyQueryPool(device_, reinterpret_cast<VkQueryPool>(h), nullptr);
      break;
    case VK_OBJECT_TYPE_PIPELINE_CACHE:
      vkDestroyPipelineCache(device_, reinterpret_cast<VkPipelineCache>(h), nullptr);
      break;
    default:
      spdlog::error("destroy_deferred: unsupported object type {}", static_cast<int>(object.type));
      break;
  }
  if (object.allocation.valid()) allocator_->free(object.allocation);
  ++destroyed_count_;
}

}  // namespace antumbra::gpu
