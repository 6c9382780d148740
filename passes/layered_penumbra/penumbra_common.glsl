// Shadow-face lookups and the blocker search of the layered penumbra pass. Faces follow
// shadow_data.glsl: face k of a light (0..5 = +X -X +Y -Y +Z -Z) sits at atlas layer
// first_layer + k; its view_proj is a 90-degree perspective with Vulkan depth 0..1.
#ifndef ANTUMBRA_PENUMBRA_COMMON_GLSL
#define ANTUMBRA_PENUMBRA_COMMON_GLSL

struct PenumbraSample {
  float width;     // penumbra width in world units at the receiver; 0 when no blocker
  bool in_shadow;  // hard shadow at the pixel's centre
  uint colour;     // translucent shadow colour, r<<24|g<<16|b<<8|a (white = clear)
};

uint cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
  return d.z >= 0.0 ? 4u : 5u;
}

// Distance along the face's axis from the stored 0..1 depth (perspective, near n, far f).
float linear_face_depth(float depth, float n, float f) {
  return n * f / (f - depth * (f - n));
}

uint pack_colour(vec4 c) {
  uvec4 b = uvec4(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return (b.r << 24u) | (b.g << 16u) | (b.b << 8u) | b.a;
}

PenumbraSample estimate_penumbra(ShadowLight sl, vec3 world, vec3 n_world, vec3 l) {
  PenumbraSample result;
  result.width = 0.0;
  result.in_shadow = false;
  result.colour = 0xFFFFFFFFu;

  float n = sl.params.y;
  float f = sl.position_range.w;
  float light_size = sl.params.x * light_size_scale;
  // Normal offset grows at grazing angles, where acne appears first.
  float n_dot_l = clamp(dot(n_world, l), 0.0, 1.0);
  vec3 p = world + n_world * normal_offset * (1.0 - n_dot_l);
  vec3 from_light = p - sl.position_range.xyz;
  uint face = cube_face(from_light);
  int layer = int(sl.params.z) + int(face);
  vec4 clip = faces[layer].view_proj * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  float z_receiver = linear_face_depth(ndc.z, n, f);
  float z_centre = linear_face_depth(texture(atlas, vec3(uv, float(layer))).r, n, f);
  // A small depth-proportional tolerance on top of the raster slope bias.
  float tolerance = 0.01 * z_receiver;
  result.in_shadow = z_centre < z_receiver - tolerance;

  // Blocker search (PCSS step 1) over a square region that grows with the light's size
  // and shrinks with distance: blockers near the receiver matter most.
  float texel = 1.0 / float(shadow_header.counts.z);
  float radius = clamp(search_scale * light_size / z_receiver, texel, 0.25);
  int taps = int(search_taps);
  float step_uv = taps > 1 ? 2.0 * radius / float(taps - 1) : 0.0;
  float blocker_sum = 0.0;
  int blockers = 0;
  for (int y = 0; y < taps; ++y) {
    for (int x = 0; x < taps; ++x) {
      vec2 offset = (vec2(x, y) - 0.5 * float(taps - 1)) * step_uv;
      vec2 tap = clamp(uv + offset, vec2(0.5 * texel), vec2(1.0 - 0.5 * texel));
      float z = linear_face_depth(texture(atlas, vec3(tap, float(layer))).r, n, f);
      if (z < z_receiver - tolerance) {
        blocker_sum += z;
        ++blockers;
      }
    }
  }
  if (blockers > 0) {
    float z_blocker = blocker_sum / float(blockers);
    // w_penumbra = (d_receiver - d_blocker) * w_light / d_blocker  (seed 000, eq. for PCSS)
    result.width = max((z_receiver - z_blocker) * light_size / z_blocker, 1e-4);
  }
#ifdef HAS_COLOUR
  result.colour = pack_colour(texture(colour_atlas, vec3(uv, float(layer))));
#endif
  return result;
}

#endif
