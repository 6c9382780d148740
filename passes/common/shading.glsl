// The per-light shading of every lighting pass (deferred-lighting, tiled-lighting and its
// shadow baselines, shadow-reference): one Blinn-Phong lobe, windowed inverse-square
// attenuation and range cut, so tiled lighting with shadows off matches the untiled pass
// and the reference shades exactly like the techniques it judges.
#ifndef ANTUMBRA_SHADING_GLSL
#define ANTUMBRA_SHADING_GLSL

#include "lights.glsl"

struct Surface {
  vec3 p;  // view-space position
  vec3 n;  // view-space normal (unit)
  vec3 v;  // unit vector to the eye
  vec3 albedo;
  float shininess;
};

Surface make_surface(vec3 p, vec4 normal_rough, vec4 albedo_metal) {
  Surface s;
  s.p = p;
  s.n = normalize(normal_rough.xyz);
  s.v = normalize(-p);
  s.albedo = albedo_metal.rgb;
  s.shininess = mix(128.0, 4.0, clamp(normal_rough.w, 0.0, 1.0));
  return s;
}

// Unshadowed radiance of one light; false when the light cannot reach the point (out of
// range or behind the surface), so callers skip the shadow lookup too. `l` is the unit
// view-space direction to the light.
// Point lights take exactly the arithmetic they always had (goldens stay bit-identical);
// spot lights multiply the cone falloff into the attenuation; directional lights have a
// constant direction and no attenuation or range.
bool shade_light(GpuLight light, Surface s, float specular, out vec3 radiance, out vec3 l) {
  radiance = vec3(0.0);
  l = vec3(0.0);
  float attenuation;
  if (light_is_directional(light)) {
    l = -light.direction_type.xyz;
    attenuation = 1.0;
  } else {
    vec3 to_light = light.position_range.xyz - s.p;
    float dist = length(to_light);
    float range = light.position_range.w;
    if (dist >= range) return false;
    l = to_light / dist;
    attenuation = light_attenuation(dist, range);
    if (light_is_spot(light)) {
      attenuation *= spot_falloff(light, l);
      if (attenuation <= 0.0) return false;
    }
  }
  float n_dot_l = max(dot(s.n, l), 0.0);
  if (n_dot_l <= 0.0) return false;
  vec3 h = normalize(l + s.v);
  float spec = specular * pow(max(dot(s.n, h), 0.0), s.shininess) * (s.shininess + 8.0) / 25.0;
  radiance = light.color_intensity.rgb * light.color_intensity.w * attenuation * n_dot_l *
             (s.albedo + vec3(spec));
  return true;
}

// The unshadowed terms of a lit surface with the G-buffer's optional `emissive` target
// (rgb emitted radiance, a glTF occlusion): emission + ambient * occlusion * albedo.
// Occlusion darkens the ambient (indirect) light only, as glTF specifies; direct lights
// are never scaled by it (docs/technique.md, "The G-buffer"). Passes without the target
// keep their `ambient * albedo` unchanged.
vec3 ambient_and_emission(vec3 ambient, vec3 albedo, vec4 emission_occlusion) {
  return ambient * emission_occlusion.a * albedo + emission_occlusion.rgb;
}

#endif
