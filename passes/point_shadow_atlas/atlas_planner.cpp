#include "atlas_planner.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <set>

#include "common/light_faces.hpp"
#include "common/shadow_faces.hpp"
#include "pages.h"

namespace antumbra::passes {

void AtlasPlanner::invalidate() {
  contents_known_ = false;
  for (auto& layer : layers_) {
    layer.valid = false;
    layer.shown = false;
    layer.cache_valid = false;
    layer.dynamic_dirty = false;
    layer.dirty_pages.clear();
  }
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

std::uint32_t face_size(const AtlasFrame& frame, std::uint32_t slot) {
  const std::uint32_t atlas = frame.header.counts.z;
  const std::uint32_t light = slot < frame.faces.size() ? frame.faces[slot].info.x : ~0u;
  if (light < frame.lights.size() && frame.lights[light].projection.y > 0.0f) {
    return std::min(static_cast<std::uint32_t>(frame.lights[light].projection.y), atlas);
  }
  return atlas;
}

FaceSquare face_square(const AtlasFrame& frame, std::uint32_t slot) {
  const FacePlace place = face_place(frame.faces.at(slot));
  const std::uint32_t size = face_size(frame, slot);
  return {.layer = place.layer, .origin = place.cell * size, .size = size};
}

const AtlasFrame& AtlasPlanner::plan(const scene::Scene& scene, const glm::mat4& camera_view_proj,
                                     std::uint64_t geometry_version, std::uint32_t frame_index,
                                     const AtlasSettings& settings, const SceneMotion& motion) {
  begin_frame(scene, frame_index, settings);
  mark_dynamic(motion, settings);
  claim_lights(scene, settings);
  place_claims(scene, settings);
  work_.clear();
  for (const Claim& claim : claims_) {
    if (claim.given == 0) continue;
    LightWork work;
    wish_light(scene, claim, camera_view_proj, geometry_version, settings, work);
    work_.push_back(work);
  }
  apply_budget(settings);
  for (const LightWork& work : work_) {
    if (work.update) {
      plan_light(scene, work, geometry_version, settings, motion);
    } else {
      keep_light(work);
    }
  }
  const PackerStats packed = packer_.stats(owned_end_);
  frame_.stats.layers_used = packed.layers_used;
  frame_.stats.texels_held = packed.texels;
  return frame_;
}

void AtlasPlanner::begin_frame(const scene::Scene& scene, std::uint32_t frame_index,
                               const AtlasSettings& settings) {
  const std::uint32_t records = std::max(settings.records, settings.layers);
  if (layers_.size() != records || packer_.records() != records ||
      packer_.layer_size() != settings.face_size || packer_.shares() != settings.pack ||
      !contents_known_) {
    layers_.assign(records, LayerState{});
    packer_.reset(settings.layers, settings.face_size, records, settings.pack);
    contents_known_ = false;
  }
  const std::uint32_t pages_side =
      (settings.face_size + shared::kPageSize - 1) >> shared::kPageShift;
  const std::uint32_t stride = settings.page_pool ? pages_side * pages_side : 0u;
  // The last frame's records, kept: only those some light owned need resetting (an
  // unowned record's place names its table, so a new stride resets them all).
  std::vector<ShadowFace> faces = std::move(frame_.faces);
  std::vector<std::uint32_t> epochs = std::move(frame_.epochs);
  std::uint32_t reset_end = std::min(owned_end_, records);
  if (faces.size() != records || !contents_known_ || stride != table_stride_) {
    faces.assign(records, ShadowFace{});
    epochs.assign(records, 0u);
    reset_end = records;
    owned_end_ = 0;  // a new layout: nothing is owned
  }
  table_stride_ = stride;
  frame_ = AtlasFrame{};
  frame_.clear_all = !contents_known_;
  contents_known_ = true;
  const auto light_count =
      static_cast<std::uint32_t>(std::min<std::size_t>(scene.lights.size(), kMaxShadowLights));
  frame_.header.counts = {light_count, records, settings.face_size, frame_index};
  frame_.lights.assign(light_count, ShadowLight{});
  frame_.faces = std::move(faces);
  frame_.epochs = std::move(epochs);
  for (std::uint32_t record = 0; record < reset_end; ++record) {  // until a light owns it
    frame_.faces[record] = ShadowFace{};
    frame_.faces[record].info = {0xFFFFFFFFu, face_info_y(0u, record), 0u, 0u};
    frame_.epochs[record] = 0u;
  }
}

// Layers whose contents a dynamic mesh entered or left are stale: with the GPU's
// decision only the pages inside its old and new bounds (dirty_pages.hpp), else the face.
void AtlasPlanner::mark_dynamic(const SceneMotion& motion, const AtlasSettings& settings) {
  if (motion.moved.empty()) return;
  // Records past owned_end_ are released: nothing valid to mark.
  const std::size_t end = std::min<std::size_t>(owned_end_, layers_.size());
  for (std::size_t i = 0; i < end; ++i) {
    LayerState& state = layers_[i];
    if (!state.valid || state.dynamic_dirty) continue;
    const std::uint32_t pages_x =
        (state.key.resolution + shared::kPageSize - 1u) >> shared::kPageShift;
    for (const scene::Aabb& box : motion.moved) {
      if (!shadow_faces::box_may_touch(state.key.view_proj, box)) continue;
      if (!settings.gpu_decides) {
        state.dynamic_dirty = true;
        break;
      }
      const PageRect rect = box_pages(state.key.view_proj, state.key.resolution, box);
      if (rect.empty()) continue;
      state.dirty_pages.resize((pages_x * pages_x + 31u) / 32u, 0u);
      rect.mark(pages_x, state.dirty_pages);
    }
  }
}

void AtlasPlanner::claim_lights(const scene::Scene& scene, const AtlasSettings& settings) {
  namespace lf = light_faces;
  claims_.clear();
  const auto records = static_cast<std::uint32_t>(layers_.size());
  std::uint32_t next = 0;
  for (std::uint32_t i = 0; i < frame_.header.counts.x; ++i) {
    const scene::PointLight& light = scene.lights[i];
    const bool directional = light.type == scene::LightType::directional;
    const float range = directional ? 0.0f : light.range;
    frame_.lights[i] = shadow_light(light, range, std::min(settings.near_plane, 0.5f * range));
    if (!light.casts_shadows) continue;
    std::uint32_t faces = light.type == scene::LightType::point ? shadow_faces::kFaceCount : 1u;
    if (directional) {
      // As many cascades as fit, at least one: a full atlas costs the far cascades first.
      const std::uint32_t left = records > next ? records - next : 0u;
      faces = std::clamp(std::min(settings.sun_cascades, left), 1u,
                         static_cast<std::uint32_t>(lf::kMaxCascades));
    }
    if (next + faces > records) {
      frame_.unshadowed.push_back(light.name);
      continue;
    }
    claims_.push_back({.light = i,
                       .first = next,
                       .faces = faces,
                       .wanted = light_resolution(light, next, settings)});
    next += faces;
  }
  // Records no light owns this frame hold nothing useful any more (those past the last
  // frame's owned ones were released then).
  for (std::uint32_t record = next; record < std::min(owned_end_, records); ++record) {
    layers_[record].valid = false;
    layers_[record].shown = false;
    layers_[record].owner.clear();
    packer_.release(record);
  }
  frame_.live_records = frame_.clear_all ? records : std::max(std::min(owned_end_, records), next);
  owned_end_ = next;
}

namespace {

// The next face size below `size` that the packer takes (a power of two).
std::uint32_t smaller_size(std::uint32_t size) {
  return std::has_single_bit(size) ? size / 2 : std::bit_floor(size);
}

// A size's class in fit_sizes: its log2, one above for a layer size that is no power of
// two (it is the largest size, so nothing else takes that class).
int size_class(std::uint32_t size) {
  return std::bit_width(size) + (std::has_single_bit(size) || size == 0 ? 0 : 1);
}

}  // namespace

// Face sizes that fit the atlas together: each claim's wanted size while the squares of
// every size class fill no more layers than there are; else the largest squares halve
// first (the last claim of a size before earlier ones), so that a full atlas gives every
// light smaller faces instead of some lights none. Claims left at 0 do not fit even at
// the smallest size.
std::vector<std::uint32_t> AtlasPlanner::fit_sizes(const AtlasSettings& settings,
                                                   std::uint32_t smallest) const {
  std::vector<std::uint32_t> sizes;
  sizes.reserve(claims_.size());
  // Per size class (its log2): the claims holding it and their faces.
  constexpr int kClasses = 32;
  std::array<std::set<std::size_t>, kClasses> members;
  std::array<std::uint64_t, kClasses> faces{};
  for (std::size_t i = 0; i < claims_.size(); ++i) {
    sizes.push_back(claims_[i].wanted);
    const int c = size_class(claims_[i].wanted);
    members[c].insert(i);
    faces[c] += claims_[i].faces;
  }
  const auto layers_needed = [&] {
    std::uint64_t layers = 0;
    for (int c = 0; c < kClasses; ++c) {
      if (faces[c] == 0) continue;
      const std::uint64_t per_layer = packer_.squares_per_layer(sizes[*members[c].begin()]);
      layers += (faces[c] + per_layer - 1) / std::max<std::uint64_t>(per_layer, 1);
    }
    return layers;
  };
  while (layers_needed() > settings.layers) {
    int c = kClasses - 1;
    while (c > 0 && members[c].empty()) --c;
    if (members[c].empty()) break;
    const std::size_t i = *members[c].rbegin();
    members[c].erase(i);
    faces[c] -= claims_[i].faces;
    if (sizes[i] <= smallest) {
      // Every claim is at the smallest size: the last ones go without.
      sizes[i] = 0;
      continue;
    }
    sizes[i] = smaller_size(sizes[i]);
    const int down = size_class(sizes[i]);
    members[down].insert(i);
    faces[down] += claims_[i].faces;
  }
  return sizes;
}

std::uint32_t AtlasPlanner::face_info_y(std::uint32_t face, std::uint32_t slot) const {
  if (table_stride_ == 0) return encode_face_info(face, place_of(slot));
  return (slot * table_stride_) << ANTUMBRA_FACE_LAYER_SHIFT | face;
}

void AtlasPlanner::size_pool_claims(const scene::Scene& scene, const AtlasSettings& settings) {
  for (Claim& claim : claims_) {
    claim.given = settings.pool_cap > 0 ? std::min(claim.wanted, settings.pool_cap) : claim.wanted;
    const std::string& name = scene.lights[claim.light].name;
    if (claim.given == 0) {
      frame_.unshadowed.push_back(name);
    } else if (claim.given < claim.wanted) {
      frame_.degraded.push_back({.name = name, .wanted = claim.wanted, .given = claim.given});
    }
  }
}

void AtlasPlanner::place_claims(const scene::Scene& scene, const AtlasSettings& settings) {
  if (settings.page_pool) {
    size_pool_claims(scene, settings);
    return;
  }
  const std::uint32_t smallest =
      std::max(FacePacker::smallest(settings.face_size), std::min(16u, settings.face_size));
  const std::vector<std::uint32_t> sizes = fit_sizes(settings, smallest);
  // Claims whose squares are not of their size give them up first, so that every claim
  // placed below sees all the room there is.
  std::vector<Claim*> pending;
  std::vector<std::pair<FacePlace, std::uint32_t>> before(layers_.size());
  for (std::size_t i = 0; i < claims_.size(); ++i) {
    Claim& claim = claims_[i];
    claim.given = sizes[i];
    const scene::PointLight& light = scene.lights[claim.light];
    bool keep = claim.given != 0 && layers_[claim.first].owner == light.name;
    for (std::uint32_t f = 0; f < claim.faces; ++f) {
      const std::uint32_t record = claim.first + f;
      keep = keep && packer_.size_of(record) == claim.given;
      before[record] = {place_of(record), packer_.size_of(record)};
    }
    if (keep) continue;
    for (std::uint32_t f = 0; f < claim.faces; ++f) packer_.release(claim.first + f);
    if (claim.given != 0) pending.push_back(&claim);
  }
  for (Claim* claim : pending) {
    // Squares scattered by earlier frames may leave less room than the fit counted:
    // smaller still, then.
    const std::uint32_t fitted = claim->given;
    claim->given = 0;
    for (std::uint32_t size = fitted; size >= smallest && claim->given == 0;
         size = smaller_size(size)) {
      std::uint32_t placed = 0;
      while (placed < claim->faces && packer_.place(claim->first + placed, size)) ++placed;
      if (placed == claim->faces) {
        claim->given = size;
      } else {
        for (std::uint32_t f = 0; f < placed; ++f) packer_.release(claim->first + f);
      }
    }
    for (std::uint32_t f = 0; f < claim->faces; ++f) {
      const std::uint32_t record = claim->first + f;
      claim->moved =
          claim->moved || before[record] != std::pair{place_of(record), packer_.size_of(record)};
    }
  }
  for (const Claim& claim : claims_) {
    const std::string& name = scene.lights[claim.light].name;
    if (claim.given == 0) {
      frame_.unshadowed.push_back(name);
    } else if (claim.given < claim.wanted) {
      frame_.degraded.push_back({.name = name, .wanted = claim.wanted, .given = claim.given});
    }
  }
}

void AtlasPlanner::wish_light(const scene::Scene& scene, const Claim& claim,
                              const glm::mat4& camera_view_proj, std::uint64_t geometry_version,
                              const AtlasSettings& settings, LightWork& work) {
  namespace sf = shadow_faces;
  namespace lf = light_faces;
  const std::uint32_t i = claim.light;
  const scene::PointLight& light = scene.lights[i];
  ShadowLight& out = frame_.lights[i];
  const std::uint32_t face_count = claim.faces;
  const float near = out.params.y;
  const float range = out.position_range.w;
  work = {.light = i, .first = claim.first, .faces = face_count};
  out.params.z = static_cast<float>(work.first);
  work.resolution = claim.given;
  out.projection.y = static_cast<float>(work.resolution);
  out.projection.z = static_cast<float>(work.resolution) / static_cast<float>(settings.face_size);
  if (settings.page_pool) out.projection.z = -1.0f;  // paged: no square (page_tables.h)
  const sf::Frustum camera = sf::camera_frustum(camera_view_proj);
  work.visible = (1u << face_count) - 1u;
  if (light.type == scene::LightType::point) {
    if (settings.cull_faces) work.visible = sf::visible_faces(camera, light.position, light.range);
  } else if (light.type == scene::LightType::spot) {
    if (settings.cull_faces && !lf::spot_may_be_visible(camera, light)) work.visible = 0u;
  } else {
    // The sun's boxes follow the camera: fitted anew every frame.
    const std::vector<lf::DirectionalFit> fits = lf::fit_cascades(
        light.direction, camera_view_proj, settings.camera_near, settings.camera_far,
        {.count = static_cast<int>(face_count),
         .lambda = settings.sun_lambda,
         .max_distance = settings.sun_max_distance},
        scene.bounds, static_cast<float>(settings.face_size));
    out.position_range = glm::vec4(fits.front().near_point, fits.front().depth);
    out.projection.x = fits.front().half_width;
    out.projection.w = encode_cascades(face_count, settings.sun_blend);
    for (std::uint32_t c = 0; c < face_count; ++c) {
      frame_.faces[work.first + c].view_proj = fits[c].view_proj;
    }
  }
  const LayerState& head = layers_[work.first];
  const bool directional = light.type == scene::LightType::directional;
  // Squares placed anew hold nothing of the light: it cannot wait for the budget.
  work.must = directional || !settings.cache || head.owner != light.name ||
              head.waited >= settings.max_stale || claim.moved;
  for (std::uint32_t face = 0; face < face_count; ++face) {
    const std::uint32_t layer = work.first + face;
    ShadowFace& out_face = frame_.faces[layer];
    if (light.type == scene::LightType::point) {
      out_face.view_proj = sf::face_view_proj(light.position, face, near, light.range);
    } else if (light.type == scene::LightType::spot) {
      out_face.view_proj =
          lf::spot_view_proj(light.position, light.direction, out.projection.x, near, range);
    }
    out_face.info = {i, face_info_y(face, layer), 0u, 0u};
    const LayerState& state = layers_[layer];
    const bool holds = state.valid && state.key == face_key(layer, geometry_version, work);
    const bool dirty = state.dynamic_dirty || !state.dirty_pages.empty();
    if ((work.visible & (1u << face)) != 0u && (!holds || dirty)) {
      work.needed |= 1u << face;
      // Nothing of this face can be shown while it waits.
      if (!(state.valid && state.shown)) work.must = true;
    }
  }
  work.priority =
      directional ? 0.0f : projected_radius(light.position, light.range, settings.resolution);
}

// Lights that must be drawn take the budget first, then the longest waiting and the
// largest on screen, while their faces fit.
void AtlasPlanner::apply_budget(const AtlasSettings& settings) {
  std::uint64_t used = 0;
  std::vector<LightWork*> optional;
  for (LightWork& work : work_) {
    const auto faces = static_cast<std::uint32_t>(std::popcount(work.needed));
    if (work.must || faces == 0) {
      used += faces;
    } else {
      optional.push_back(&work);
    }
  }
  frame_.stats.forced =
      static_cast<std::uint32_t>(used > settings.face_budget ? used - settings.face_budget : 0u);
  std::stable_sort(optional.begin(), optional.end(), [&](const LightWork* a, const LightWork* b) {
    const std::uint32_t wa = layers_[a->first].waited;
    const std::uint32_t wb = layers_[b->first].waited;
    return wa != wb ? wa > wb : a->priority > b->priority;
  });
  for (LightWork* work : optional) {
    const auto faces = static_cast<std::uint32_t>(std::popcount(work->needed));
    if (used + faces <= settings.face_budget) {
      used += faces;
    } else {
      work->update = false;
    }
  }
}

void AtlasPlanner::keep_light(const LightWork& work) {
  LayerState& head = layers_[work.first];
  ++head.waited;
  frame_.stats.stalest = std::max(frame_.stats.stalest, head.waited);
  frame_.stats.deferred += static_cast<std::uint32_t>(std::popcount(work.needed));
  frame_.lights[work.light] = head.shown_light;
  for (std::uint32_t face = 0; face < work.faces; ++face) {
    const std::uint32_t layer = work.first + face;
    const LayerState& state = layers_[layer];
    ShadowFace& out_face = frame_.faces[layer];
    out_face.view_proj = state.key.view_proj;
    out_face.info = {work.light, face_info_y(face, layer), state.valid && state.shown ? 1u : 0u,
                     0u};
    frame_.epochs[layer] = state.epoch;
    ++frame_.stats.total;
    if ((work.visible & (1u << face)) != 0u) {
      ++frame_.stats.cached;
    } else {
      ++frame_.stats.culled;
    }
  }
}

void AtlasPlanner::plan_light(const scene::Scene& scene, const LightWork& work,
                              std::uint64_t geometry_version, const AtlasSettings& settings,
                              const SceneMotion& motion) {
  LayerState& head = layers_[work.first];
  head.owner = scene.lights[work.light].name;
  head.waited = 0;
  head.shown_light = frame_.lights[work.light];
  const bool cacheable =
      settings.static_cache && settings.cache &&
      !(work.light < settings.uncached_lights.size() && settings.uncached_lights[work.light]);
  for (std::uint32_t face = 0; face < work.faces; ++face) {
    const std::uint32_t layer = work.first + face;
    plan_layer(layer, (work.visible & (1u << face)) != 0u, face_key(layer, geometry_version, work),
               settings, cacheable, motion);
  }
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
                              const AtlasSettings& settings, bool cacheable,
                              const SceneMotion& motion) {
  ++frame_.stats.total;
  if (settings.gpu_decides) {
    plan_candidate(layer, visible, key, settings.cache);
    return;
  }
  LayerState& state = layers_[layer];
  ShadowFace& out_face = frame_.faces[layer];
  const bool holds = state.valid && state.key == key;
  const bool current = settings.cache && holds && !state.dynamic_dirty;
  if (!visible) {
    // Not drawn: the layer keeps whatever it held, valid only if it still matches.
    ++frame_.stats.culled;
    if (state.valid && state.key != key) {
      state.valid = false;
      state.epoch = next_epoch_++;  // what it holds is no longer this face
    }
    state.shown = state.valid && !state.dynamic_dirty;
    out_face.info.z = state.shown ? 1u : 0u;
    frame_.epochs[layer] = state.epoch;
    state.wanted = key;
    return;
  }
  out_face.info.z = 1u;
  state.shown = true;
  if (current) {
    ++frame_.stats.cached;
    frame_.epochs[layer] = state.epoch;
    state.wanted = key;
    return;
  }
  ++frame_.stats.rendered;
  if (holds && state.dynamic_dirty) ++frame_.stats.dynamic;
  frame_.stats.texels += std::uint64_t{key.resolution} * key.resolution;
  const FaceUpdate update = choose_update(layer, key, cacheable, motion);
  if (update != FaceUpdate::all) ++frame_.stats.over_cache;
  frame_.render_layers.push_back(layer);
  frame_.updates.push_back(update);
  out_face.info.w = 1u;  // consumers that cache derived data redo this layer
  state.valid = true;
  state.key = key;
  state.dynamic_dirty = false;
  state.epoch = next_epoch_++;
  state.wanted = key;
  frame_.epochs[layer] = state.epoch;
}

// Only faces that dynamic meshes touch go through the cache; the cache is filled once
// their key held still for a frame (a moving light would refill it every frame).
FaceUpdate AtlasPlanner::choose_update(std::uint32_t layer, const FaceKey& key, bool cacheable,
                                       const SceneMotion& motion) {
  LayerState& state = layers_[layer];
  if (!cacheable) return FaceUpdate::all;
  const bool touched =
      std::any_of(motion.dynamic.begin(), motion.dynamic.end(),
                  [&](const auto& box) { return shadow_faces::box_may_touch(key.view_proj, box); });
  if (!touched) return FaceUpdate::all;
  if (state.cache_valid && state.cache_key == key) return FaceUpdate::over_cache;
  if (state.wanted == key) {
    state.cache_valid = true;
    state.cache_key = key;
    return FaceUpdate::fill_cache;
  }
  return FaceUpdate::all;
}

// The GPU keeps what each layer holds (its epoch) and draws a candidate only where a
// visible pixel needs it and the epoch differs; info.z/w are its to write.
void AtlasPlanner::plan_candidate(std::uint32_t layer, bool visible, const FaceKey& key,
                                  bool cache) {
  LayerState& state = layers_[layer];
  state.shown = true;
  if (!(state.valid && state.key == key) || !cache || state.dynamic_dirty) {
    state.valid = true;
    state.key = key;
    state.epoch = next_epoch_++;
    state.dynamic_dirty = false;
    state.dirty_pages.clear();  // a new epoch: every page is drawn anew where needed
  } else if (!state.dirty_pages.empty()) {
    for (const std::uint32_t bits : state.dirty_pages) {
      frame_.stats.dynamic_pages += static_cast<std::uint32_t>(std::popcount(bits));
    }
    frame_.dirty_pages.push_back({layer, std::move(state.dirty_pages)});
    state.dirty_pages.clear();
  }
  frame_.epochs[layer] = state.epoch;
  if (!visible) {
    ++frame_.stats.culled;
    return;
  }
  ++frame_.stats.candidates;
  frame_.render_layers.push_back(layer);
  frame_.updates.push_back(FaceUpdate::all);
}

}  // namespace antumbra::passes
