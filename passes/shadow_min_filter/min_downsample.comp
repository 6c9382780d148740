#version 460
#extension GL_GOOGLE_include_directive : require
// Step 1 of the separable min filter (docs/technique.md section 1, step 4, the cheaper
// alternative to the blocker search): each output texel takes the nearest depth of the
// factor x factor atlas texels under it, read four at a time with gathers, so every
// atlas texel is read once.

#include "min_common.glsl"

layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(set = 0, binding = kMinInput) uniform sampler2DArray atlas;
layout(set = 0, binding = kMinOutput, r32f) uniform writeonly image2DArray coarse;

// `p`: a texel of the coarse map's layer `layer` (not of the face).
float nearest_under(ivec2 p, int layer) {
  ivec2 base = p * int(factor);
  if (factor == 1u) return texelFetch(atlas, ivec3(base, layer), 0).r;
  // Faces smaller than the layer are powers of two of at least `factor` texels, so the
  // quads below never reach past the face.
  vec2 texel = 1.0 / vec2(textureSize(atlas, 0).xy);
  float nearest = 1.0;
  for (int y = 0; y < int(factor); y += 2) {
    for (int x = 0; x < int(factor); x += 2) {
      // The shared corner of the 2x2 quad at (x, y) selects exactly those four texels.
      vec2 uv = vec2(base + ivec2(x, y) + 1) * texel;
      vec4 g = textureGather(atlas, vec3(uv, float(layer)), 0);
      nearest = min(nearest, min(min(g.x, g.y), min(g.z, g.w)));
    }
  }
  return nearest;
}

void main() {
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;
  ivec2 size = derived_face_extent(record, imageSize(coarse).xy);
  ivec2 corner = derived_face_origin(record, imageSize(coarse).xy);
  int layer = derived_face_layer(record);
  if (any(greaterThanEqual(ivec2(gl_WorkGroupID.xy) * int(span), size))) return;
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(span) + ivec2(gl_LocalInvocationID.xy);
  for (int y = 0; y < int(span); y += GROUP) {
    for (int x = 0; x < int(span); x += GROUP) {
      ivec2 p = origin + ivec2(x, y);
      if (all(lessThan(p, size))) {
        imageStore(coarse, ivec3(corner + p, layer), vec4(nearest_under(corner + p, layer)));
      }
    }
  }
}
