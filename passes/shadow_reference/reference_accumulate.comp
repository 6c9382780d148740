#version 460
#extension GL_GOOGLE_include_directive : require
// One sample of the shadow reference: every pixel tests each light of the batch against
// the depth faces rendered from that light's sample k (hard test, small bias) and adds
// its coloured visibility to the per-pixel, per-light sums: 0 when an opaque caster
// blocks, else the product of the tints of the translucent panes in between (the
// colour layers, white where no pane is; reference_colour.frag), all weighted.
//
// Point and spot lights: sample k is a point of the light's sphere, seen through cube
// faces. Weight ("projected", the default): cos(theta_s) / r^2, theta_s between the
// sphere's normal at the sample and the direction to the receiver, r the distance; zero
// where the sample lies on the part of the sphere the receiver cannot see. Samples are
// uniform by area on the sphere and dOmega = cos(theta_s) dA / r^2, so the weighted
// average is the visible fraction of the solid angle of the light's disc as seen from
// this receiver (a uniformly radiant sphere looks like a uniformly bright disc), exact
// even where the receiver is close to the light (docs/technique.md, "Reference").
// "uniform" weighs every sample 1 (the projection of a uniform sphere: more weight near
// the disc's rim, a linear penumbra profile).
// Directional light: sample k is a direction spread uniformly over the sun's disc, seen
// through its own orthographic map (matrices[]); every sample weighs 1 in both modes.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "reference_faces.glsl"
#define ANTUMBRA_REFERENCE_ACCUMULATE_SHADER
#include "reference_interface.h"

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kRefAccumulateFrame) uniform Frame {
  FrameUniforms frame;
};
#include "../common/view_space.glsl"
layout(set = 0, binding = kRefAccumulateLights, std430) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kRefAccumulateDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kRefAccumulateNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kRefAccumulateFaces) uniform sampler2DArray faces;
layout(set = 0, binding = kRefAccumulatePoints, std430) readonly buffer Points {
  vec4 points[];
};
// Per (slot, pixel) two vec4: (weight * rgb visibility, weight) and
// (weight * opaque visibility, weight * untinted visibility, 0, 0).
layout(set = 0, binding = kRefAccumulateVisibility, std430) buffer Visibility {
  vec4 visibility[];
};
layout(set = 0, binding = kRefAccumulateTints) uniform sampler2DArray tints;
layout(set = 0, binding = kRefAccumulateMatrices, std430) readonly buffer Matrices {
  mat4 matrices[];
};

// A tint this close to white is no tint.
const float kUntinted = 0.998;
// A receiver this close to the nearest pane (a fraction of the far plane or the map's
// depth; the colour layers are 16-bit floats) is that pane's own surface: not tinted.
const float kPaneTolerance = 2e-3;

// One sample's hard test at a receiver, what main() adds to the light's sums.
struct SampleTest {
  bool counts;     // false: nothing is added (the resolve skips the pixel for this light)
  float weight;    // the sample's weight (module comment)
  float lit;       // 0 behind an opaque caster, else 1
  vec3 fuv;        // face uv and layer of the lookup, for the colour layers
  bool inside;     // the lookup lies on the map and inside its depth range
  float receiver;  // the offset receiver's distance, as the colour layers store it
};

// Directional light: sample `point` is a direction over the sun's disc with its own
// orthographic map, so the receiver is projected by that sample's matrix.
SampleTest sun_sample_test(uint light, uint slot, uint point, vec4 pf, vec3 p, vec3 n) {
  SampleTest t = SampleTest(true, 1.0, 1.0, vec3(0.0), false, 0.0);
  // The resolve skips surfaces facing away from the sun's centre too.
  vec3 to_sun = -normalize(mat3(frame.inv_view) * lights[light].direction_type.xyz);
  if (dot(n, to_sun) <= 0.0) {
    t.counts = false;
    return t;
  }
  // Normal offset of `normal_offset` map texels, more at grazing angles.
  float n_dot_l = clamp(dot(n, -pf.xyz), 0.0, 1.0);
  float texel = 2.0 * pf.w / face_size;
  vec3 q = p + n * (normal_offset * texel * (2.0 - n_dot_l));
  vec4 clip = matrices[point] * vec4(q, 1.0);
  t.fuv = vec3(clip.xy * 0.5 + 0.5, float(slot * 6u));
  // Outside the map (never, for receivers the fit holds) or its depth range: lit.
  t.inside = clip.z > 0.0 && clip.z < 1.0 && all(greaterThanEqual(t.fuv.xy, vec2(0.0))) &&
             all(lessThanEqual(t.fuv.xy, vec2(1.0)));
  if (t.inside) {
    float stored = textureLod(faces, t.fuv, 0.0).r;
    t.lit = clip.z > stored + depth_bias ? 0.0 : 1.0;
    t.receiver = clip.z;
  }
  return t;
}

// Point and spot lights: the sample is a point of the light's sphere seen through cube
// faces, weighed by how much of the disc it stands for from this receiver.
SampleTest sphere_sample_test(uint light, uint slot, vec4 pf, vec3 p, vec3 n) {
  SampleTest t = SampleTest(true, 1.0, 1.0, vec3(0.0), false, 0.0);
  vec4 centre_size = lights[light].world_size;
  vec3 to_centre = centre_size.xyz - p;
  float dist = length(to_centre);
  // The resolve skips these pixels too (no light reaches them).
  if (dist >= lights[light].position_range.w || dot(n, to_centre) <= 0.0) {
    t.counts = false;
    return t;
  }
  vec3 s = pf.xyz;
  vec3 to_receiver = p - s;
  float len = length(to_receiver);
  if (weighting == 0u && centre_size.w > 0.0 && len > 0.0) {
    float cos_sample = dot((s - centre_size.xyz) / centre_size.w, to_receiver / len);
    t.weight = max(cos_sample, 0.0) / (len * len);
  }
  if (t.weight <= 0.0) {
    t.counts = false;
    return t;
  }

  // Normal offset of about `normal_offset` texels at the receiver's distance, more at
  // grazing angles (where a texel covers more depth), so faces do not self-shadow.
  float n_dot_l = len > 0.0 ? clamp(dot(n, -to_receiver / len), 0.0, 1.0) : 1.0;
  float texel = 2.0 * len / face_size;
  vec3 d = p + n * (normal_offset * texel * (2.0 - n_dot_l)) - s;
  uint face = reference_cube_face(d);
  vec4 clip = reference_face_clip(d, face, near, pf.w);
  if (clip.w > near) {
    float z = clip.z / clip.w;
    t.fuv = vec3(clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0), float(slot * 6u + face));
    float stored = textureLod(faces, t.fuv, 0.0).r;
    t.lit = (z < 1.0 && z > stored + depth_bias) ? 0.0 : 1.0;
    t.inside = z < 1.0;
    t.receiver = length(d) / pf.w;
  }
  return t;
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, image_size))) return;
  float depth = texelFetch(g_depth, ivec2(pixel), 0).r;
  if (depth >= 1.0) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  vec3 p = (frame.inv_view * vec4(view_position(uv, depth), 1.0)).xyz;
  vec3 n = normalize(mat3(frame.inv_view) * normalize(texelFetch(g_normal, ivec2(pixel), 0).xyz));
  uint pixels = image_size.x * image_size.y;
  uint pixel_index = pixel.y * image_size.x + pixel.x;

  for (uint slot = 0u; slot < light_count; ++slot) {
    uint light = first_light + slot;
    if (light >= frame.counts.x) break;
    uint point = light * samples + sample_index;
    vec4 pf = points[point];
    if (pf.w < 0.0) continue;  // no shadows: visibility stays 1

    SampleTest t;
    if (light_is_directional(lights[light])) {
      t = sun_sample_test(light, slot, point, pf, p, n);
    } else {
      t = sphere_sample_test(light, slot, pf, p, n);
    }
    if (!t.counts) continue;
    vec3 tint = vec3(1.0);
    if (tinted != 0u && t.inside && t.lit > 0.0) {
      vec4 panes = textureLod(tints, t.fuv, 0.0);
      if (t.receiver > panes.a + kPaneTolerance) tint = panes.rgb;
    }
    float untinted = (t.lit > 0.0 && all(greaterThanEqual(tint, vec3(kUntinted)))) ? 1.0 : 0.0;
    uint index = 2u * (slot * pixels + pixel_index);
    visibility[index] += vec4(t.weight * t.lit * tint, t.weight);
    visibility[index + 1u] += vec4(t.weight * t.lit, t.weight * untinted, 0.0, 0.0);
  }
}
