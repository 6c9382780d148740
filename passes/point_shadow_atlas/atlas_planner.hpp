#pragma once
// Vulkan-free per-frame bookkeeping of the point-shadow atlas: which light owns which
// layers, which faces the camera may need (culling), which layers still hold valid
// depth from an earlier frame (static caching) and so which faces to draw. Also fills
// the shadowData contents (shadow_data.hpp). The pass uploads and draws what it says.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"
#include "common/shadow_data.hpp"

namespace antumbra::passes {

struct AtlasSettings {
  std::uint32_t layers = 6;
  std::uint32_t face_size = 512;
  float near_plane = 0.05f;
  bool cull_faces = true;
  bool cache = true;
};

struct AtlasStats {
  std::uint32_t total = 0;     // faces of shadowed lights (6 per light slot)
  std::uint32_t culled = 0;    // not needed for the visible image
  std::uint32_t rendered = 0;  // drawn this frame
  std::uint32_t cached = 0;    // needed and still valid from an earlier frame
};

// What one layer's contents were rendered for; a face is re-rendered when this changes.
struct FaceKey {
  glm::vec3 position{0.0f};
  float range = 0.0f;
  float near = 0.0f;
  std::uint64_t geometry_version = 0;
  bool operator==(const FaceKey&) const = default;
};

struct AtlasFrame {
  ShadowHeader header;
  std::vector<ShadowLight> lights;           // per scene light index (at most kMaxShadowLights)
  std::vector<ShadowFace> faces;             // per atlas layer
  std::vector<std::uint32_t> render_layers;  // layers to clear and draw, ascending
  std::vector<std::string> unshadowed;       // casters left without a slot (atlas full)
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
  };
  std::vector<LayerState> layers_;
  bool contents_known_ = false;
  AtlasFrame frame_;
};

}  // namespace antumbra::passes
