#pragma once
// Pass type "scene-sdf": a signed distance field of the scene's triangles, baked by
// compute into an array image (one layer per z slice) and a small buffer saying where it
// lies, for tiled-lighting's shadows = sdf (docs/technique.md 3, "Signed distance field
// soft shadows"). Baked when the scene's geometry changes (a load or reload) or the
// volume is new; other frames do nothing. Dynamic meshes are baked where they stood at
// load. Reflection in scene_sdf_desc.cpp, the bake in sdf_bake.comp.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/pass_support.hpp"
#include "scene_sdf_interface.h"

namespace antumbra::scene {
struct Aabb;
}

namespace antumbra::passes {

struct SceneSdfParams {
  float band = 8.0f;               // voxels: the largest distance stored
  std::uint32_t memory_mib = 256;  // budget for the volume
};

// Where a volume of `dims` voxels lies around `bounds`: the bounds centred with two
// voxels of margin on every side, each axis's voxels as long as that takes (no side under
// a sixteenth of the longest). Exposed for tests.
shared::SceneSdfPush fit_sdf_volume(const scene::Aabb& bounds, glm::uvec3 dims, float band_voxels);

class SceneSdfPass final : public fgvk::Pass {
 public:
  static constexpr const char* kType = "scene-sdf";
  static fg::PassDesc describe();
  static const fg::ParamTable<SceneSdfParams>& param_table();
  explicit SceneSdfPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  SceneSdfParams params_;
  ComputePipeline chunks_;  // bounds of every 64 triangles
  ComputePipeline bake_;
  gpu::Buffer chunk_bounds_;
  VkImage baked_into_ = VK_NULL_HANDLE;
  std::uint64_t baked_version_ = 0;
  shared::SceneSdfPush baked_{};  // what the field holds, for the frame reports
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
