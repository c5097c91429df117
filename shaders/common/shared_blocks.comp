#version 450
#extension GL_GOOGLE_include_directive : require
// Runs in no pass: compiled so that tools/shader_structs mirrors the blocks and structs many
// shaders share once, under one name (vkw::glsl::shared_blocks_comp), for the C++ that fills them.
#include "common/frame_constants.glsl"
#include "caustics/caustic_light_space.glsl"

// The caustic map's light space, as the photon kernels' push blocks and the map's uniform block hold it.
layout(set = 0, binding = 1, std140) uniform SharedCausticLightSpace { CausticLightSpace space; } caustic_light;

layout(local_size_x = 1) in;

void main() {
    // Read, so that no compiler drops the block.
    if (frame.viewport.x < 0.0 || caustic_light.space.sun.w < 0.0) return;
}
