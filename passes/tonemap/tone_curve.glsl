// The tone mapping both tonemap shaders share (tonemap.frag, tonemap.comp): exposure, a
// tone curve, then sRGB encoding when the target is a UNORM image (an *_srgb target
// encodes in hardware). Needs tonemap_interface.h's push constants.
#ifndef ANTUMBRA_TONE_CURVE_GLSL
#define ANTUMBRA_TONE_CURVE_GLSL

vec3 aces_fitted(vec3 x) {
  // Narkowicz 2015 fit of the ACES reference rendering transform.
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

vec4 tone_map(vec3 radiance) {
  vec3 c = radiance * exposure;
  if (tone_operator == ANTUMBRA_TONE_ACES) {
    c = aces_fitted(c);
  } else if (tone_operator == ANTUMBRA_TONE_REINHARD) {
    c = c / (1.0 + c);
  } else {
    c = clamp(c, 0.0, 1.0);
  }
  if (encode_srgb != 0u) c = srgb_encode(c);
  return vec4(c, 1.0);
}

#endif
