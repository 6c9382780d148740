// The passes' *_interface.h headers and the shared headers of passes/interface/shared
// (valid GLSL and C++; docs/architecture.md, "One source for CPU and GPU") on the CPU:
// every header compiles alone as GLSL and is included here as C++ (so its static_asserts
// hold), every push-constant block is as long in the compiled shader as its C++ struct,
// the std430 offsets of vec2 and uvec2 hold in C++ (the prelude's 8-byte aligned
// typedefs), and the shaders declare their bindings at the headers' numbers. The GPU tests
// check each pass at prepare; this shows the headers agree without a device.
//
// kHeaders lists every header this suite covers; a header added under passes/ and not
// listed here (and included above) fails HeadersOnDiskAreTheCoveredOnes, by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "anisotropic_blur/anisotropic_blur_interface.h"
#include "colour_grade/colour_grade_interface.h"
#include "debug_views/debug_views_interface.h"
#include "deferred_lighting/deferred_lighting_interface.h"
#include "gbuffer/gbuffer_interface.h"
#include "gbuffer/visibility_interface.h"
#include "interface/shared/bvh.h"
#include "interface/shared/derived_maps.h"
#include "interface/shared/frame_uniforms.h"
#include "interface/shared/glsl_cpp.h"
#include "interface/shared/layer_palette.h"
#include "interface/shared/layer_table.h"
#include "interface/shared/limits.h"
#include "interface/shared/material_textures.h"
#include "interface/shared/page_tables.h"
#include "interface/shared/scene_data.h"
#include "interface/shared/sdf_info.h"
#include "interface/shared/shadow_data.h"
#include "interface/shared/shadow_modes.h"
#include "interface/shared/tone_operators.h"
#include "interface/shared/workgroups.h"
#include "layered_penumbra/layered_penumbra_interface.h"
#include "penumbra_wedges/penumbra_wedges_interface.h"
#include "point_shadow_atlas/compute_raster_interface.h"
#include "point_shadow_atlas/face_decision_interface.h"
#include "point_shadow_atlas/page_pool_interface.h"
#include "point_shadow_atlas/pages.h"
#include "point_shadow_atlas/point_shadow_atlas_interface.h"
#include "scene_sdf/scene_sdf_interface.h"
#include "shader_reflection.hpp"
#include "shadow_min_filter/shadow_min_filter_interface.h"
#include "shadow_moments/shadow_moments_interface.h"
#include "shadow_reference/reference_interface.h"
#include "tiled_lighting/tiled_lighting_interface.h"
#include "tonemap/tonemap_interface.h"

namespace antumbra::passes {
namespace {

namespace fs = std::filesystem;

// Every header included above, relative to passes/: keep the two lists together.
const std::vector<std::string> kHeaders{
    "anisotropic_blur/anisotropic_blur_interface.h",
    "colour_grade/colour_grade_interface.h",
    "debug_views/debug_views_interface.h",
    "deferred_lighting/deferred_lighting_interface.h",
    "gbuffer/gbuffer_interface.h",
    "gbuffer/visibility_interface.h",
    "interface/shared/bvh.h",
    "interface/shared/derived_maps.h",
    "interface/shared/frame_uniforms.h",
    "interface/shared/glsl_cpp.h",
    "interface/shared/layer_palette.h",
    "interface/shared/layer_table.h",
    "interface/shared/limits.h",
    "interface/shared/material_textures.h",
    "interface/shared/page_tables.h",
    "interface/shared/scene_data.h",
    "interface/shared/sdf_info.h",
    "interface/shared/shadow_data.h",
    "interface/shared/shadow_modes.h",
    "interface/shared/tone_operators.h",
    "interface/shared/workgroups.h",
    "layered_penumbra/layered_penumbra_interface.h",
    "penumbra_wedges/penumbra_wedges_interface.h",
    "point_shadow_atlas/compute_raster_interface.h",
    "point_shadow_atlas/face_decision_interface.h",
    "point_shadow_atlas/page_pool_interface.h",
    "point_shadow_atlas/pages.h",
    "point_shadow_atlas/point_shadow_atlas_interface.h",
    "scene_sdf/scene_sdf_interface.h",
    "shadow_min_filter/shadow_min_filter_interface.h",
    "shadow_moments/shadow_moments_interface.h",
    "shadow_reference/reference_interface.h",
    "tiled_lighting/tiled_lighting_interface.h",
    "tonemap/tonemap_interface.h",
};

// std430 puts a float after a vec2 at 8 and rounds nothing up; GLM alone would not.
static_assert(alignof(shared::vec2) == 8 && sizeof(shared::vec2) == 8);
static_assert(alignof(shared::uvec2) == 8 && sizeof(shared::uvec2) == 8);
static_assert(offsetof(shared::AnisotropicBlurPush, depth_threshold) == 8);
static_assert(offsetof(shared::ReferenceAccumulatePush, sample_index) == 8);
static_assert(offsetof(shared::TiledLightingPush, image_size) == 16);
static_assert(offsetof(shared::ReferenceResolvePush, image_size) == 24);
// The BVH's nodes: two vec4, 32 bytes, as common/bvh.glsl indexes them.
static_assert(sizeof(shared::BvhNode) == 32 && offsetof(shared::BvhNode, hi) == 16);

const fs::path kPasses = fs::path(ANTUMBRA_SOURCE_DIR) / "passes";

gpu::SpirvInterface reflect(const std::string& relative,
                            const std::vector<gpu::ShaderDefine>& defines = {}) {
  return testing::compile_and_reflect(kPasses / relative, defines);
}

// The binding the shader declares under `name` (its variable's or block's name).
std::int64_t binding_of(const gpu::SpirvInterface& shader, const std::string& name) {
  for (const auto& b : shader.bindings) {
    if (b.name == name) return b.binding;
  }
  return -1;
}

// Every *_interface.h of a pass folder and every header of interface/shared, on disk.
std::set<std::string> headers_on_disk() {
  std::set<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(kPasses)) {
    const std::string name = entry.path().filename().string();
    const std::string relative = entry.path().lexically_relative(kPasses).generic_string();
    const bool interface = name.ends_with("_interface.h");
    const bool shared = relative.starts_with("interface/shared/") && name.ends_with(".h");
    if (entry.is_regular_file() && (interface || shared)) found.insert(relative);
  }
  return found;
}

TEST(PassInterface, HeadersOnDiskAreTheCoveredOnes) {
  const std::set<std::string> covered(kHeaders.begin(), kHeaders.end());
  for (const std::string& header : headers_on_disk()) {
    EXPECT_TRUE(covered.contains(header))
        << "passes/" << header
        << " is not covered: include it in tests/builtin/pass_interface_test.cpp, add it to "
           "kHeaders and, for a pass's *_interface.h, to a push-block or binding case";
  }
  // kHeaders against this file's includes, so a listed header is compiled as C++ too.
  std::ifstream self(fs::path(ANTUMBRA_SOURCE_DIR) / "tests/builtin/pass_interface_test.cpp");
  const std::string text{std::istreambuf_iterator<char>(self), std::istreambuf_iterator<char>()};
  for (const std::string& header : kHeaders) {
    EXPECT_TRUE(fs::exists(kPasses / header)) << "kHeaders names a missing passes/" << header;
    EXPECT_NE(text.find("#include \"" + header + "\""), std::string::npos)
        << "kHeaders names passes/" << header << ", which this test does not include";
  }
}

// Each header alone in an otherwise empty compute shader: it must be valid GLSL by itself
// (its own includes), as it is valid C++ by being included above.
TEST(PassInterface, EveryHeaderCompilesAloneAsGlsl) {
  const fs::path dir = fs::temp_directory_path() / "antumbra_pass_interface_test";
  fs::create_directories(dir);
  for (const std::string& header : kHeaders) {
    const fs::path probe = dir / (fs::path(header).stem().string() + ".comp");
    std::ofstream(probe) << "#version 460\n"
                            "#extension GL_GOOGLE_include_directive : require\n"
                         << "#include \"" << (kPasses / header).generic_string() << "\"\n"
                         << "layout(local_size_x = 1) in;\nvoid main() {}\n";
    SCOPED_TRACE(header);
    testing::compile_and_reflect(probe);
  }
}

const std::vector<gpu::ShaderDefine> kTiledLayered{
    {"SHADOW_MODE", std::to_string(ANTUMBRA_SHADOW_LAYERED)},
    {"HAS_ATLAS", "1"},
    {"ATLAS_D16", "0"},
    {"HAS_COLOUR", "1"},
    {"HAS_HARD_BITS", "1"},
    {"FALLBACK_PCF", "1"},
    {"KERNEL", "3"},
    {"BLOCKER_SEARCH", "3"},
    {"HDR_FORMAT", "rgba16f"},
};

std::vector<gpu::ShaderDefine> tiled_paged() {
  std::vector<gpu::ShaderDefine> defines = kTiledLayered;
  defines.push_back({"SHADOW_PAGE_TABLES", "1"});
  return defines;
}
const std::vector<gpu::ShaderDefine> kTiledPaged = tiled_paged();

const std::vector<gpu::ShaderDefine> kGradeRgba16f{{"HDR_FORMAT", "rgba16f"}};

const std::vector<gpu::ShaderDefine> kMoments{{"MOMENTS_TECHNIQUE", "2"},
                                              {"MOMENTS_FORMAT", "rgba32f"}};

// A push-constant block: the header declaring it, a shader reading it, the C++ size.
struct PushCase {
  std::string header;
  std::string shader;
  std::vector<gpu::ShaderDefine> defines;
  std::size_t cpp_bytes;
};

const std::vector<PushCase>& push_cases() {
  static const std::vector<PushCase> kCases{
      {"tonemap/tonemap_interface.h", "tonemap/tonemap.frag", {}, sizeof(shared::TonemapPush)},
      {"colour_grade/colour_grade_interface.h", "colour_grade/colour_grade.comp", kGradeRgba16f,
       sizeof(shared::ColourGradePush)},
      {"deferred_lighting/deferred_lighting_interface.h",
       "deferred_lighting/deferred_lighting.frag",
       {},
       sizeof(shared::DeferredLightingPush)},
      {"anisotropic_blur/anisotropic_blur_interface.h",
       "anisotropic_blur/anisotropic_blur.comp",
       {},
       sizeof(shared::AnisotropicBlurPush)},
      {"layered_penumbra/layered_penumbra_interface.h",
       "layered_penumbra/layered_penumbra.comp",
       {},
       sizeof(shared::LayeredPenumbraPush)},
      {"tiled_lighting/tiled_lighting_interface.h", "tiled_lighting/tiled_lighting.comp",
       kTiledLayered, sizeof(shared::TiledLightingPush)},
      {"shadow_min_filter/shadow_min_filter_interface.h",
       "shadow_min_filter/min_downsample.comp",
       {},
       sizeof(shared::ShadowMinFilterPush)},
      {"shadow_min_filter/shadow_min_filter_interface.h",
       "shadow_min_filter/min_separable.comp",
       {},
       sizeof(shared::ShadowMinFilterPush)},
      {"debug_views/debug_views_interface.h",
       "debug_views/layer_view.comp",
       {},
       sizeof(shared::LayerViewPush)},
      {"debug_views/debug_views_interface.h",
       "debug_views/penumbra_view.comp",
       {},
       sizeof(shared::PenumbraViewPush)},
      {"debug_views/debug_views_interface.h",
       "debug_views/atlas_view.comp",
       {},
       sizeof(shared::AtlasViewPush)},
      {"shadow_reference/reference_interface.h",
       "shadow_reference/reference_depth.vert",
       {},
       sizeof(shared::ReferenceDepthPush)},
      {"shadow_reference/reference_interface.h",
       "shadow_reference/reference_accumulate.comp",
       {},
       sizeof(shared::ReferenceAccumulatePush)},
      {"shadow_reference/reference_interface.h",
       "shadow_reference/reference_resolve.comp",
       {},
       sizeof(shared::ReferenceResolvePush)},
      {"shadow_reference/reference_interface.h",
       "shadow_reference/reference_final.comp",
       {{"HDR_FORMAT", "rgba16f"}, {"HAS_PENUMBRA", "1"}},
       sizeof(shared::ReferenceFinalPush)},
      {"shadow_moments/shadow_moments_interface.h", "shadow_moments/moments_convert.comp", kMoments,
       sizeof(shared::ShadowMomentsPush)},
      {"penumbra_wedges/penumbra_wedges_interface.h",
       "penumbra_wedges/silhouettes.comp",
       {},
       sizeof(shared::PenumbraWedgesPush)},
      {"point_shadow_atlas/compute_raster_interface.h",
       "point_shadow_atlas/shadow_cull.comp",
       {},
       sizeof(shared::RasterPush)},
      {"point_shadow_atlas/face_decision_interface.h",
       "point_shadow_atlas/shadow_face_decide.comp",
       {},
       sizeof(shared::DecisionPush)},
      {"gbuffer/visibility_interface.h",
       "gbuffer/visibility_raster.comp",
       {{"FRONT_SIGN", "-1.0"}},
       sizeof(shared::VisibilityPush)},
      {"scene_sdf/scene_sdf_interface.h",
       "scene_sdf/sdf_bake.comp",
       {{"SDF_FORMAT", "r16f"}, {"SDF_CHUNKS", "0"}},
       sizeof(shared::SceneSdfPush)},
  };
  return kCases;
}

// Also the derived maps' record list (interface/shared/derived_maps.h), shared by two passes.
std::vector<PushCase> all_push_cases() {
  std::vector<PushCase> cases = push_cases();
  cases.push_back({"interface/shared/derived_maps.h",
                   "common/derived_list.comp",
                   {},
                   sizeof(shared::DerivedListPush)});
  return cases;
}

TEST(PassInterface, PushBlocksAreAsLongAsTheirCppStructs) {
  for (const PushCase& c : all_push_cases()) {
    EXPECT_EQ(reflect(c.shader, c.defines).push_constant_bytes, c.cpp_bytes) << c.shader;
  }
}

// A binding: the header numbering it, a shader declaring it, its name there, the number.
struct BindingCase {
  std::string header;
  std::string shader;
  std::vector<gpu::ShaderDefine> defines;
  std::string name;
  std::int64_t number;
};

const std::vector<BindingCase>& binding_cases() {
  static const std::vector<BindingCase> kCases{
      {"tonemap/tonemap_interface.h", "tonemap/tonemap.frag", {}, "hdr", shared::kTonemapHdr},
      {"colour_grade/colour_grade_interface.h", "colour_grade/colour_grade.comp", kGradeRgba16f,
       "source_image", shared::kColourGradeSource},
      {"colour_grade/colour_grade_interface.h", "colour_grade/colour_grade.comp", kGradeRgba16f,
       "target", shared::kColourGradeTarget},
      // layered.glsl's bindings come from the same header as tiled_lighting.comp's.
      {"tiled_lighting/tiled_lighting_interface.h", "tiled_lighting/tiled_lighting.comp",
       kTiledLayered, "out_hdr", shared::kTiledHdr},
      {"tiled_lighting/tiled_lighting_interface.h", "tiled_lighting/tiled_lighting.comp",
       kTiledLayered, "shadow_layers", shared::kTiledShadow},
      {"tiled_lighting/tiled_lighting_interface.h", "tiled_lighting/tiled_lighting.comp",
       kTiledLayered, "hard_bits", shared::kTiledHardBits},
      {"debug_views/debug_views_interface.h",
       "debug_views/atlas_view.comp",
       {{"HAS_SHADOW_DATA", "1"}},
       "Shadows",
       shared::kAtlasViewShadowData},
      {"debug_views/debug_views_interface.h",
       "debug_views/atlas_view.comp",
       {{"HAS_SHADOW_DATA", "1"}},
       "view_out",
       shared::kAtlasViewOut},
      {"shadow_reference/reference_interface.h",
       "shadow_reference/reference_resolve.comp",
       {},
       "Accum",
       shared::kRefResolveAccum},
      {"shadow_min_filter/shadow_min_filter_interface.h",
       "shadow_min_filter/min_separable.comp",
       {},
       "Shadows",
       shared::kMinShadowData},
      {"shadow_min_filter/shadow_min_filter_interface.h",
       "shadow_min_filter/min_separable.comp",
       {},
       "min_out",
       shared::kMinOutput},
      {"point_shadow_atlas/compute_raster_interface.h",
       "point_shadow_atlas/shadow_cull.comp",
       {},
       "Pages",
       shared::kRasterPages},
      {"point_shadow_atlas/face_decision_interface.h",
       "point_shadow_atlas/shadow_face_decide.comp",
       {},
       "Pages",
       shared::kDecidePages},
      {"point_shadow_atlas/point_shadow_atlas_interface.h",
       "point_shadow_atlas/shadow_atlas.vert",
       {},
       "Faces",
       shared::kAtlasFaces},
      {"gbuffer/gbuffer_interface.h",
       "gbuffer/gbuffer.frag",
       {},
       "Materials",
       shared::kGbufferMaterials},
  };
  return kCases;
}

// The page pool's shaders and the paged atlas's readers (page_pool_interface.h,
// interface/shared/page_tables.h).
const std::vector<BindingCase>& paged_binding_cases() {
  static const std::vector<BindingCase> kCases{
      {"interface/shared/derived_maps.h",
       "common/derived_list.comp",
       {},
       "Records",
       shared::kDerivedRecords},
      {"interface/shared/derived_maps.h",
       "shadow_min_filter/min_separable.comp",
       {{"PAGED", "1"}},
       "PageTables",
       shared::kDerivedPageTables},
      {"interface/shared/derived_maps.h",
       "shadow_moments/moments_blur.comp",
       {{"MOMENTS_TECHNIQUE", "2"}, {"MOMENTS_FORMAT", "rgba32f"}, {"PAGED", "1"}},
       "Records",
       shared::kDerivedRecords},
      {"tiled_lighting/tiled_lighting_interface.h", "tiled_lighting/tiled_lighting.comp",
       kTiledPaged, "PageTables", shared::kTiledPageTables},
      {"layered_penumbra/layered_penumbra_interface.h",
       "layered_penumbra/layered_penumbra.comp",
       {{"SHADOW_PAGE_TABLES", "1"}},
       "PageTables",
       shared::kPenumbraPageTables},
      {"debug_views/debug_views_interface.h",
       "debug_views/atlas_view.comp",
       {{"HAS_SHADOW_DATA", "1"}, {"SHADOW_PAGE_TABLES", "1"}},
       "PageTables",
       shared::kAtlasViewPageTables},
      {"point_shadow_atlas/page_pool_interface.h",
       "point_shadow_atlas/shadow_pool_reclaim.comp",
       {},
       "PoolOrder",
       shared::kPoolOrder},
      {"point_shadow_atlas/page_pool_interface.h",
       "point_shadow_atlas/shadow_pool_publish.comp",
       {},
       "Published",
       shared::kPoolPublished},
      {"point_shadow_atlas/compute_raster_interface.h",
       "point_shadow_atlas/shadow_raster_resolve.comp",
       {{"WRITE_DEPTH", ""}, {"PAGE_POOL", ""}},
       "PoolTables",
       shared::kRasterPoolTables},
  };
  return kCases;
}

// Every binding case.
std::vector<BindingCase> all_binding_cases() {
  std::vector<BindingCase> cases = binding_cases();
  cases.insert(cases.end(), paged_binding_cases().begin(), paged_binding_cases().end());
  return cases;
}

TEST(PassInterface, ShadersDeclareBindingsAtTheHeadersNumbers) {
  for (const BindingCase& c : all_binding_cases()) {
    EXPECT_EQ(binding_of(reflect(c.shader, c.defines), c.name), c.number)
        << c.shader << ": " << c.name;
  }
}

// A pass's *_interface.h is covered when a push-block or binding case checks it against a
// shader; a shared header by compiling alone and being included (above).
TEST(PassInterface, EveryPassInterfaceHeaderHasACase) {
  std::set<std::string> checked;
  for (const PushCase& c : all_push_cases()) checked.insert(c.header);
  for (const BindingCase& c : all_binding_cases()) checked.insert(c.header);
  for (const std::string& header : kHeaders) {
    if (!header.ends_with("_interface.h")) continue;
    EXPECT_TRUE(checked.contains(header)) << "no push-block or binding case checks " << header;
  }
  for (const std::string& header : checked) {
    EXPECT_TRUE(std::find(kHeaders.begin(), kHeaders.end(), header) != kHeaders.end()) << header;
  }
}

}  // namespace
}  // namespace antumbra::passes
