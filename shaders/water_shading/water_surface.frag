#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface with the per-frame camera medium (the stencil split is culled).
#include "water_shading/water_surface_shading.glsl"
