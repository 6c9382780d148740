#pragma once
// Pass types "tiled-lighting", "shadow-hard", "shadow-pcf" and "shadow-pcss": one
// compute shader (tiled_lighting.comp) with per-tile depth bounds and light lists, whose
// shadow term is chosen per type/mode. The three shadow-* baselines are tiled-lighting
// with the mode fixed and the atlas required, so comparisons differ only in the shadow
// technique. Reflection in tiled_lighting_desc.cpp, runtime in tiled_lighting_pass.cpp.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/lighting_reflection.hpp"
#include "interface/shared/shadow_modes.h"

namespace antumbra::passes {

// vsm .. vssm: filtered shadow maps from shadow-moments (its technique, in the same order
// from vsm on as MomentTechnique; moment_technique_index).
// The values are tiled_lighting.comp's SHADOW_MODE (interface/shared/shadow_modes.h).
enum class ShadowMode : std::uint8_t {
  none = ANTUMBRA_SHADOW_NONE,
  hard = ANTUMBRA_SHADOW_HARD,
  pcf = ANTUMBRA_SHADOW_PCF,
  pcss = ANTUMBRA_SHADOW_PCSS,
  layered = ANTUMBRA_SHADOW_LAYERED,
  vsm = ANTUMBRA_SHADOW_VSM,
  evsm2 = ANTUMBRA_SHADOW_EVSM2,
  evsm4 = ANTUMBRA_SHADOW_EVSM4,
  msm = ANTUMBRA_SHADOW_MSM,
  vssm = ANTUMBRA_SHADOW_VSSM,
  sdf = ANTUMBRA_SHADOW_SDF,
  penumbra_map = ANTUMBRA_SHADOW_PENUMBRA_MAP
};

[[nodiscard]] constexpr bool is_moment_mode(ShadowMode mode) {
  return mode >= ShadowMode::vsm && mode <= ShadowMode::vssm;
}
// The MOMENTS_TECHNIQUE value of a moment mode (shadow_modes.h asserts the offsets).
[[nodiscard]] constexpr int moment_technique_index(ShadowMode mode) {
  return is_moment_mode(mode) ? static_cast<int>(mode) - static_cast<int>(ShadowMode::vsm) : 0;
}

std::string_view to_string(ShadowMode mode);

struct TiledLightingParams {
  LightingParams lighting;
  ShadowMode shadows = ShadowMode::none;  // tiled-lighting; shadow-* fix the mode by type
  int kernel = 11;
  int blocker_search = 5;
  float light_size_scale = 1.0f;
  bool pcf_fallback = true;         // layered: layer-less lights by PCF (else one hard test)
  float bleeding_reduction = 0.2f;  // moment modes (common/moments.glsl reduce_bleeding)
  bool wedge_receiver = true;       // penumbra-map: wedge ramps rescaled per receiver
};

class TiledLightingPass final : public fgvk::Pass {
 public:
  static constexpr const char* kType = "tiled-lighting";
  static constexpr const char* kHardType = "shadow-hard";
  static constexpr const char* kPcfType = "shadow-pcf";
  static constexpr const char* kPcssType = "shadow-pcss";

  static fg::PassDesc describe();       // tiled-lighting: mode from the `shadows` param
  static fg::PassDesc describe_hard();  // shadow-hard
  static fg::PassDesc describe_pcf();   // shadow-pcf
  static fg::PassDesc describe_pcss();  // shadow-pcss

  // The parameters of pass type `type` (the four differ in which they have).
  static const fg::ParamTable<TiledLightingParams>& param_table(std::string_view type);

  // The mode comes from the pass type (shadow-*) or the `shadows` parameter.
  static ShadowMode mode_of(std::string_view type, const TiledLightingParams& params);

  explicit TiledLightingPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  TiledLightingParams params_;
  ShadowMode mode_;
  bool has_atlas_ = false;
  bool page_tables_ = false;  // `pageTables` bound: the atlas is paged
  bool has_colour_ = false;
  bool has_hard_bits_ = false;  // layered: full-resolution hard bits for sharp edges
  bool has_moments_ = false;    // vsm .. vssm: the filtered moment map
  bool has_peeled_ = false;     // penumbra-map: the third depth layer
  bool has_emissive_ = false;   // the G-buffer's emission and occlusion
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline pipeline_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
