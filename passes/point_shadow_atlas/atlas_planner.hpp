#pragma once
// Vulkan-free per-frame bookkeeping of the point-shadow atlas: which light owns which face
// records (in light order: 6 per point light, 1 per spot light, one per cascade of the
// directional light, fewer when the records run out; ShadowLight.params.z = the first),
// where each record's square lies and at what size (face_packer.hpp: smaller when the atlas
// is full; docs/technique.md, "Packed faces"), which faces the camera may need (culling),
// which records still hold valid depth from an earlier frame (static caching), which ones
// dynamic meshes made stale, which updates fit this frame's budget and so which faces to
// draw, and how (over a cache of their static depth or not). Also fills the shadowData
// contents (shadow_data.hpp). The pass uploads and draws what it says (docs/technique.md,
// "Static and dynamic casters").

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"
#include "common/shadow_data.hpp"
#include "dirty_pages.hpp"
#include "face_packer.hpp"
#include "face_resolution.hpp"

namespace antumbra::passes {

struct AtlasSettings {
  std::uint32_t layers = 6;
  std::uint32_t face_size = 512;
  // Face records the shadowData buffer holds (0: one per layer). Faces smaller than a
  // layer share layers (face_packer.hpp), so with per-light resolution, or when the atlas
  // is full and faces are drawn smaller, more faces than layers fit.
  std::uint32_t records = 0;
  // Faces smaller than a layer share layers; off: one face per layer, at its origin.
  bool pack = true;
  float near_plane = 0.05f;
  bool cull_faces = true;
  bool cache = true;
  // The compute rasteriser decides on the GPU which visible faces it draws (receiver
  // culling, face_decision.hpp): every visible face is a candidate, and the planner only
  // says which epoch of its contents each layer should hold.
  bool gpu_decides = false;
  // The faces' pages live in a page pool (page_pool_interface.h; with gpu_decides): faces
  // have no squares, every light gets the face size it wants, and a record's
  // ShadowFace.info.y names its page table (interface/shared/page_tables.h).
  bool page_pool = false;
  // A page pool too small for the view (pool_fit.hpp): faces at most this size (0: none).
  std::uint32_t pool_cap = 0;
  // Per-light face resolution from the light's size on screen (face_resolution.hpp);
  // off: every face has face_size texels. `resolution.maximum` is set from face_size.
  bool adaptive_resolution = false;
  ResolutionSettings resolution;
  // The directional light's cascades cover the camera frustum up to this distance
  // (metres), split by PSSM with blend `sun_lambda` (light_faces::fit_cascades); the
  // lookups blend neighbouring cascades over `sun_blend` of a cascade's half width.
  float sun_max_distance = 40.0f;
  std::uint32_t sun_cascades = 4;
  float sun_lambda = 0.75f;
  float sun_blend = 0.1f;
  float camera_near = 0.1f;  // the scene camera's planes, for the sun's fit
  float camera_far = 200.0f;
  // Faces that dynamic meshes touch keep their static depth in a cache and draw only the
  // dynamic meshes over a copy of it (the hardware rasteriser's layered path).
  bool static_cache = false;
  std::vector<bool> uncached_lights;  // per scene light: never through the cache (tinted)
  // Update budget: faces drawn per frame beyond those that must be (never drawn, or stale
  // for `max_stale` frames). Lights that wait keep showing the shadow they were last drawn
  // with; the longest waiting go first (round-robin), then the largest on screen.
  std::uint32_t face_budget = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t max_stale = 4;
};

// Where dynamic meshes are (FrameResources::moved_bounds, dynamic_bounds).
struct SceneMotion {
  std::span<const scene::Aabb> moved;    // left and entered this frame
  std::span<const scene::Aabb> dynamic;  // every dynamic mesh now
};

// How a face is drawn (hardware rasteriser): every mesh; the static cache copied in and
// the dynamic meshes over it; or the static meshes into the cache first, then the same.
enum class FaceUpdate : std::uint8_t { all, over_cache, fill_cache };

struct AtlasStats {
  std::uint32_t total = 0;       // faces of shadowed lights (6 point, 1 spot, 1-4 sun)
  std::uint32_t culled = 0;      // not needed for the visible image
  std::uint32_t rendered = 0;    // drawn this frame
  std::uint32_t cached = 0;      // needed and still valid from an earlier frame
  std::uint32_t candidates = 0;  // gpu_decides: visible faces handed to the GPU's decision
  std::uint64_t texels = 0;      // of the faces drawn (each light's face size squared)
  std::uint32_t dynamic = 0;     // drawn because dynamic meshes moved through them
  // gpu_decides: pages handed to the GPU as dirty (dynamic meshes moved through them)
  std::uint32_t dynamic_pages = 0;
  std::uint32_t over_cache = 0;   // drawn over their static cache (fill_cache included)
  std::uint32_t deferred = 0;     // needed but left for a later frame (budget)
  std::uint32_t forced = 0;       // drawn past the budget (never drawn, or too stale)
  std::uint32_t stalest = 0;      // frames the oldest shadow shown is behind its light
  std::uint32_t layers_used = 0;  // atlas layers holding a face
  std::uint64_t texels_held = 0;  // texels of every shadowed light's faces
};

// A light whose faces are smaller than it wants: the atlas had no room at its size.
struct DegradedLight {
  std::string name;
  std::uint32_t wanted = 0;  // texels per face side
  std::uint32_t given = 0;
};

// What one layer's contents were rendered for; a face is re-rendered when this changes.
// The face's matrix says everything about the view (position, direction, planes, fit).
struct FaceKey {
  glm::mat4 view_proj{0.0f};
  std::uint64_t geometry_version = 0;
  std::uint32_t resolution = 0;  // texels per side, drawn at `place`
  FacePlace place;
  bool operator==(const FaceKey&) const = default;
};

struct AtlasFrame {
  ShadowHeader header;
  std::vector<ShadowLight> lights;           // per scene light index (at most kMaxShadowLights)
  std::vector<ShadowFace> faces;             // per atlas layer
  std::vector<std::uint32_t> render_layers;  // layers to clear and draw, ascending
  std::vector<FaceUpdate> updates;           // per render_layers entry
  // Per layer: which contents it should hold. A new epoch whenever the face's key
  // changes, it is drawn (CPU decision) or cached contents are not allowed; 0: none.
  std::vector<std::uint32_t> epochs;
  // gpu_decides: layers whose pages dynamic meshes moved through, at an epoch that stays:
  // only those pages are drawn again (FaceRequest::dirty).
  struct DirtyPages {
    std::uint32_t layer = 0;
    std::vector<std::uint32_t> bits;  // bit k: page k of the face (row-major)
  };
  std::vector<DirtyPages> dirty_pages;
  std::vector<std::string> unshadowed;  // casters left without a slot (atlas full)
  std::vector<DegradedLight> degraded;  // casters drawn smaller than wanted (atlas full)
  bool clear_all = false;  // the whole atlas has undefined contents (first frame, reload)
  // Records [0, live_records) are what the GPU takes this frame (the upload, the face
  // decision): every record on a clear_all frame, else those a light owns now or owned
  // on the last frame (which read "no owner" once more). The others read "no owner"
  // already in the face decision's own copy, which writes the graph's shadowData whole
  // (that buffer need not keep last frame's words): work per frame follows the lights.
  std::uint32_t live_records = 0;
  AtlasStats stats;
};

// Where face record `slot`'s texels are (ShadowFace.info.y): its layer, and its square's
// corner and width in texels (its light's face size; the whole layer for a record no
// light owns).
struct FaceSquare {
  std::uint32_t layer = 0;
  glm::uvec2 origin{0u};
  std::uint32_t size = 0;
};
FaceSquare face_square(const AtlasFrame& frame, std::uint32_t slot);
// Face record `slot`'s size in texels: its light's (per-light resolution), at most the
// atlas's; the atlas's for a record no light owns. The rasteriser, the decision's requests
// and the squares all size a face by it (shadow_receivers.comp mirrors it on the GPU).
std::uint32_t face_size(const AtlasFrame& frame, std::uint32_t slot);

class AtlasPlanner {
 public:
  // Every layer's contents are unknown (new image, new pipelines).
  void invalidate();

  // `camera_view_proj`: the scene camera for this frame's viewport (Vulkan clip space).
  const AtlasFrame& plan(const scene::Scene& scene, const glm::mat4& camera_view_proj,
                         std::uint64_t geometry_version, std::uint32_t frame_index,
                         const AtlasSettings& settings, const SceneMotion& motion = {});

  [[nodiscard]] const AtlasFrame& last() const { return frame_; }

 private:
  struct LayerState {
    bool valid = false;
    FaceKey key;
    std::uint32_t epoch = 0;
    std::uint32_t resolution = 0;  // a light's first layer: its last choice (hysteresis)
    bool dynamic_dirty = false;    // dynamic meshes moved through it since it was drawn
    // gpu_decides: bits of the pages they moved through, not yet sent (empty: none)
    std::vector<std::uint32_t> dirty_pages;
    bool shown = false;        // holds the face of its light's shown (last drawn) state
    FaceKey wanted;            // last frame's key: a key that holds still is worth caching
    bool cache_valid = false;  // the static cache holds the static meshes for cache_key
    FaceKey cache_key;
    // A light's first layer: what it was last drawn with (shown while it waits for the
    // budget), whose it is, and for how many frames it has waited.
    ShadowLight shown_light{};
    std::string owner;
    std::uint32_t waited = 0;
  };
  // A shadowed light's records and face size (before the squares are placed).
  struct Claim {
    std::uint32_t light = 0;
    std::uint32_t first = 0;
    std::uint32_t faces = 0;
    std::uint32_t wanted = 0;  // face size it asks for
    std::uint32_t given = 0;   // what the atlas had room for (0: none)
    bool moved = false;        // its squares changed this frame: what they held is gone
  };
  // This frame's wish for one shadowed light, before the budget decides.
  struct LightWork {
    std::uint32_t light = 0;
    std::uint32_t first = 0;
    std::uint32_t faces = 0;
    std::uint32_t visible = 0;  // bit per face
    std::uint32_t needed = 0;   // visible faces whose layer does not hold them
    bool must = false;          // never drawn, changed owner, too stale, or the sun
    bool update = true;         // the budget's decision
    float priority = 0.0f;      // projected radius (pixels)
    std::uint32_t resolution = 0;
  };
  void begin_frame(const scene::Scene& scene, std::uint32_t frame_index,
                   const AtlasSettings& settings);
  // Gives every shadowed light its records and wanted face size (claims_); lights past
  // the records are unshadowed.
  void claim_lights(const scene::Scene& scene, const AtlasSettings& settings);
  // Squares for every claim: kept while the size holds, else placed anew, smaller when
  // there is no room (frame_.degraded), none when not even the smallest fits.
  void place_claims(const scene::Scene& scene, const AtlasSettings& settings);
  [[nodiscard]] std::vector<std::uint32_t> fit_sizes(const AtlasSettings& settings,
                                                     std::uint32_t smallest) const;
  // Fills frame_.lights/faces with this frame's wish for a placed claim.
  void wish_light(const scene::Scene& scene, const Claim& claim, const glm::mat4& camera_view_proj,
                  std::uint64_t geometry_version, const AtlasSettings& settings, LightWork& work);
  void mark_dynamic(const SceneMotion& motion, const AtlasSettings& settings);
  void apply_budget(const AtlasSettings& settings);
  // Publishes a waiting light as it was last drawn.
  void keep_light(const LightWork& work);
  void plan_light(const scene::Scene& scene, const LightWork& work, std::uint64_t geometry_version,
                  const AtlasSettings& settings, const SceneMotion& motion);
  // The light's face size this frame (ShadowLight.projection.y/z).
  std::uint32_t light_resolution(const scene::PointLight& light, std::uint32_t first_layer,
                                 const AtlasSettings& settings);
  // Decides whether one face's layer is drawn, kept (cached) or left (culled) this frame.
  void plan_layer(std::uint32_t layer, bool visible, const FaceKey& key,
                  const AtlasSettings& settings, bool cacheable, const SceneMotion& motion);
  // The GPU decides (settings.gpu_decides): visible faces are candidates.
  void plan_candidate(std::uint32_t layer, bool visible, const FaceKey& key, bool cache);
  // Where face record `slot`'s texels are (unplaced: layer 0, never read).
  [[nodiscard]] FacePlace place_of(std::uint32_t slot) const {
    return packer_.place_of(slot).value_or(FacePlace{});
  }
  // ShadowFace.info.y of record `slot` holding face `face`: its place, or in a page pool
  // its page table's first word.
  [[nodiscard]] std::uint32_t face_info_y(std::uint32_t face, std::uint32_t slot) const;
  // A page pool's claims: every light at its wanted size (no squares to place).
  void size_pool_claims(const scene::Scene& scene, const AtlasSettings& settings);
  [[nodiscard]] FaceKey face_key(std::uint32_t record, std::uint64_t geometry_version,
                                 const LightWork& work) const {
    return {frame_.faces[record].view_proj, geometry_version, work.resolution, place_of(record)};
  }
  [[nodiscard]] FaceUpdate choose_update(std::uint32_t layer, const FaceKey& key, bool cacheable,
                                         const SceneMotion& motion);
  std::vector<LayerState> layers_;  // per face record
  std::vector<Claim> claims_;
  std::vector<LightWork> work_;
  FacePacker packer_;
  std::uint32_t next_epoch_ = 1;
  std::uint32_t table_stride_ = 0;  // page-table words per record (page pool), else 0
  // Records [0, owned_end_) had an owner on the last frame; the others are released and
  // their ShadowFace in frame_.faces reads "no owner" already: a frame's work on records
  // is proportional to the records lights own, not to the records the graph holds.
  std::uint32_t owned_end_ = 0;
  bool contents_known_ = false;
  AtlasFrame frame_;
};

}  // namespace antumbra::passes
