#version 450
#extension GL_GOOGLE_include_directive : require
// The floor with the per-frame camera medium (the stencil split is culled).
#include "receivers/floor_shading.glsl"
