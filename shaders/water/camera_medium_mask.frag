#version 450
// The stencil split's second pass: a full-screen triangle whose stencil test
// (passes/water/water_volume_stencil.cpp) keeps the pixels with an odd count, i.e. whose
// ray starts in the water; they write 1 over the mask cleared to 0.
layout(location = 0) out float out_in_water;

void main() { out_in_water = 1.0; }
