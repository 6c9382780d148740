#include "antumbra/gpu/pipeline_cache.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "antumbra/gpu/shader_compiler.hpp"

namespace antumbra::gpu {

namespace fs = std::filesystem;

namespace {

std::vector<std::byte> read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return {};
  std::vector<std::byte> data(static_cast<std::size_t>(file.tellg()));
  file.seekg(0);
  file.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size()));
  if (!file) return {};
  return data;
}

}  // namespace

bool PipelineCache::header_matches(const std::vector<std::byte>& data,
                                   const VkPhysicalDeviceProperties& properties) {
  VkPipelineCacheHeaderVersionOne header{};
  if (data.size() < sizeof(header)) return false;
  std::memcpy(&header, data.data(), sizeof(header));
  return header.headerSize >= sizeof(header) &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE &&
         header.vendorID == properties.vendorID && header.deviceID == properties.deviceID &&
         std::memcmp(header.pipelineCacheUUID, properties.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

PipelineCache::PipelineCache(Context& context, fs::path path)
    : context_(context), path_(std::move(path)) {
  if (path_.empty()) {
    std::ostringstream name;
    name << "pipeline-" << std::hex << context.properties().vendorID << "-"
         << context.properties().deviceID << ".bin";
    path_ = ShaderCompiler::default_cache_dir().parent_path() / name.str();
  }
  std::vector<std::byte> data = read_file(path_);
  if (!data.empty() && !header_matches(data, context.properties())) {
    spdlog::info("pipeline cache {} was made by another device or driver; ignoring it",
                 path_.string());
    data.clear();
  }
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  check(vkCreatePipelineCache(context.device(), &info, nullptr, &cache_), "vkCreatePipelineCache");
  loaded_ = !data.empty();
  context.set_name(cache_, VK_OBJECT_TYPE_PIPELINE_CACHE, "pipeline_cache");
}

PipelineCache::~PipelineCache() {
  save();
  // Pipelines created from the cache do not reference it: safe to destroy now, but
  // the deferred queue keeps the rule "one way to destroy" simple.
  context_.destroy_deferred(VK_OBJECT_TYPE_PIPELINE_CACHE, handle_bits(cache_));
}

bool PipelineCache::save() const {
  try {
    std::size_t size = 0;
    check(vkGetPipelineCacheData(context_.device(), cache_, &size, nullptr),
          "vkGetPipelineCacheData");
    std::vector<std::byte> data(size);
    check(vkGetPipelineCacheData(context_.device(), cache_, &size, data.data()),
          "vkGetPipelineCacheData");
    data.resize(size);
    std::error_code error;
    fs::create_directories(path_.parent_path(), error);
    const fs::path temp = path_.string() + ".tmp";
    {
      std::ofstream file(temp, std::ios::binary | std::ios::trunc);
      if (!file) return false;
      file.write(reinterpret_cast<const char*>(data.data()),
                 static_cast<std::streamsize>(data.size()));
      if (!file) return false;
    }
    fs::rename(temp, path_, error);
    return !error;
  } catch (const std::exception& e) {
    spdlog::warn("pipeline cache save failed: {}", e.what());
    return false;
  }
}

}  // namespace antumbra::gpu
