#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "../common/lights.glsl"

// Untiled deferred shading of every scene light (point, spot, directional), no shadows:
// the reference lighting that shadow techniques multiply into.
layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform sampler2D g_depth;
layout(set = 0, binding = 3) uniform sampler2D g_normal;
layout(set = 0, binding = 4) uniform sampler2D g_albedo;

layout(push_constant) uniform Params {
  float exposure;
  float ambient_scale;
  float specular;
};

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

vec3 view_position(vec2 uv, float depth) {
  vec4 clip = vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec4 view = frame.inv_proj * clip;
  return view.xyz / view.w;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(g_depth, pixel, 0).r;
  if (depth >= 1.0) {
    out_color = vec4(frame.ambient.rgb * 0.5, 1.0);  // background
    return;
  }
  vec4 normal_rough = texelFetch(g_normal, pixel, 0);
  vec4 albedo_metal = texelFetch(g_albedo, pixel, 0);
  vec3 n = normalize(normal_rough.xyz);
  vec3 p = view_position(in_uv, depth);
  vec3 v = normalize(-p);
  float shininess = mix(128.0, 4.0, clamp(normal_rough.w, 0.0, 1.0));

  vec3 color = frame.ambient.rgb * ambient_scale * albedo_metal.rgb;
  uint count = frame.counts.x;
  for (uint i = 0u; i < count; ++i) {
    GpuLight light = lights[i];
    // Same per-type rules as tiled_lighting/shading.glsl; point lights unchanged.
    vec3 l;
    float attenuation;
    if (light_is_directional(light)) {
      l = -light.direction_type.xyz;
      attenuation = 1.0;
    } else {
      vec3 to_light = light.position_range.xyz - p;
      float dist = length(to_light);
      float range = light.position_range.w;
      if (dist >= range) continue;
      l = to_light / dist;
      attenuation = light_attenuation(dist, range);
      if (light_is_spot(light)) attenuation *= spot_falloff(light, l);
    }
    float n_dot_l = max(dot(n, l), 0.0);
    if (n_dot_l <= 0.0) continue;
    vec3 h = normalize(l + v);
    float spec = specular * pow(max(dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.0;
    vec3 radiance = light.color_intensity.rgb * light.color_intensity.w * attenuation;
    color += radiance * n_dot_l * (albedo_metal.rgb + vec3(spec));
  }
  out_color = vec4(color * exposure, 1.0);
}
