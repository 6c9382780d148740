#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> HDR grade: exposure and tint (one gain), saturation against Rec. 709 luminance,
// then contrast around mid-grey. The defaults leave every texel as it was, so inserting
// the pass before tonemap changes nothing until a parameter moves. Define: HDR_FORMAT
// (the target's storage format).
#include "colour_grade_interface.h"
#include "../interface/shared/workgroups.h"

layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kColourGradeSource) uniform sampler2D source_image;
layout(set = 0, binding = kColourGradeTarget, HDR_FORMAT) uniform writeonly image2D target;

// Mid-grey, where contrast pivots: a contrast change keeps the middle tones where the
// exposure put them.
const float kPivot = 0.18;

vec3 grade(vec3 c) {
  c *= gain.rgb;
  // Saturation above 1 pushes a channel below the luminance; radiance cannot be negative.
  float luma = dot(c, vec3(0.2126, 0.7152, 0.0722));
  c = max(mix(vec3(luma), c, saturation), vec3(0.0));
  // pow is not exact at 1 (exp2(log2(x))): skip it, so the default is the identity.
  if (contrast != 1.0) {
    c = kPivot * pow(max(c, vec3(1e-8)) / kPivot, vec3(contrast));
  }
  return c;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  vec4 colour = texelFetch(source_image, p, 0);
  imageStore(target, p, vec4(grade(colour.rgb), colour.a));
}
