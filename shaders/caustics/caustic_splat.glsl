// The splat kernel of a caustic photon in the light-space map: a separable tent
// whose half-width on each axis is the spacing of the photon's neighbours where they land (the
// photon-density sizing of the splat, de la Fuente 2011's point size regulation done in light space),
// at least one texel and at most kMaxSplatHalfWidth. The weights sum to one: the caller splits
// the photon's integer flux over the taps by cumulative rounding, so the taps sum to it exactly.
// Under flat water (texel = water cell, photons on texel centres) the half-width is one texel
// and the kernel is exactly the 2x2 bilinear splat.
#ifndef VKWATER_CAUSTIC_SPLAT_GLSL
#define VKWATER_CAUSTIC_SPLAT_GLSL

#include "caustics/caustic_photon.glsl"

const float kMaxSplatHalfWidth = 4.0;  // texels: at most 8 taps per axis

// The tent of half-width h centred at c (texel coordinates whose integers are texel centres):
// taps first .. first + count - 1, the integers strictly inside (c - h, c + h).
struct SplatAxis {
    int first;
    int count;
    float centre;
    float half_width;
};

SplatAxis splat_axis(float c, float h) {
    const int first = int(floor(c - h)) + 1;
    const int last = int(ceil(c + h)) - 1;
    return SplatAxis(first, max(last - first + 1, 1), c, h);
}

float splat_weight(SplatAxis axis, int k) { return max(0.0, 1.0 - abs(float(axis.first + k) - axis.centre) / axis.half_width); }

float splat_total(SplatAxis axis) {
    float total = 0.0;
    for (int k = 0; k < axis.count; ++k) total += splat_weight(axis, k);
    return total;
}

// The half-widths, in texels, from where the neighbouring photons of the grid (one sub-cell
// further along u and along v) land after the same path length: the larger of each axis's
// components of the two spacings, clamped to [1, kMaxSplatHalfWidth]. A neighbour whose ray
// does not enter (it points up) leaves the kernel at one texel.
vec2 splat_half_width(CausticCell cell, vec2 at, float step, CausticPhoton photon, CausticLightSpace space) {
    const vec2 centre = caustic_texel_coord(photon.hit, space);
    vec2 spread = vec2(1.0);
    for (int axis = 0; axis < 2; ++axis) {
        const vec2 neighbour = at + (axis == 0 ? vec2(step, 0.0) : vec2(0.0, step));
        vec3 p, t;
        if (!caustic_patch_ray(cell, neighbour, space, p, t)) return vec2(1.0);
        spread = max(spread, abs(caustic_texel_coord(p + photon.path * t, space) - centre));
    }
    return clamp(spread, vec2(1.0), vec2(kMaxSplatHalfWidth));
}

#endif
