#version 460
#extension GL_GOOGLE_include_directive : require
// The next depth layer: fragments at or in front of the layer in front (plus a gap that
// grows with the surface's depth slope across a texel, so one surface does not peel from
// itself) are
// discarded; the depth test keeps the nearest of the rest. Surfaces edge-on to the light
// are skipped too: they cover no solid angle from it, yet rasterise as slivers along
// silhouettes, exactly where the inner wedges need Z2 and Z3 to be the occluder's back
// and the receiver.
#include "wedges_common.glsl"
#ifdef CUT
#define MATERIAL_SRGB_TEXTURES kWedgeSrgbTextures
#define MATERIAL_SAMPLER kWedgeSampler
#include "../common/material_textures.glsl"
#endif

layout(set = 0, binding = kWedgeFirst) uniform sampler2DArray previous;

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
#ifdef CUT
// Cut casters (docs/technique.md, "Draw classes"): peeled only where they cast in the
// atlas (Z1), their front towards the light and their alpha at or above the cutoff.
layout(set = 0, binding = kWedgeMaterials, std430) readonly buffer Materials {
  GpuMaterial materials[];
};
layout(location = 2) flat in uint in_material;
layout(location = 3) in vec4 in_uv;
layout(location = 4) flat in uint in_mirrored;
#endif

// |cos| of the angle between the surface and the light's ray below which a fragment
// counts as edge-on (about 1 degree off the ray).
const float kEdgeOn = 0.02;

void main() {
#ifdef CUT
  {
    GpuMaterial m = materials[in_material];
    vec4 dx = dFdx(in_uv);
    vec4 dy = dFdy(in_uv);
    bool front = gl_FrontFacing != (in_mirrored != 0u);
    if (!front && (m.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u) discard;
    if (material_cut(m, in_uv, dx, dy)) discard;
  }
#endif
  ShadowLight sl = shadow_lights[shadow_faces[layer].info.x];
  float d = wedge_linearise(sl, gl_FragCoord.z);
  vec3 ray = normalize(in_position - sl.position_range.xyz);
  float facing = abs(dot(normalize(in_normal), ray));
  if (facing < kEdgeOn) discard;
  // Depth change across one texel: the texel's width at this distance times the tangent
  // of the surface's tilt, from the geometry rather than fwidth (undefined beside a
  // triangle's edge, which is where silhouettes are).
  float share = sl.projection.z > 0.0 ? sl.projection.z : 1.0;  // 0: the whole layer
  float texel = 2.0 * d * sl.projection.x / max(extent.x * share, 1.0);
  float slope = texel * min(sqrt(max(1.0 - facing * facing, 0.0)) / facing, 8.0);
  vec2 map_uv = gl_FragCoord.xy / extent;
#ifdef PAGED
  // The second layer peels from the atlas (paged), the third from this pass's second.
  float front = first_paged != 0u ? wedge_first_depth(previous, layer, map_uv)
                                  : textureLod(previous, vec3(map_uv, float(layer)), 0.0).r;
#else
  float front = textureLod(previous, vec3(map_uv, float(layer)), 0.0).r;
#endif
  // Nothing in front (the layer before found no surface here): nothing behind it either.
  if (front >= 1.0 || d <= wedge_linearise(sl, front) + gap + 2.0 * slope) discard;
}
