#version 460
#extension GL_GOOGLE_include_directive : require
// Step 1 of shadow-moments (docs/technique.md 3, "Filtered shadow maps"): each map texel
// holds the average moments of the factor x factor atlas texels under it. Moments filter
// linearly, so this average is already a box prefilter and the blur that follows
// continues it.

#include "moments_common.glsl"
#include "../common/shadow_sampling.glsl"
#include "../common/moments.glsl"

layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(set = 0, binding = kMomentsInput) uniform sampler2DArray atlas;
layout(set = 0, binding = kMomentsOutput, rgba32f) uniform writeonly image2DArray raw;

#ifdef PAGED
// Every placed page of paged face `f` (light `l`): each map texel of the page's block the
// average moments of its factor x factor atlas texels (cut at the face's edge).
void convert_pages(DerivedPaged f, ShadowLight l) {
  const int page = 1 << int(ANTUMBRA_PAGE_SHIFT);
  int per_page = derived_per_page();
  int used = derived_page_used(f.texels);
  int fct = int(factor);
  uint pages = uint(f.pages_x * f.pages_x);
  for (uint k = derived_first_page(); k < pages; k += derived_page_stride()) {
    ivec2 at_page = ivec2(int(k) % f.pages_x, int(k) / f.pages_x);
    ivec3 place = derived_page_place(f, at_page);
    if (place.z < 0) continue;  // uniform: the whole workgroup reads one entry
    for (int y = int(gl_LocalInvocationID.y); y < used; y += GROUP) {
      for (int x = int(gl_LocalInvocationID.x); x < used; x += GROUP) {
        ivec2 p = ivec2(x, y);
        ivec2 face_texel = at_page * page + p * fct;
        if (any(greaterThanEqual(face_texel, ivec2(f.texels)))) continue;  // the last page's cut
        ivec2 extent = min(ivec2(fct), ivec2(f.texels) - face_texel);
        ivec2 at = place.xy * page + p * fct;
        vec4 sum = vec4(0.0);
        for (int dy = 0; dy < extent.y; ++dy) {
          for (int dx = 0; dx < extent.x; ++dx) {
            float d = texelFetch(atlas, ivec3(at + ivec2(dx, dy), place.z), 0).r;
            sum += moments_encode(shadow_depth_fraction(l, d));
          }
        }
        imageStore(raw, ivec3(place.xy * per_page + p, place.z), sum / float(extent.x * extent.y));
      }
    }
  }
}
#endif

void main() {
#ifdef PAGED
  uint record = derived_record();  // listed: needed
  DerivedPaged paged = derived_paged(record);
  if (paged.table >= 0) {
    convert_pages(paged, shadow_lights[faces[record].info.x]);
    return;
  }
#else
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;
#endif
  ivec2 size = derived_face_extent(record, imageSize(raw).xy);
  if (any(greaterThanEqual(ivec2(gl_WorkGroupID.xy) * int(span), size))) return;
  ivec2 corner = derived_face_origin(record, imageSize(raw).xy);
  int layer = derived_face_layer(record);
  ShadowLight l = shadow_lights[min(faces[record].info.x, uint(ANTUMBRA_MAX_SHADOW_LIGHTS - 1))];
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(span) + ivec2(gl_LocalInvocationID.xy);
  int f = int(factor);
  for (int y = 0; y < int(span); y += GROUP) {
    for (int x = 0; x < int(span); x += GROUP) {
      ivec2 p = origin + ivec2(x, y);
      if (any(greaterThanEqual(p, size))) continue;
      vec4 sum = vec4(0.0);
      for (int dy = 0; dy < f; ++dy) {
        for (int dx = 0; dx < f; ++dx) {
          float d = texelFetch(atlas, ivec3((corner + p) * f + ivec2(dx, dy), layer), 0).r;
          sum += moments_encode(shadow_depth_fraction(l, d));
        }
      }
      imageStore(raw, ivec3(corner + p, layer), sum / float(f * f));
    }
  }
}
