#version 450
#extension GL_GOOGLE_include_directive : require
// The floor with the stencil split's per-pixel camera medium.
#define VKWATER_PER_PIXEL_MEDIUM
#include "receivers/floor_shading.glsl"
