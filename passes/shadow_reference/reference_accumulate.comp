#version 460
#extension GL_GOOGLE_include_directive : require
// One sample of the shadow reference: every pixel tests each light of the batch against
// the depth faces rendered from that light's sample point k (hard test, small bias) and
// adds (weight * lit, weight) to its per-pixel, per-light visibility sums.
//
// Weight ("projected", the default): the cosine between the sphere's normal at the
// sample and the direction to the receiver, zero on the far hemisphere. A uniformly
// radiant sphere seen from the receiver is a uniformly bright disk; cosine-weighted
// uniform sphere samples project to a uniform density on that disk, so the average is
// the visible fraction of the light. "uniform" weighs every sample 1 (the projection of
// a uniform sphere: more weight near the disk's rim, a linear penumbra profile).
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "reference_faces.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform sampler2D g_depth;
layout(set = 0, binding = 3) uniform sampler2D g_normal;
layout(set = 0, binding = 4) uniform sampler2DArray faces;
layout(set = 0, binding = 5, std430) readonly buffer Points { vec4 points[]; };
layout(set = 0, binding = 6, std430) buffer Visibility { vec2 visibility[]; };

layout(push_constant) uniform Params {
  uvec2 image_size;
  uint sample_index;
  uint samples;
  uint first_light;
  uint light_count;  // lights in this batch
  float near;
  float normal_offset;  // texels
  float face_size;
  uint weighting;  // 0 projected, 1 uniform
  float depth_bias;
};

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, image_size))) return;
  float depth = texelFetch(g_depth, ivec2(pixel), 0).r;
  if (depth >= 1.0) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  vec4 view = frame.inv_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec3 p = (frame.inv_view * vec4(view.xyz / view.w, 1.0)).xyz;
  vec3 n = normalize(mat3(frame.inv_view) * normalize(texelFetch(g_normal, ivec2(pixel), 0).xyz));
  uint pixels = image_size.x * image_size.y;
  uint pixel_index = pixel.y * image_size.x + pixel.x;

  for (uint slot = 0u; slot < light_count; ++slot) {
    uint light = first_light + slot;
    if (light >= frame.counts.x) break;
    vec4 centre_size = lights[light].world_size;
    vec3 to_centre = centre_size.xyz - p;
    float dist = length(to_centre);
    // The resolve skips these pixels too (no light reaches them).
    if (dist >= lights[light].position_range.w || dot(n, to_centre) <= 0.0) continue;
    vec4 pf = points[light * samples + sample_index];
    if (pf.w < 0.0) continue;  // no shadows: visibility stays 1

    vec3 s = pf.xyz;
    vec3 to_receiver = p - s;
    float len = length(to_receiver);
    float weight = 1.0;
    if (weighting == 0u && centre_size.w > 0.0 && len > 0.0) {
      weight = max(dot((s - centre_size.xyz) / centre_size.w, to_receiver / len), 0.0);
    }
    if (weight <= 0.0) continue;

    // Normal offset of about `normal_offset` texels at the receiver's distance, more at
    // grazing angles (where a texel covers more depth), so faces do not self-shadow.
    float n_dot_l = len > 0.0 ? clamp(dot(n, -to_receiver / len), 0.0, 1.0) : 1.0;
    float texel = 2.0 * len / face_size;
    vec3 d = p + n * (normal_offset * texel * (2.0 - n_dot_l)) - s;
    uint face = reference_cube_face(d);
    vec4 clip = reference_face_clip(d, face, near, pf.w);
    float lit = 1.0;
    if (clip.w > near) {
      float z = clip.z / clip.w;
      vec2 fuv = clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0);
      float stored = textureLod(faces, vec3(fuv, float(slot * 6u + face)), 0.0).r;
      lit = (z < 1.0 && z > stored + depth_bias) ? 0.0 : 1.0;
    }
    visibility[slot * pixels + pixel_index] += vec2(weight * lit, weight);
  }
}
