#pragma once
// Vulkan-free per-frame bookkeeping of the point-shadow atlas: which light owns which
// layers (allocated in light order: 6 per point light, 1 per spot or directional light;
// ShadowLight.params.z = the first), which faces the camera may need (culling), which layers still
// hold valid depth from an earlier frame (static caching) and so which faces to draw. Also fills
// the shadowData contents (shadow_data.hpp). The pass uploads and draws what it says.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"
#include "common/shadow_data.hpp"
#include "face_resolution.hpp"

namespace antumbra::passes {

struct AtlasSettings {
  std::uint32_t layers = 6;
  std::uint32_t face_size = 512;
  float near_plane = 0.05f;
  bool cull_faces = true;
  bool cache = true;
  // The compute rasteriser decides on the GPU which visible faces it draws (receiver
  // culling, face_decision.hpp): every visible face is a candidate, and the planner only
  // says which epoch of its contents each layer should hold.
  bool gpu_decides = false;
  // Per-light face resolution from the light's size on screen (face_resolution.hpp);
  // off: every face has face_size texels. `resolution.maximum` is set from face_size.
  bool adaptive_resolution = false;
  ResolutionSettings resolution;
  // The directional light's map covers the camera frustum up to this distance (metres).
  float sun_max_distance = 40.0f;
  float camera_near = 0.1f;  // the scene camera's planes, for the sun's fit
  float camera_far = 200.0f;
};

struct AtlasStats {
  std::uint32_t total = 0;       // faces of shadowed lights (6 point, 1 spot, 1 sun)
  std::uint32_t culled = 0;      // not needed for the visible image
  std::uint32_t rendered = 0;    // drawn this frame
  std::uint32_t cached = 0;      // needed and still valid from an earlier frame
  std::uint32_t candidates = 0;  // gpu_decides: visible faces handed to the GPU's decision
  std::uint64_t texels = 0;      // of the faces drawn (each light's face size squared)
};

// What one layer's contents were rendered for; a face is re-rendered when this changes.
// The face's matrix says everything about the view (position, direction, planes, fit).
struct FaceKey {
  glm::mat4 view_proj{0.0f};
  std::uint64_t geometry_version = 0;
  std::uint32_t resolution = 0;  // texels per side, drawn at the layer's origin
  bool operator==(const FaceKey&) const = default;
};

struct AtlasFrame {
  ShadowHeader header;
  std::vector<ShadowLight> lights;           // per scene light index (at most kMaxShadowLights)
  std::vector<ShadowFace> faces;             // per atlas layer
  std::vector<std::uint32_t> render_layers;  // layers to clear and draw, ascending
  // Per layer: which contents it should hold. A new epoch whenever the face's key
  // changes, it is drawn (CPU decision) or cached contents are not allowed; 0: none.
  std::vector<std::uint32_t> epochs;
  std::vector<std::string> unshadowed;  // casters left without a slot (atlas full)
  bool clear_all = false;  // the whole atlas has undefined contents (first frame, reload)
  AtlasStats stats;
};

class AtlasPlanner {
 public:
  // Every layer's contents are unknown (new image, new pipelines).
  void invalidate();

  // `camera_view_proj`: the scene camera for this frame's viewport (Vulkan clip space).
  const AtlasFrame& plan(const scene::Scene& scene, const glm::mat4& camera_view_proj,
                         std::uint64_t geometry_version, std::uint32_t frame_index,
                         const AtlasSettings& settings);

  [[nodiscard]] const AtlasFrame& last() const { return frame_; }

 private:
  struct LayerState {
    bool valid = false;
    FaceKey key;
    std::uint32_t epoch = 0;
    std::uint32_t resolution = 0;  // a light's first layer: its last choice (hysteresis)
  };
  // The light's face size this frame (ShadowLight.projection.y/z).
  std::uint32_t light_resolution(const scene::PointLight& light, std::uint32_t first_layer,
                                 const AtlasSettings& settings);
  // Decides whether one face's layer is drawn, kept (cached) or left (culled) this frame.
  void plan_layer(std::uint32_t layer, bool visible, const FaceKey& key,
                  const AtlasSettings& settings);
  // The GPU decides (settings.gpu_decides): visible faces are candidates.
  void plan_candidate(std::uint32_t layer, bool visible, const FaceKey& key, bool cache);
  std::vector<LayerState> layers_;
  std::uint32_t next_epoch_ = 1;
  bool contents_known_ = false;
  AtlasFrame frame_;
};

}  // namespace antumbra::passes
