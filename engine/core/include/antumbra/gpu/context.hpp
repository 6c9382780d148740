#pragma once
// The Vulkan context: instance (+ validation with synchronization validation), one
// physical device, one device with one graphics+compute queue, the sub-allocator, the
// timeline semaphore every submission signals, and the deferred-destruction queue keyed
// to that timeline. Passed explicitly as `Context&`; there is no global instance.
//
// Threading: one thread records, submits and destroys; only the validation callback
// may run on other threads (its counters are synchronised).

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/memory.hpp"
#include "antumbra/gpu/vk_check.hpp"

namespace antumbra::gpu {

struct ContextOptions {
  std::string app_name = "antumbra";
  bool validation = false;
  bool sync_validation = true;  // only when validation is on
  // auto | cpu | gpu | <index> | <case-insensitive name substring>. auto prefers
  // discrete, then integrated, then virtual GPUs, then CPU (lavapipe).
  std::string device = "auto";
  std::vector<std::string> instance_extensions;
  std::vector<std::string> device_extensions;
  bool headless = true;  // false: VK_KHR_swapchain is enabled on the device as well
  // The highest Vulkan version to use: VK_API_VERSION_1_2 treats every device as a 1.2
  // device (the path RenderDoc 1.24 takes: dynamic rendering, synchronization2 and
  // maintenance4 through their KHR extensions). 0: the ANTUMBRA_VULKAN_API environment
  // variable ("1.2" or "1.3") when it is set, else 1.3.
  std::uint32_t max_api_version = 0;
  // A test hook (docs/robustness.md, "Device loss"): the n-th submission (submit() and
  // submit_immediate(), uploads included, counted from 1) and every one after it fail with
  // VK_ERROR_DEVICE_LOST instead of reaching the queue, as on a lost device. 0: the
  // ANTUMBRA_TEST_LOSE_DEVICE_AT environment variable when it is set, else never.
  std::uint64_t lose_device_at_submission = 0;
  // A test hook (docs/robustness.md, "Out of device memory"): every transient heap a graph
  // allocates of more than this many bytes fails with VK_ERROR_OUT_OF_DEVICE_MEMORY. 0: the
  // ANTUMBRA_TEST_FAIL_HEAPS_ABOVE environment variable when it is set, else never.
  std::uint64_t fail_heaps_above = 0;
};

// A device the host created and keeps owning (docs/integration.md, "The host's device"):
// a Context made from it borrows it, checks that it has what Antumbra needs and names
// what it lacks, and destroys only its own objects. Enable device_setup()'s extensions
// and features when creating the device.
struct HostDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  // A graphics+compute queue. Antumbra submits to it only for uploads (scene, loads):
  // the host externally synchronises it, as Vulkan requires (no call into Antumbra while
  // another thread submits to it).
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  // The instance's VkApplicationInfo::apiVersion (VK_API_VERSION_1_2 or _1_3).
  std::uint32_t api_version = VK_API_VERSION_1_3;
  // Exactly what the device was created with: ppEnabledExtensionNames, and the pNext
  // chain of VkDeviceCreateInfo (VkPhysicalDeviceFeatures2 and the Vulkan 1.1/1.2/1.3
  // feature blocks, or the KHR structs on a 1.2 device; pEnabledFeatures is not read).
  std::vector<std::string> enabled_extensions;
  const void* enabled_features = nullptr;
  // VK_EXT_debug_utils is enabled on the instance: objects get names, passes labels.
  bool debug_utils = false;
  // The host's instance runs the validation layer: Antumbra counts its messages too
  // (a messenger of its own, when debug_utils), and checks its barrier plan.
  bool validation = false;
  // Antumbra also logs the messages it counts (spdlog). A host whose own messenger prints
  // them sets false, so that each message is printed once; the counts and
  // Context::validation_messages() stay.
  bool log_validation = true;
};

// Vulkan 1.3, or 1.2 with these extensions: a 1.2 device needs them (with their
// dynamicRendering, synchronization2 features) for what 1.3 has in core.
inline constexpr const char* kVulkan13Extensions[] = {VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME,
                                                      VK_KHR_SYNCHRONIZATION_2_EXTENSION_NAME,
                                                      VK_KHR_MAINTENANCE_4_EXTENSION_NAME};

// Optional features that were found and enabled (required ones are always on:
// dynamicRendering, synchronization2, timelineSemaphore, VK_KHR_push_descriptor, and on a
// Vulkan 1.2 device kVulkan13Extensions).
struct DeviceFeatures {
  bool sampler_anisotropy = false;
  bool storage_image_write_without_format = false;
  bool storage_image_read_without_format = false;
  bool multiview = false;
  bool descriptor_indexing = false;  // runtime arrays, partially bound, non-uniform sampled
  bool host_query_reset = false;
  bool geometry_shader = false;
  bool shader_output_layer = false;  // gl_Layer from vertex shaders
  bool image_cube_array = false;
  bool fill_mode_non_solid = false;
  bool multi_draw_indirect = false;
  bool shader_clip_distance = false;  // gl_ClipDistance (the atlas packs faces with it)
  bool scalar_block_layout = false;
  bool shader_draw_parameters = false;
  bool int64_buffer_atomics = false;  // shaderInt64 + shaderBufferInt64Atomics
};

struct DeviceInfo {
  std::uint32_t index = 0;
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t api_version = 0;  // what the device reports
};

struct ValidationMessage {
  VkDebugUtilsMessageSeverityFlagBitsEXT severity{};
  std::string id_name;
  std::string text;
};

// Semaphores a submission waits on / signals besides the context's timeline (binary
// semaphores of a swapchain, for instance).
struct SubmitExtras {
  std::vector<VkSemaphoreSubmitInfo> waits;
  std::vector<VkSemaphoreSubmitInfo> signals;
  VkFence fence = VK_NULL_HANDLE;
};

// Extension entry points, loaded once (nullptr where the extension is absent).
struct ExtensionFunctions {
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name = nullptr;
  PFN_vkCmdBeginDebugUtilsLabelEXT cmd_begin_label = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT cmd_end_label = nullptr;
  PFN_vkQueueInsertDebugUtilsLabelEXT queue_insert_label = nullptr;
  PFN_vkCmdPushDescriptorSetKHR cmd_push_descriptor_set = nullptr;
};

// Told of every command-buffer label a pass opens and closes (Context::begin_label), for
// timing the steps inside passes (GpuTimer's LabelScopes); on the recording thread.
class LabelListener {
 public:
  virtual ~LabelListener() = default;
  virtual void begin(VkCommandBuffer cmd, std::string_view name) = 0;
  virtual void end(VkCommandBuffer cmd) = 0;
};

class Context {
 public:
  static constexpr std::size_t kKeptValidationMessages = 64;

  // Throws NoVulkanDeviceError (no driver/device), DeviceSelectionError (no device
  // matches), ValidationLayerMissingError or VulkanError.
  explicit Context(const ContextOptions& options);
  // Borrows a host's device. Throws HostDeviceError naming every missing extension and
  // feature, std::invalid_argument for a null handle.
  explicit Context(const HostDevice& host);
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();  // waits for the device, destroys everything still queued

  [[nodiscard]] VkInstance instance() const { return instance_; }
  [[nodiscard]] VkPhysicalDevice physical_device() const { return physical_device_; }
  [[nodiscard]] VkDevice device() const { return device_; }
  [[nodiscard]] VkQueue queue() const { return queue_; }
  [[nodiscard]] std::uint32_t queue_family() const { return queue_family_; }
  [[nodiscard]] const VkPhysicalDeviceProperties& properties() const { return properties_; }
  [[nodiscard]] const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  [[nodiscard]] const std::string& device_name() const { return device_name_; }
  [[nodiscard]] bool is_cpu() const;
  // The Vulkan version in use: the device's, capped by the instance's (max_api_version).
  [[nodiscard]] std::uint32_t api_version() const { return api_version_; }
  // "Vulkan 1.3", or "Vulkan 1.2 with VK_KHR_dynamic_rendering, ..." (logs, `devices`).
  [[nodiscard]] std::string api_summary() const;
  [[nodiscard]] const DeviceFeatures& features() const { return features_; }
  [[nodiscard]] const ExtensionFunctions& ext() const { return ext_; }
  [[nodiscard]] Allocator& allocator() { return *allocator_; }
  [[nodiscard]] bool validation_enabled() const { return validation_; }
  // The device is a host's (HostDevice): never destroyed here.
  [[nodiscard]] bool borrowed() const { return borrowed_; }
  // Every physical device, in enumeration order (also listed in selection errors).
  [[nodiscard]] const std::vector<DeviceInfo>& devices() const { return devices_; }

  // Debug-utils names and labels; no-ops when VK_EXT_debug_utils is unavailable.
  void set_name(std::uint64_t handle, VkObjectType type, std::string_view name) const;
  template <class T>
  void set_name(T handle, VkObjectType type, std::string_view name) const {
    set_name(handle_bits(handle), type, name);
  }
  void begin_label(VkCommandBuffer cmd, std::string_view name,
                   std::array<float, 4> color = {0.f, 0.f, 0.f, 0.f}) const;
  void end_label(VkCommandBuffer cmd) const;
  // Labels are also reported to `listener` (nullptr: to nobody), with or without
  // VK_EXT_debug_utils. The caller keeps it alive while set.
  void set_label_listener(LabelListener* listener) { label_listener_ = listener; }

  // A debugger captures from one present to the next, and headless frames have none:
  // these ask it to start and end a capture around submissions (the queue labels
  // RenderDoc acts on). No-ops without a capture tool or VK_EXT_debug_utils.
  void begin_debugger_capture() const;
  void end_debugger_capture() const;

  // Validation-layer messages seen so far (errors and warnings, any thread).
  [[nodiscard]] std::size_t validation_error_count() const { return errors_.load(); }
  [[nodiscard]] std::size_t validation_warning_count() const { return warnings_.load(); }
  [[nodiscard]] std::vector<ValidationMessage> validation_messages() const;  // last N
  void reset_validation_counts();

  // Submission. Every submit signals the timeline with the next value and returns it.
  [[nodiscard]] VkSemaphore timeline() const { return timeline_; }
  [[nodiscard]] std::uint64_t last_submitted_value() const { return last_submitted_; }
  [[nodiscard]] std::uint64_t completed_value() const;
  // Throws VulkanError; VK_ERROR_DEVICE_LOST (real or injected) also makes device_lost() true.
  std::uint64_t submit(VkCommandBuffer cmd, const SubmitExtras& extras = {});
  [[nodiscard]] bool device_lost() const { return device_lost_; }
  void wait_for(std::uint64_t timeline_value) const;
  // A submission the host makes (docs/integration.md, "The frame"): reserves the next
  // timeline value, which the host's submit of the recorded work must signal on
  // timeline() before Antumbra submits or reserves again.
  std::uint64_t reserve_host_submission();
  // Records, submits and waits: for init-time uploads and tests, not per frame.
  void submit_immediate(const std::function<void(VkCommandBuffer)>& record);

  // Deferred destruction: the object is destroyed once the GPU has passed every
  // submission up to and including the one being recorded now.
  void destroy_deferred(VkObjectType type, std::uint64_t handle, const Allocation& allocation = {});
  void collect_garbage();  // call once per frame
  void wait_idle();        // vkDeviceWaitIdle, then destroys everything queued
  [[nodiscard]] std::size_t pending_destruction_count() const { return pending_.size(); }
  [[nodiscard]] std::uint64_t destroyed_count() const { return destroyed_count_; }

 private:
  struct PendingDestroy {
    VkObjectType type;
    std::uint64_t handle;
    Allocation allocation;
    std::uint64_t after_value;
  };

  static VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  void create_instance(const ContextOptions& options);
  void select_physical_device(const ContextOptions& options);
  void create_device(const ContextOptions& options);
  void adopt_host_device(const HostDevice& host);
  void create_messenger();
  void bind_device_functions();
  void create_own_objects();  // allocator, timeline, immediate pool
  void destroy_own_objects();
  void find_capture_tool();
  void destroy_now(const PendingDestroy& object);

  bool validation_ = false;
  bool log_validation_ = true;  // HostDevice::log_validation
  bool debug_utils_ = false;
  bool borrowed_ = false;
  std::uint32_t max_api_version_ = VK_API_VERSION_1_3;  // the instance's apiVersion
  std::uint32_t api_version_ = 0;
  bool commands_bound_ = false;  // vk_commands.hpp bound for this device
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  VkPhysicalDeviceProperties properties_{};
  std::string device_name_;
  // The graphics debugger capturing this process (RenderDoc), as the device reports it
  // among its tools; empty when there is none (begin/end_capture are no-ops then).
  std::string capture_tool_;
  DeviceFeatures features_;
  ExtensionFunctions ext_;
  std::vector<DeviceInfo> devices_;
  std::unique_ptr<Allocator> allocator_;

  VkSemaphore timeline_ = VK_NULL_HANDLE;
  std::uint64_t last_submitted_ = 0;
  std::uint64_t lose_device_at_ = 0;  // ContextOptions::lose_device_at_submission
  std::uint64_t submissions_ = 0;     // counted only while lose_device_at_ is set
  bool device_lost_ = false;
  VkCommandPool immediate_pool_ = VK_NULL_HANDLE;

  std::deque<PendingDestroy> pending_;
  std::uint64_t destroyed_count_ = 0;

  std::atomic<std::size_t> errors_{0};
  std::atomic<std::size_t> warnings_{0};
  mutable std::mutex messages_mutex_;
  LabelListener* label_listener_ = nullptr;
  std::deque<ValidationMessage> messages_;
};

// RAII debug label around a region of a command buffer.
class CommandLabel {
 public:
  CommandLabel(const Context& context, VkCommandBuffer cmd, std::string_view name,
               std::array<float, 4> color = {0.f, 0.f, 0.f, 0.f})
      : context_(context), cmd_(cmd) {
    context_.begin_label(cmd_, name, color);
  }
  CommandLabel(const CommandLabel&) = delete;
  CommandLabel& operator=(const CommandLabel&) = delete;
  ~CommandLabel() { context_.end_label(cmd_); }

 private:
  const Context& context_;
  VkCommandBuffer cmd_;
};

}  // namespace antumbra::gpu
