#include "atlas_planner.hpp"

#include <algorithm>

#include "shadow_faces.hpp"

namespace antumbra::passes {

void AtlasPlanner::invalidate() {
  contents_known_ = false;
  for (auto& layer : layers_) layer.valid = false;
}

const AtlasFrame& AtlasPlanner::plan(const scene::Scene& scene, const glm::mat4& camera_view_proj,
                                     std::uint64_t geometry_version, std::uint32_t frame_index,
                                     const AtlasSettings& settings) {
  namespace sf = shadow_faces;
  const std::uint32_t layer_count = settings.layers;
  if (layers_.size() != layer_count) {
    layers_.assign(layer_count, LayerState{});
    contents_known_ = false;
  }
  frame_ = AtlasFrame{};
  frame_.clear_all = !contents_known_;
  contents_known_ = true;
  const auto light_count =
      static_cast<std::uint32_t>(std::min<std::size_t>(scene.lights.size(), kMaxShadowLights));
  frame_.header.counts = {light_count, layer_count, settings.face_size, frame_index};
  frame_.lights.assign(light_count, ShadowLight{});
  frame_.faces.assign(layer_count, ShadowFace{});
  for (auto& face : frame_.faces) face.info = {0xFFFFFFFFu, 0u, 0u, 0u};  // unused layer

  const sf::Frustum camera = sf::camera_frustum(camera_view_proj);
  const std::uint32_t max_slots = layer_count / sf::kFaceCount;
  std::uint32_t slot = 0;
  for (std::uint32_t i = 0; i < light_count; ++i) {
    const scene::PointLight& light = scene.lights[i];
    ShadowLight& out = frame_.lights[i];
    const float near = std::min(settings.near_plane, 0.5f * light.range);
    out.position_range = glm::vec4(light.position, light.range);
    out.params = glm::vec4(light.size, near, -1.0f, 0.0f);
    if (!light.casts_shadows) continue;
    if (slot >= max_slots) {
      frame_.unshadowed.push_back(light.name);
      continue;
    }
    const std::uint32_t first = slot * sf::kFaceCount;
    out.params.z = static_cast<float>(first);
    ++slot;
    const std::uint32_t visible = settings.cull_faces
                                      ? sf::visible_faces(camera, light.position, light.range)
                                      : (1u << sf::kFaceCount) - 1u;
    const FaceKey key{light.position, light.range, near, geometry_version};
    for (std::uint32_t face = 0; face < sf::kFaceCount; ++face) {
      const std::uint32_t layer = first + face;
      LayerState& state = layers_[layer];
      ShadowFace& out_face = frame_.faces[layer];
      out_face.view_proj = sf::face_view_proj(light.position, face, near, light.range);
      out_face.info = {i, face, 0u, 0u};
      ++frame_.stats.total;
      const bool current = settings.cache && state.valid && state.key == key;
      if ((visible & (1u << face)) == 0u) {
        // Not drawn: the layer keeps whatever it held, valid only if it still matches.
        ++frame_.stats.culled;
        state.valid = state.valid && state.key == key;
        out_face.info.z = state.valid ? 1u : 0u;
        continue;
      }
      out_face.info.z = 1u;
      if (current) {
        ++frame_.stats.cached;
        continue;
      }
      ++frame_.stats.rendered;
      frame_.render_layers.push_back(layer);
      state.valid = true;
      state.key = key;
    }
  }
  // Layers no light owns this frame hold nothing useful any more.
  for (std::uint32_t layer = slot * sf::kFaceCount; layer < layer_count; ++layer) {
    layers_[layer].valid = false;
  }
  return frame_;
}

}  // namespace antumbra::passes
