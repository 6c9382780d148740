#version 460
#extension GL_GOOGLE_include_directive : require
// Samples of the ray-traced shadow reference (visibility "rays"; docs/technique.md 7,
// "Ray-traced reference"): from every pixel, one ray per light of the batch and sample,
// to sample k of the light, through the scene's BVH (common/bvh.glsl). No shadow map is
// involved, so there is no bias, no texel size and no near-plane clipping of casters
// other than `near` next to the sample itself. The sums are reference_accumulate.comp's,
// which reference_resolve.comp shades: the same samples, the same weights.
//
// What a hit does follows the shadow atlas's draw classes (docs/technique.md, "Draw
// classes"), with the rasterisers' geometric facing (cross(b - a, c - a) turned towards
// the light):
//  - a translucent material tints (the product of mix(1, transmittance.rgb,
//    transmittance.a) over the panes crossed) where the surface is turned towards the
//    light, so a closed pane counts once and a pane never tints its own lit surface
//    (the ray leaves from the receiver's side);
//  - a one-sided material blocks only where it is turned towards the light;
//  - an alpha-tested material blocks only where its alpha (the finest level of its base
//    colour texture at the hit) reaches the cutoff;
//  - anything else blocks, and ends the ray.
// The ray starts two depth-buffer steps towards the camera and `ray_offset` along the
// normal: positions rebuilt from a 16-bit depth would otherwise shadow themselves.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#define ANTUMBRA_REFERENCE_TRACE_SHADER
#include "reference_interface.h"
#define MATERIAL_SRGB_TEXTURES kRefTraceSrgbTextures
#define MATERIAL_SAMPLER kRefTraceSampler
#include "../common/material_textures.glsl"

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kRefTraceFrame) uniform Frame {
  FrameUniforms frame;
};
#include "../common/view_space.glsl"
layout(set = 0, binding = kRefTraceLights, std430) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kRefTraceDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kRefTraceNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kRefTracePoints, std430) readonly buffer Points {
  vec4 points[];
};
// Per (slot, pixel) two vec4, as reference_accumulate.comp writes them.
layout(set = 0, binding = kRefTraceVisibility, std430) buffer Visibility {
  vec4 visibility[];
};
layout(set = 0, binding = kRefTraceBvh, std430) readonly buffer Bvh {
  vec4 bvh[];  // 2 per node, then 3 per triangle in leaf order
};
layout(set = 0, binding = kRefTraceIndices, std430) readonly buffer Indices {
  uint indices[];
};
layout(set = 0, binding = kRefTraceVertices, std430) readonly buffer Vertices {
  float vertex_words[];  // GpuVertex: position, normal, material (7 words)
};
layout(set = 0, binding = kRefTraceAttributes, std430) readonly buffer Attributes {
  GpuVertexAttributes attributes[];
};
layout(set = 0, binding = kRefTraceMaterials, std430) readonly buffer Materials {
  GpuMaterial materials[];
};

// A tint this close to white is no tint (reference_accumulate.comp's).
const float kUntinted = 0.998;

// What the ray has crossed so far.
vec3 g_tint;

vec3 vertex_position(uint index) {
  uint w = 7u * index;
  return vec3(vertex_words[w], vertex_words[w + 1u], vertex_words[w + 2u]);
}

// Whether the ray goes on past this hit (common/bvh.glsl's BVH_VISIT): false for an
// opaque one. `towards` is the ray's direction, towards the light.
vec3 g_towards;
bool visit(uint triangle, vec2 barycentrics) {
  uint i0 = indices[3u * triangle];
  uint i1 = indices[3u * triangle + 1u];
  uint i2 = indices[3u * triangle + 2u];
  GpuMaterial m = materials[floatBitsToUint(vertex_words[7u * i0 + 6u])];
  bool translucent = m.params.z > 0.5;
  bool one_sided = (m.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u;
  if (translucent || one_sided) {
    vec3 a = vertex_position(i0);
    vec3 n = cross(vertex_position(i1) - a, vertex_position(i2) - a);
    if (dot(n, g_towards) <= 0.0) return true;  // turned away from the light
  }
  if (translucent) {
    vec4 t = m.transmittance;
    g_tint *= mix(vec3(1.0), clamp(t.rgb, 0.0, 1.0), clamp(t.a, 0.0, 1.0));
    return true;
  }
  if (m.params.w >= 0.0) {
    vec4 uv = attributes[i0].uv * (1.0 - barycentrics.x - barycentrics.y) +
              attributes[i1].uv * barycentrics.x + attributes[i2].uv * barycentrics.y;
    if (material_cut(m, uv, vec4(0.0), vec4(0.0))) return true;
  }
  return false;
}

#define BVH_NODE(i) BvhNode(bvh[2u * (i)], bvh[2u * (i) + 1u])
#define BVH_VERTEX(i) bvh[2u * node_count + (i)]
#define BVH_VISIT(triangle, t, barycentrics) visit(triangle, barycentrics)
#include "../common/bvh.glsl"

// The ray's visibility: 0 behind an opaque hit, else 1 with g_tint the panes' product.
float trace(vec3 origin, vec3 direction, float t_max) {
  g_tint = vec3(1.0);
  g_towards = direction;
  return bvh_visit(node_count, origin, direction, 0.0, t_max) ? 0.0 : 1.0;
}

void add(uint index, float weight, float lit) {
  vec3 tint = lit > 0.0 ? g_tint : vec3(0.0);
  float untinted = (lit > 0.0 && all(greaterThanEqual(tint, vec3(kUntinted)))) ? 1.0 : 0.0;
  visibility[index] += vec4(weight * lit * tint, weight);
  visibility[index + 1u] += vec4(weight * lit, weight * untinted, 0.0, 0.0);
}

// Weighting "projected" of a sphere light: the samples are directions spread evenly over
// the solid angle the sphere subtends from the receiver (a Fibonacci spiral on the
// spherical cap, equal-area), each weighing 1, so their average is the visible fraction
// of that solid angle, the quantity the map-based samples' cos / r^2 weights estimate
// (reference_accumulate.comp), without their variance. A ray ends `near` short of the
// sphere. A receiver inside the sphere sees it everywhere: lit.
const float kGoldenAngle = 2.39996322973;
void sphere_samples(uint index, vec3 origin, vec3 to_centre, float dist, float radius) {
  if (dist <= radius) {
    g_tint = vec3(1.0);
    for (uint k = sample_first; k < sample_first + sample_count; ++k) add(index, 1.0, 1.0);
    return;
  }
  vec3 axis = to_centre / dist;
  float sin_max = radius / dist;
  float cos_max = sqrt(max(1.0 - sin_max * sin_max, 0.0));
  vec3 helper = abs(axis.x) < 0.5 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(axis, helper));
  vec3 t2 = cross(axis, t1);
  float c = dist * dist - radius * radius;
  for (uint k = sample_first; k < sample_first + sample_count; ++k) {
    float u = (float(k) + 0.5) / float(samples);
    float cos_t = 1.0 - u * (1.0 - cos_max);
    float sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
    float phi = float(k) * kGoldenAngle;
    vec3 w = axis * cos_t + (t1 * cos(phi) + t2 * sin(phi)) * sin_t;
    float b = dot(w, to_centre);
    float hit = b - sqrt(max(b * b - c, 0.0));  // where the direction meets the sphere
    add(index, 1.0, hit > near ? trace(origin, w, hit - near) : 1.0);
  }
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, image_size))) return;
  float depth = texelFetch(g_depth, ivec2(pixel), 0).r;
  if (depth >= 1.0) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  vec3 p = (frame.inv_view * vec4(view_position(uv, depth), 1.0)).xyz;
  vec3 n = normalize(mat3(frame.inv_view) * normalize(texelFetch(g_normal, ivec2(pixel), 0).xyz));
  // A stored depth stands for any surface within a step of it along the view ray: start
  // above the farthest of those, two steps towards the camera (a 16-bit depth buffer
  // is centimetres off at a few metres), then rayOffset along the normal.
  float step = max(depth_step, depth * 1.2e-7);
  vec3 nearer = (frame.inv_view * vec4(view_position(uv, max(depth - step, 0.0)), 1.0)).xyz;
  vec3 origin = p + 2.0 * (nearer - p) + n * ray_offset;
  uint pixels = image_size.x * image_size.y;
  uint pixel_index = pixel.y * image_size.x + pixel.x;

  for (uint slot = 0u; slot < light_count; ++slot) {
    uint light = first_light + slot;
    if (light >= frame.counts.x) break;
    if (points[light * samples].w < 0.0) continue;  // no shadows: visibility stays 1
    uint index = 2u * (slot * pixels + pixel_index);
    if (light_is_directional(lights[light])) {
      // The resolve skips surfaces facing away from the sun's centre too.
      vec3 to_sun = -normalize(mat3(frame.inv_view) * lights[light].direction_type.xyz);
      if (dot(n, to_sun) <= 0.0) continue;
      for (uint k = sample_first; k < sample_first + sample_count; ++k) {
        add(index, 1.0, trace(origin, -points[light * samples + k].xyz, scene_size));
      }
      continue;
    }
    vec4 centre_size = lights[light].world_size;
    vec3 to_centre = centre_size.xyz - p;
    float dist = length(to_centre);
    // The resolve skips these pixels too (no light reaches them).
    if (dist >= lights[light].position_range.w || dot(n, to_centre) <= 0.0) continue;
    if (weighting == 0u && centre_size.w > 0.0) {
      sphere_samples(index, origin, to_centre, dist, centre_size.w);
      continue;
    }
    for (uint k = sample_first; k < sample_first + sample_count; ++k) {
      vec3 s = points[light * samples + k].xyz;
      vec3 to_receiver = p - s;
      float len = length(to_receiver);
      float weight = 1.0;
      if (weighting == 0u && centre_size.w > 0.0 && len > 0.0) {
        float cos_sample = dot((s - centre_size.xyz) / centre_size.w, to_receiver / len);
        weight = max(cos_sample, 0.0) / (len * len);
      }
      if (weight <= 0.0) continue;
      vec3 direction = s - origin;
      float reach = length(direction);
      add(index, weight, reach > near ? trace(origin, direction, 1.0 - near / reach) : 1.0);
    }
  }
}
