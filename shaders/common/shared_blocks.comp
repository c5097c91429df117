#version 450
#extension GL_GOOGLE_include_directive : require
// Runs in no pass: compiled so that tools/shader_structs mirrors the blocks many shaders share
// once, under one name (vkw::glsl::shared_blocks_comp), for the C++ that fills them.
#include "frame_constants.glsl"

layout(local_size_x = 1) in;

void main() {
    // Read, so that no compiler drops the block.
    if (frame.viewport.x < 0.0) return;
}
