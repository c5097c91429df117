// The layout of the godray radiance pyramids (passes/godrays/godrays_lines.hpp): level l (0 = the godray
// resolution W x H) has W_l x H_l = ceil(W / 2^l) x ceil(H / 2^l) pixels, stretched to cover the
// image exactly (pixel (i, j) covers level-0 coordinates [i W / W_l, (i + 1) W / W_l) x ..., so a
// level's pixel centres stay inside the image: a one-pixel level samples the image's centre); each
// pixel holds three uint64 (R, G, B), row after row, level after level. A beam deposits at the level where its own width spans one to two
// pixels, so a wide beam near the camera costs no more than a thin one far away. Two pyramids, one
// after the other: kGodrayStraight for the direct and the refracted view (a pixel's camera medium
// picks one), kGodrayMirrored for the view mirrored in the surface from below. They hold radiance
// without the phase function of the flat beam and the surface's weight, which the resolve applies
// per pixel (the sharp parts that a coarse level cannot carry).
#ifndef VKWATER_GODRAY_PYRAMID_GLSL
#define VKWATER_GODRAY_PYRAMID_GLSL

const int kGodrayStraight = 0;
const int kGodrayMirrored = 1;

ivec2 godray_level_size(ivec2 size, int level) { return (size + (1 << level) - 1) >> level; }

// Level-l pixels per level-0 pixel, along x and y.
vec2 godray_level_scale(ivec2 size, int level) { return vec2(godray_level_size(size, level)) / vec2(size); }

// Pixels before level `level`.
uint godray_level_offset(ivec2 size, int level) {
    uint offset = 0u;
    for (int l = 0; l < level; ++l) {
        const ivec2 s = godray_level_size(size, l);
        offset += uint(s.x * s.y);
    }
    return offset;
}

#endif
