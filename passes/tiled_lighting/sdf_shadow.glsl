// Signed-distance-field soft shadows (tiled-lighting's shadows = sdf; docs/technique.md 3,
// "Signed distance field soft shadows"). From the receiver, sphere tracing walks the
// field towards the light. At distance t along the ray the light's cone (the light's disk
// seen from the receiver) has radius r(t) = R t / D for a sphere of radius R at distance
// D, t tan(angular radius) for the sun; an occluder at signed distance d from the ray
// covers about 1/2 - d / (2 r) of it, and the smallest such visibility along the ray is
// the light's. Marching through occluders (negative d) at a minimum step keeps the
// inner half of the penumbra, so the ramp spans the similar-triangles width centred on
// the hard edge. Expects `sdf_volume` (sampler2DArray, linear), SdfInfo `sdf_info`.
#ifndef ANTUMBRA_SDF_SHADOW_GLSL
#define ANTUMBRA_SDF_SHADOW_GLSL

#ifndef SDF_STEPS
#define SDF_STEPS 64
#endif

// Trilinear: bilinear in the layer by the sampler, linear across layers by hand. Outside
// the volume: the band (nothing there).
float sdf_distance(vec3 p) {
  vec3 g = (p - sdf_info.origin.xyz) / sdf_info.voxel.xyz - 0.5;  // voxel-centre coordinates
  vec3 dims = vec3(sdf_info.dims.xyz);
  if (any(lessThan(g, vec3(-0.5))) || any(greaterThan(g, dims - 0.5))) return sdf_info.band.x;
  vec2 uv = (g.xy + 0.5) / dims.xy;
  float z = clamp(g.z, 0.0, dims.z - 1.0);
  float k = floor(z);
  float a = textureLod(sdf_volume, vec3(uv, k), 0.0).r;
  float b = textureLod(sdf_volume, vec3(uv, min(k + 1.0, dims.z - 1.0)), 0.0).r;
  return mix(a, b, z - k);
}

// Visibility (1 lit) of the light seen along unit world direction `l` from the surface
// point `p` (normal `n`); `distance` to the light (the sun: infinite), `radius` its
// radius (the sun: tan of its angular radius).
float sdf_visibility(vec3 p, vec3 n, vec3 l, float distance, float radius, bool sun) {
  if (sdf_info.dims.w == 0u) return 1.0;  // nothing baked
  float voxel = sdf_info.voxel.w;         // the smallest side
  // Leave the receiver's own surface: a voxel along the normal (the voxel's extent in
  // that direction), as the field's interpolation smears surfaces by about that much.
  float offset = dot(abs(n), sdf_info.voxel.xyz);
  vec3 o = p + n * offset;
  float far = sun ? length(vec3(sdf_info.dims.xyz) * sdf_info.voxel.xyz) : distance - offset;
  float visibility = 1.0;
  float t = 0.5 * voxel;
  for (int i = 0; i < SDF_STEPS && t < far; ++i) {
    float d = sdf_distance(o + l * t);
    float cone = sun ? t * radius : radius * t / max(distance, 1e-4);
    cone = max(cone, 0.25 * voxel);  // the field cannot resolve a sharper edge
    visibility = min(visibility, clamp(0.5 + 0.5 * d / cone, 0.0, 1.0));
    if (visibility <= 0.0) break;
    t += max(abs(d), 0.25 * voxel);
  }
  return visibility;
}

float sdf_shadow(GpuLight light, vec3 p_world, vec3 n_world, vec3 l_view) {
  vec3 l = normalize(mat3(frame.inv_view) * l_view);
  bool sun = light_is_directional(light);
  float distance = sun ? 0.0 : length(light.world_size.xyz - p_world);
  float radius = sun ? tan(radians(light.world_size.w)) : light.world_size.w * light_size_scale;
  return sdf_visibility(p_world, n_world, l, distance, radius, sun);
}

#endif
