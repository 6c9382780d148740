#version 460
#extension GL_GOOGLE_include_directive : require
// Writes the reference's outputs from the accumulator: ambient + shadowed lights (with
// HAS_EMISSIVE: + emission, the ambient scaled by occlusion, as every lighting pass does;
// common/shading.glsl), times exposure (background as tiled-lighting draws it), and the
// penumbra light count. Defines: HDR_FORMAT, HAS_PENUMBRA, HAS_EMISSIVE.
#include "../common/frame.glsl"
#define ANTUMBRA_REFERENCE_FINAL_SHADER
#include "reference_interface.h"

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kRefFinalFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kRefFinalDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kRefFinalAlbedo) uniform sampler2D g_albedo;
layout(set = 0, binding = kRefFinalAccum, std430) readonly buffer Accum {
  vec4 accum[];
};
layout(set = 0, binding = kRefFinalHdr, HDR_FORMAT) uniform writeonly image2D out_hdr;
#if HAS_PENUMBRA
layout(set = 0, binding = kRefFinalPenumbra, r32f) uniform writeonly image2D out_penumbra;
#endif
#if HAS_EMISSIVE
#include "../common/shading.glsl"
layout(set = 0, binding = kRefFinalEmissive) uniform sampler2D g_emissive;
#endif

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, image_size))) return;
  float depth = texelFetch(g_depth, ivec2(pixel), 0).r;
  vec4 sum = accum[pixel.y * image_size.x + pixel.x];
  vec3 color = frame.ambient.rgb * 0.5;  // background
  float penumbra = 0.0;
  if (depth < 1.0) {
    vec3 albedo = texelFetch(g_albedo, ivec2(pixel), 0).rgb;
#if HAS_EMISSIVE
    // Read only where the scene emits (else not written): no emission, occlusion 1.
    vec4 emission = vec4(0.0, 0.0, 0.0, 1.0);
    if ((frame.counts.z & kFrameSceneEmits) != 0u) {
      emission = texelFetch(g_emissive, ivec2(pixel), 0);
    }
    color = (ambient_and_emission(frame.ambient.rgb * ambient_scale, albedo, emission) + sum.rgb) *
            exposure;
#else
    color = (frame.ambient.rgb * ambient_scale * albedo + sum.rgb) * exposure;
#endif
    penumbra = sum.a;
  }
  imageStore(out_hdr, ivec2(pixel), vec4(color, 1.0));
#if HAS_PENUMBRA
  imageStore(out_penumbra, ivec2(pixel), vec4(penumbra));
#endif
}
