// Screen -> view space through the frame's inverse projection: one definition for every
// pass that reconstructs positions from G-buffer depth. The including shader declares
// `FrameUniforms frame` (frame.glsl).
#ifndef ANTUMBRA_VIEW_SPACE_GLSL
#define ANTUMBRA_VIEW_SPACE_GLSL

// `uv` in [0, 1] across the image, `depth` the 0..1 depth-buffer value.
vec3 view_position(vec2 uv, float depth) {
  vec4 view = frame.inv_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return view.xyz / view.w;
}

#endif
