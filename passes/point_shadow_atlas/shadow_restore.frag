#version 460
#extension GL_GOOGLE_include_directive : require
#include "point_shadow_atlas_interface.h"

// The static cache's depth, texel for texel (depth test ALWAYS, no bias: the cache was
// drawn with the atlas's bias already).
layout(set = 0, binding = kAtlasCache) uniform sampler2DArray cache;

layout(location = 0) flat in uint in_layer;

void main() {
  gl_FragDepth = texelFetch(cache, ivec3(ivec2(gl_FragCoord.xy), int(in_layer)), 0).r;
}
