// The passes' *_interface.h headers (valid GLSL and C++) on the CPU: every push-constant
// block is as long in the compiled shader as its C++ struct, the std430 offsets of vec2 and
// uvec2 hold in C++ (the prelude's 8-byte aligned typedefs), and the shaders declare their
// bindings at the headers' numbers. The GPU tests check each pass at prepare; this shows
// the headers agree without a device.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "anisotropic_blur/anisotropic_blur_interface.h"
#include "debug_views/debug_views_interface.h"
#include "deferred_lighting/deferred_lighting_interface.h"
#include "layered_penumbra/layered_penumbra_interface.h"
#include "shader_reflection.hpp"
#include "shadow_min_filter/shadow_min_filter_interface.h"
#include "shadow_reference/reference_interface.h"
#include "tiled_lighting/tiled_lighting_interface.h"
#include "tonemap/tonemap_interface.h"

namespace antumbra::passes {
namespace {

namespace fs = std::filesystem;

// std430 puts a float after a vec2 at 8 and rounds nothing up; GLM alone would not.
static_assert(alignof(shared::vec2) == 8 && sizeof(shared::vec2) == 8);
static_assert(alignof(shared::uvec2) == 8 && sizeof(shared::uvec2) == 8);
static_assert(offsetof(shared::AnisotropicBlurPush, depth_threshold) == 8);
static_assert(offsetof(shared::ReferenceAccumulatePush, sample_index) == 8);
static_assert(offsetof(shared::TiledLightingPush, image_size) == 16);
static_assert(offsetof(shared::ReferenceResolvePush, image_size) == 24);

gpu::SpirvInterface reflect(const std::string& relative,
                            const std::vector<gpu::ShaderDefine>& defines = {}) {
  return testing::compile_and_reflect(fs::path(ANTUMBRA_SOURCE_DIR) / "passes" / relative, defines);
}

// The binding the shader declares under `name` (its variable's or block's name).
std::int64_t binding_of(const gpu::SpirvInterface& shader, const std::string& name) {
  for (const auto& b : shader.bindings) {
    if (b.name == name) return b.binding;
  }
  return -1;
}

const std::vector<gpu::ShaderDefine> kTiledLayered{
    {"SHADOW_MODE", "4"}, {"HAS_ATLAS", "1"},      {"ATLAS_D16", "0"},
    {"HAS_COLOUR", "1"},  {"HAS_HARD_BITS", "1"},  {"FALLBACK_PCF", "1"},
    {"KERNEL", "3"},      {"BLOCKER_SEARCH", "3"}, {"HDR_FORMAT", "rgba16f"},
};

TEST(PassInterface, PushBlocksAreAsLongAsTheirCppStructs) {
  struct Case {
    std::string shader;
    std::vector<gpu::ShaderDefine> defines;
    std::size_t cpp_bytes;
  };
  const std::vector<Case> cases{
      {"tonemap/tonemap.frag", {}, sizeof(shared::TonemapPush)},
      {"deferred_lighting/deferred_lighting.frag", {}, sizeof(shared::DeferredLightingPush)},
      {"anisotropic_blur/anisotropic_blur.comp", {}, sizeof(shared::AnisotropicBlurPush)},
      {"layered_penumbra/layered_penumbra.comp", {}, sizeof(shared::LayeredPenumbraPush)},
      {"tiled_lighting/tiled_lighting.comp", kTiledLayered, sizeof(shared::TiledLightingPush)},
      {"shadow_min_filter/min_downsample.comp", {}, sizeof(shared::ShadowMinFilterPush)},
      {"shadow_min_filter/min_separable.comp", {}, sizeof(shared::ShadowMinFilterPush)},
      {"debug_views/layer_view.comp", {}, sizeof(shared::LayerViewPush)},
      {"debug_views/penumbra_view.comp", {}, sizeof(shared::PenumbraViewPush)},
      {"debug_views/atlas_view.comp", {}, sizeof(shared::AtlasViewPush)},
      {"shadow_reference/reference_depth.vert", {}, sizeof(shared::ReferenceDepthPush)},
      {"shadow_reference/reference_accumulate.comp", {}, sizeof(shared::ReferenceAccumulatePush)},
      {"shadow_reference/reference_resolve.comp", {}, sizeof(shared::ReferenceResolvePush)},
      {"shadow_reference/reference_final.comp",
       {{"HDR_FORMAT", "rgba16f"}, {"HAS_PENUMBRA", "1"}},
       sizeof(shared::ReferenceFinalPush)},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(reflect(c.shader, c.defines).push_constant_bytes, c.cpp_bytes) << c.shader;
  }
}

TEST(PassInterface, ShadersDeclareBindingsAtTheHeadersNumbers) {
  const auto tonemap = reflect("tonemap/tonemap.frag");
  EXPECT_EQ(binding_of(tonemap, "hdr"), shared::kTonemapHdr);
  // layered.glsl's bindings come from the same header as tiled_lighting.comp's.
  const auto tiled = reflect("tiled_lighting/tiled_lighting.comp", kTiledLayered);
  EXPECT_EQ(binding_of(tiled, "out_hdr"), shared::kTiledHdr);
  EXPECT_EQ(binding_of(tiled, "shadow_layers"), shared::kTiledShadow);
  EXPECT_EQ(binding_of(tiled, "hard_bits"), shared::kTiledHardBits);
  const auto atlas_view = reflect("debug_views/atlas_view.comp", {{"HAS_SHADOW_DATA", "1"}});
  EXPECT_EQ(binding_of(atlas_view, "Shadows"), shared::kAtlasViewShadowData);
  EXPECT_EQ(binding_of(atlas_view, "view_out"), shared::kAtlasViewOut);
  const auto resolve = reflect("shadow_reference/reference_resolve.comp");
  EXPECT_EQ(binding_of(resolve, "Accum"), shared::kRefResolveAccum);
  const auto separable = reflect("shadow_min_filter/min_separable.comp");
  EXPECT_EQ(binding_of(separable, "Shadows"), shared::kMinShadowData);
  EXPECT_EQ(binding_of(separable, "min_out"), shared::kMinOutput);
}

}  // namespace
}  // namespace antumbra::passes
