#version 450
#extension GL_GOOGLE_include_directive : require
// Runs in no pass: compiled so that tools/shader_structs mirrors the blocks and structs many
// shaders share once, under one name (vkw::glsl::shared_blocks_comp), for the C++ that fills them.
// Every other shader's generated header aliases a struct of the same name to the type here.
#include "common/frame_constants.glsl"
#include "caustics/caustic_photon_source.glsl"
#include "receivers/sun_shadow.glsl"
#include "water/water_vertex.glsl"

// The photon kernels' push blocks begin with a CausticPhotonSource (its CausticLightSpace is also
// the caustic map's uniform block); the water grid kernels' begin with a WaterGrid.
layout(set = 0, binding = 1, std140) uniform SharedCausticBlocks { CausticPhotonSource source; } caustic;
layout(set = 0, binding = 2, std140) uniform SharedWaterGrid { WaterGrid grid; } water;

layout(local_size_x = 1) in;

void main() {
    // Read, so that no compiler drops a block.
    if (frame.viewport.x < 0.0 || caustic.source.space.sun.w < 0.0 || water.grid.level < 0.0 ||
        sun_shadow.sun.params.w < 0.0) {
        return;
    }
}
