#include "atlas_planner.hpp"

#include <algorithm>
#include <cmath>

#include "common/light_faces.hpp"
#include "common/shadow_faces.hpp"

namespace antumbra::passes {

void AtlasPlanner::invalidate() {
  contents_known_ = false;
  for (auto& layer : layers_) layer.valid = false;
}

namespace {

// The light as the shaders read it, before the planner gives it layers (params.z) and
// fits the sun's box.
ShadowLight shadow_light(const scene::PointLight& light, float range, float near) {
  ShadowLight out{};
  out.position_range = glm::vec4(light.position, range);
  out.params = glm::vec4(light.size, near, -1.0f, 0.0f);
  out.direction_type = glm::vec4(light.direction, kLightTypePoint);
  if (light.type == scene::LightType::spot) {
    out.direction_type.w = kLightTypeSpot;
    out.projection.x = light_faces::spot_tan_half_fov(light.spot_outer);
  } else if (light.type == scene::LightType::directional) {
    // Sun size is an angular radius in degrees; penumbrae use its tangent.
    out.direction_type.w = kLightTypeDirectional;
    out.params = glm::vec4(std::tan(glm::radians(light.size)), 0.0f, -1.0f, 0.0f);
  }
  return out;
}

}  // namespace

const AtlasFrame& AtlasPlanner::plan(const scene::Scene& scene, const glm::mat4& camera_view_proj,
                                     std::uint64_t geometry_version, std::uint32_t frame_index,
                                     const AtlasSettings& settings) {
  namespace sf = shadow_faces;
  namespace lf = light_faces;
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
  frame_.epochs.assign(layer_count, 0u);
  for (auto& face : frame_.faces) face.info = {0xFFFFFFFFu, 0u, 0u, 0u};  // unused layer

  const sf::Frustum camera = sf::camera_frustum(camera_view_proj);
  std::uint32_t next_layer = 0;
  for (std::uint32_t i = 0; i < light_count; ++i) {
    const scene::PointLight& light = scene.lights[i];
    ShadowLight& out = frame_.lights[i];
    const bool directional = light.type == scene::LightType::directional;
    const float range = directional ? 0.0f : light.range;
    const float near = std::min(settings.near_plane, 0.5f * range);
    out = shadow_light(light, range, near);
    if (!light.casts_shadows) continue;
    const std::uint32_t face_count = light.type == scene::LightType::point ? sf::kFaceCount : 1u;
    if (next_layer + face_count > layer_count) {
      frame_.unshadowed.push_back(light.name);
      continue;
    }
    const std::uint32_t first = next_layer;
    next_layer += face_count;
    out.params.z = static_cast<float>(first);
    const std::uint32_t resolution = light_resolution(light, first, settings);
    out.projection.y = static_cast<float>(resolution);
    out.projection.z = static_cast<float>(resolution) / static_cast<float>(settings.face_size);
    std::uint32_t visible = (1u << face_count) - 1u;
    if (light.type == scene::LightType::point) {
      if (settings.cull_faces) visible = sf::visible_faces(camera, light.position, light.range);
    } else if (light.type == scene::LightType::spot) {
      if (settings.cull_faces && !lf::spot_may_be_visible(camera, light)) {
        visible = 0u;
      }
    } else {
      // The sun's box follows the camera: fitted anew every frame.
      const lf::DirectionalFit fit = lf::fit_directional(
          light.direction, camera_view_proj, settings.camera_near, settings.camera_far,
          settings.sun_max_distance, scene.bounds, static_cast<float>(settings.face_size));
      out.position_range = glm::vec4(fit.near_point, fit.depth);
      out.projection.x = fit.half_width;
      frame_.faces[first].view_proj = fit.view_proj;
    }
    for (std::uint32_t face = 0; face < face_count; ++face) {
      const std::uint32_t layer = first + face;
      ShadowFace& out_face = frame_.faces[layer];
      if (light.type == scene::LightType::point) {
        out_face.view_proj = sf::face_view_proj(light.position, face, near, light.range);
      } else if (light.type == scene::LightType::spot) {
        out_face.view_proj =
            lf::spot_view_proj(light.position, light.direction, out.projection.x, near, range);
      }
      out_face.info = {i, face, 0u, 0u};
      plan_layer(layer, (visible & (1u << face)) != 0u,
                 FaceKey{out_face.view_proj, geometry_version, resolution}, settings);
    }
  }
  // Layers no light owns this frame hold nothing useful any more.
  for (std::uint32_t layer = next_layer; layer < layer_count; ++layer) {
    layers_[layer].valid = false;
  }
  return frame_;
}

std::uint32_t AtlasPlanner::light_resolution(const scene::PointLight& light,
                                             std::uint32_t first_layer,
                                             const AtlasSettings& settings) {
  if (!settings.adaptive_resolution || light.type == scene::LightType::directional) {
    return settings.face_size;  // the sun's map follows the camera frustum, not a size
  }
  ResolutionSettings r = settings.resolution;
  r.maximum = settings.face_size;
  const float wanted = projected_radius(light.position, light.range, r) * r.scale;
  LayerState& state = layers_[first_layer];
  state.resolution = choose_resolution(wanted, state.resolution, r);
  return state.resolution;
}

// Static caching: a visible face is drawn only when its layer does not hold it already.
void AtlasPlanner::plan_layer(std::uint32_t layer, bool visible, const FaceKey& key,
                              const AtlasSettings& settings) {
  ++frame_.stats.total;
  if (settings.gpu_decides) {
    plan_candidate(layer, visible, key, settings.cache);
    return;
  }
  LayerState& state = layers_[layer];
  ShadowFace& out_face = frame_.faces[layer];
  const bool current = settings.cache && state.valid && state.key == key;
  if (!visible) {
    // Not drawn: the layer keeps whatever it held, valid only if it still matches.
    ++frame_.stats.culled;
    if (state.valid && state.key != key) {
      state.valid = false;
      state.epoch = next_epoch_++;  // what it holds is no longer this face
    }
    out_face.info.z = state.valid ? 1u : 0u;
    frame_.epochs[layer] = state.epoch;
    return;
  }
  out_face.info.z = 1u;
  if (current) {
    ++frame_.stats.cached;
    frame_.epochs[layer] = state.epoch;
    return;
  }
  ++frame_.stats.rendered;
  frame_.stats.texels += std::uint64_t{key.resolution} * key.resolution;
  frame_.render_layers.push_back(layer);
  out_face.info.w = 1u;  // consumers that cache derived data redo this layer
  state.valid = true;
  state.key = key;
  state.epoch = next_epoch_++;
  frame_.epochs[layer] = state.epoch;
}

// The GPU keeps what each layer holds (its epoch) and draws a candidate only where a
// visible pixel needs it and the epoch differs; info.z/w are its to write.
void AtlasPlanner::plan_candidate(std::uint32_t layer, bool visible, const FaceKey& key,
                                  bool cache) {
  LayerState& state = layers_[layer];
  if (!(state.valid && state.key == key) || !cache) {
    state.valid = true;
    state.key = key;
    state.epoch = next_epoch_++;
  }
  frame_.epochs[layer] = state.epoch;
  if (!visible) {
    ++frame_.stats.culled;
    return;
  }
  ++frame_.stats.candidates;
  frame_.render_layers.push_back(layer);
}

}  // namespace antumbra::passes
