// Penumbra wedges with depth peeling, the shading rule (tiled-lighting's shadows =
// penumbra-map; docs/technique.md 2). The receiver is classified from the atlas (Z1),
// penumbra-wedges' map and, with HAS_PEELED, the third depth layer Z3, as in the seed's
// figure 7:
//   seen by the light (the hard test passes): in an outer wedge it lies behind, the
//   ramp, else lit;
//   hidden: no wedge, or an outer wedge (a hidden point is never in an outer penumbra):
//   umbra; an inner wedge: its ramp when the receiver lies in front of Z3 (it is the
//   surface right behind the occluder), umbra when another occluder lies between.
// The map is read at the receiver's own texel (nearest), so no texel mixes two kinds of
// wedge: the seed's leftover pixels at class borders do not arise. Directional lights
// have no wedges: they fall back to PCF.
// Expects `penumbra_map` (and `peeled_map` with HAS_PEELED), shadow_filter.glsl.
#ifndef ANTUMBRA_PENUMBRA_MAP_SHADOW_GLSL
#define ANTUMBRA_PENUMBRA_MAP_SHADOW_GLSL

// The seed's transition curve: 0 at the inner edge, 0.3 on the silhouette, 1 at the
// outer edge, flat at both ends.
float wedge_transition(float theta) {
  const float kPi = 3.14159265;
  if (theta < 0.5) return (1.0 - cos(theta * kPi)) * 0.3;
  return sin((theta - 0.5) * kPi) * 0.7 + 0.3;
}

// theta spans the wedge, whose angular width is the penumbra of a receiver infinitely far
// behind the edge. A receiver at distance z_r behind a wedge at z_w sees a penumbra
// (1 - z_w / z_r) as wide (similar triangles), centred on the silhouette.
float wedge_theta(float theta, float wedge, float receiver) {
#if WEDGE_RECEIVER
  float share = clamp(1.0 - abs(wedge) / max(receiver, 1e-6), 0.02, 1.0);
  return clamp(0.5 + (theta - 0.5) / share, 0.0, 1.0);
#else
  return theta;
#endif
}

float penumbra_map_face(ShadowLight sl, int layer, vec3 p_world, vec3 n_world) {
  FilterCoord c;
  if (!filter_coord(sl, layer, p_world, n_world, c)) return 1.0;
  float lit = filter_hard(c);
  // penumbra-wedges draws only faces at the corner of their own layer (wedges_common.glsl,
  // wedge_face_in_own_layer); a face packed elsewhere keeps its hard edge. Over a page
  // pool it keeps each paged face in the layer of its record, where the map has one.
  vec2 uv = clamp(c.uv, vec2(0.5 * c.texel), vec2(1.0 - 0.5 * c.texel));
#ifdef SHADOW_PAGE_TABLES
  bool paged = c.pages.table >= 0;
  if (paged && layer >= textureSize(penumbra_map, 0).z) return lit;
  if (!paged && (int(c.layer) != layer || any(notEqual(c.origin, vec2(0.0))))) return lit;
  vec3 at = paged ? vec3(uv, float(layer)) : vec3(uv * c.share + c.origin, c.layer);
#else
  if (int(c.layer) != layer || any(notEqual(c.origin, vec2(0.0)))) return lit;
  vec3 at = vec3(uv * c.share + c.origin, c.layer);
#endif
  vec2 texel = textureLod(penumbra_map, at, 0.0).rg;
  float wedge = texel.g;
  if (lit > 0.5) {
    // A wedge shades only what lies behind it: the occluder's own surface at its edge
    // (the wedge starts there) stays lit, as it does under an area light.
    bool behind = c.linear > wedge + max(0.02, 0.01 * c.linear);
    return wedge > 0.0 && behind ? wedge_transition(wedge_theta(texel.r, wedge, c.linear)) : 1.0;
  }
  if (wedge >= 0.0) return 0.0;  // no wedge, or an outer one: umbra
#if HAS_PEELED
  float z3 = textureLod(peeled_map, at, 0.0).r;
  if (z3 < 1.0) {
    float behind = shadow_linearise(z3, c.near, c.far);
    if (c.linear > behind + max(0.02, 0.02 * c.linear)) return 0.0;  // a second occluder
  }
#endif
  return wedge_transition(wedge_theta(texel.r, wedge, c.linear));
}

float penumbra_map_shadow(uint index, vec3 p_world, vec3 n_world) {
  if (index >= ANTUMBRA_MAX_SHADOW_LIGHTS) return 1.0;
  ShadowLight sl = shadow_lights[index];
  if (shadow_is_ortho(sl)) return atlas_shadow(index, p_world, n_world, ANTUMBRA_SHADOW_PCF);
  int layer = shadow_face_layer(sl, p_world);
  if (layer < 0) return 1.0;
  return penumbra_map_face(sl, layer, p_world, n_world);
}

#endif
