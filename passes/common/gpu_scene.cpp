#include "gpu_scene.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <stdexcept>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "frame_data.hpp"

namespace antumbra::passes {
namespace {

constexpr std::uint32_t kMaxLights = 4096;

// Process-wide, so two scenes uploaded one after the other never share a version.
std::atomic<std::uint64_t> next_geometry_version{1};

template <class T>
gpu::Buffer upload_device_buffer(gpu::Context& gpu, const std::vector<T>& data,
                                 VkBufferUsageFlags usage, std::string_view name) {
  // Empty scenes still get a valid (minimal) buffer so descriptors stay valid.
  const VkDeviceSize bytes = std::max<VkDeviceSize>(sizeof(T), data.size() * sizeof(T));
  auto buffer = gpu::Buffer::create(gpu, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    gpu::MemoryUsage::gpu_only, name);
  if (!data.empty()) buffer.upload(gpu, data.data(), data.size() * sizeof(T));
  return buffer;
}

}  // namespace

GpuScene::GpuScene(gpu::Context& gpu, const scene::Scene& scene, std::uint32_t frames_in_flight)
    : gpu_(&gpu) {
  const auto geometry = merge_scene_geometry(scene);
  static_indices_ = geometry.static_indices;
  draw_ranges_ = geometry.ranges;
  static_vertices_ = geometry.static_vertices;
  dynamic_vertex_count_ = static_cast<std::uint32_t>(geometry.vertices.size()) - static_vertices_;
  for (const std::size_t m : merge_order(scene)) {
    const scene::Mesh& mesh = scene.meshes[m];
    if (!mesh.dynamic) continue;
    dynamic_.push_back({m, mesh.transform, mesh.bounds});
    dynamic_bounds_.push_back(mesh.bounds);
  }
  vertices_ = upload_device_buffer(
      gpu, geometry.vertices,
      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "scene.vertices");
  attributes_ =
      upload_device_buffer(gpu, geometry.attributes,
                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                           "scene.vertexAttributes");
  textures_ = SceneTextures(gpu, scene);
  indices_ = upload_device_buffer(
      gpu, geometry.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
      "scene.indices");
  index_count_ = static_cast<std::uint32_t>(geometry.indices.size());
  alpha_tested_ = std::any_of(scene.materials.begin(), scene.materials.end(),
                              [](const scene::Material& m) { return m.alpha_tested(); });
  textured_ = scene_textured(scene);
  emits_ = scene_emits(scene);
  geometry_version_ = next_geometry_version.fetch_add(1);
  materials_ = upload_device_buffer(gpu, build_materials(scene, textures_.plan()),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "scene.materials");
  for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
    Slot slot;
    slot.uniforms =
        gpu::Buffer::create(gpu, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                            gpu::MemoryUsage::upload, "frame.uniforms." + std::to_string(i));
    slot.lights =
        gpu::Buffer::create(gpu, sizeof(GpuLight) * kMaxLights, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            gpu::MemoryUsage::upload, "frame.lights." + std::to_string(i));
    if (dynamic_vertex_count_ > 0) {
      slot.dynamic_vertices =
          gpu::Buffer::create(gpu, VkDeviceSize{dynamic_vertex_count_} * sizeof(GpuVertex),
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::upload,
                              "scene.dynamicVertices.staging." + std::to_string(i));
      slot.dynamic_attributes = gpu::Buffer::create(
          gpu, VkDeviceSize{dynamic_vertex_count_} * sizeof(GpuVertexAttributes),
          VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::upload,
          "scene.dynamicAttributes.staging." + std::to_string(i));
    }
    slots_.push_back(std::move(slot));
  }
}

void GpuScene::upload_dynamic(gpu::Context& gpu, VkCommandBuffer cmd, Slot& slot,
                              const scene::Scene& scene) {
  moved_bounds_.clear();
  bool moved = false;
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    DynamicMesh& d = dynamic_[i];
    const scene::Mesh& mesh = scene.meshes.at(d.mesh);
    if (mesh.transform == d.transform) continue;
    moved_bounds_.push_back(d.bounds);
    moved_bounds_.push_back(mesh.bounds);
    d.transform = mesh.transform;
    d.bounds = mesh.bounds;
    dynamic_bounds_[i] = mesh.bounds;
    moved = true;
  }
  if (!moved) return;
  ++dynamic_version_;
  dynamic_scratch_.clear();
  dynamic_attribute_scratch_.clear();
  for (const DynamicMesh& d : dynamic_) {
    append_world_vertices(scene.meshes[d.mesh], dynamic_scratch_, &dynamic_attribute_scratch_);
  }
  const VkDeviceSize bytes = dynamic_scratch_.size() * sizeof(GpuVertex);
  std::memcpy(slot.dynamic_vertices.mapped(), dynamic_scratch_.data(), bytes);
  const VkDeviceSize attribute_bytes =
      dynamic_attribute_scratch_.size() * sizeof(GpuVertexAttributes);
  std::memcpy(slot.dynamic_attributes.mapped(), dynamic_attribute_scratch_.data(), attribute_bytes);
  // Earlier frames may still read the range (vertex input, storage reads): every
  // stage waits, as for any in-place rewrite of shared data.
  gpu.begin_label(cmd, "scene.moveDynamic");
  for (const VkBuffer target : {vertices_.handle(), attributes_.handle()}) {
    gpu::buffer_barrier(cmd, target, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  }
  const VkBufferCopy region{0, VkDeviceSize{static_vertices_} * sizeof(GpuVertex), bytes};
  vkCmdCopyBuffer(cmd, slot.dynamic_vertices, vertices_, 1, &region);
  const VkBufferCopy attribute_region{
      0, VkDeviceSize{static_vertices_} * sizeof(GpuVertexAttributes), attribute_bytes};
  vkCmdCopyBuffer(cmd, slot.dynamic_attributes, attributes_, 1, &attribute_region);
  for (const VkBuffer target : {vertices_.handle(), attributes_.handle()}) {
    gpu::buffer_barrier(cmd, target, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
  }
  gpu.end_label(cmd);
}

fgvk::FrameResources GpuScene::update(VkCommandBuffer cmd, std::uint32_t slot_index,
                                      const scene::Scene& scene, VkExtent2D viewport,
                                      std::uint64_t frame_index) {
  if (scene.lights.size() > kMaxLights) {
    throw std::runtime_error("the scene has " + std::to_string(scene.lights.size()) +
                             " lights; at most " + std::to_string(kMaxLights) + " are supported");
  }
  auto& slot = slots_.at(slot_index);
  if (!dynamic_.empty()) upload_dynamic(*gpu_, cmd, slot, scene);
  // The emits flag the G-buffer follows (FrameResources::emits, from the uploaded
  // materials), so the lighting passes never read a target the G-buffer did not write.
  const auto uniforms = build_frame_uniforms(scene, viewport.width, viewport.height,
                                             static_cast<std::uint32_t>(frame_index), emits_);
  std::memcpy(slot.uniforms.mapped(), &uniforms, sizeof uniforms);
  const auto lights = build_lights(scene, uniforms.view);
  if (!lights.empty())
    std::memcpy(slot.lights.mapped(), lights.data(), lights.size() * sizeof(GpuLight));

  fgvk::FrameResources frame;
  frame.frame_uniforms = slot.uniforms;
  frame.frame_uniforms_size = sizeof(FrameUniforms);
  frame.lights = slot.lights;
  frame.lights_size = slot.lights.size();
  frame.light_count = static_cast<std::uint32_t>(lights.size());
  frame.materials = materials_;
  frame.materials_size = materials_.size();
  frame.vertices = vertices_;
  frame.vertex_attributes = attributes_;
  frame.srgb_textures = textures_.srgb_views();
  frame.linear_textures = textures_.linear_views();
  frame.texture_sampler = textures_.sampler();
  frame.alpha_tested = alpha_tested_;
  frame.textured = textured_;
  frame.emits = emits_;
  frame.indices = indices_;
  frame.index_count = index_count_;
  frame.geometry_version = geometry_version_;
  frame.static_index_count = static_indices_;
  frame.draw_ranges = draw_ranges_;
  frame.dynamic_version = dynamic_version_;
  frame.moved_bounds = &moved_bounds_;
  frame.dynamic_bounds = &dynamic_bounds_;
  frame.viewport = viewport;
  frame.scene = &scene;
  frame.frame_index = frame_index;
  frame.slot = slot_index;
  frame.frames_in_flight = static_cast<std::uint32_t>(slots_.size());
  return frame;
}

}  // namespace antumbra::passes
