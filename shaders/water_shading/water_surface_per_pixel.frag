#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface with the stencil split's per-pixel camera medium.
#define VKWATER_PER_PIXEL_MEDIUM
#include "water_shading/water_surface_shading.glsl"
