#version 460
#include "../beta/beta.glsl"
