#pragma once
// VkPipelineCache persisted to disk: loaded at start when the file's header matches
// this device (vendor, device id, pipelineCacheUUID), saved by save() or at
// destruction. A stale or foreign file is ignored, never passed to the driver.

#include <cstddef>
#include <filesystem>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"

namespace antumbra::gpu {

class PipelineCache {
 public:
  // `path` empty: <ShaderCompiler::default_cache_dir()>/../pipeline-<vendor>-<device>.bin
  PipelineCache(Context& context, std::filesystem::path path = {});
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;
  ~PipelineCache();  // saves (errors are logged, not thrown)

  [[nodiscard]] VkPipelineCache handle() const { return cache_; }
  operator VkPipelineCache() const { return cache_; }  // NOLINT(google-explicit-constructor)
  [[nodiscard]] bool loaded_from_disk() const { return loaded_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  bool save() const;  // false when the file could not be written

  // True when `data` starts with a pipeline cache header made by this device.
  static bool header_matches(const std::vector<std::byte>& data,
                             const VkPhysicalDeviceProperties& properties);

 private:
  Context& context_;
  std::filesystem::path path_;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
  bool loaded_ = false;
};

}  // namespace antumbra::gpu
