// The adaptive splat kernel of a caustic photon in the light-space map: the hat function of the
// landed photon lattice (docs/model.md section 4, "How the photon map keeps this law texel by
// texel"). Per map axis the photon's hat rises from 0 where its grid neighbour on one side lands to
// 1 where it lands itself and falls to 0 where its neighbour on the other side lands, so its two
// sides have their own widths and no lower bound; a texel takes the hat's integral over its own
// width, not a sample at its centre. Hats with shared nodes sum to one everywhere between the
// nodes, whatever their spacing: for a lattice that is a product of its axes (waves that vary along
// one map axis, at any sun azimuth) the kernels partition the map exactly. The photon's flux is
// what its hat intercepts on the surface: the same hat built on the entry points, projected along
// the sun. With n = 1 the landed lattice is that projection itself, so each texel gets exactly E_s,
// to rounding.
//
// The includer declares `vertices` as caustic_grid_photon.glsl asks, with the cell rows before and
// after the chunk's (a photon's neighbours across a chunk edge are in them).
#ifndef VKWATER_CAUSTIC_SPLAT_GLSL
#define VKWATER_CAUSTIC_SPLAT_GLSL

#include "caustics/caustic_grid_photon.glsl"

// Each side at most kMaxHatSide texels, so a hat's taps lie within kAdaptiveSplatReach texels of
// the texel that holds its node (mirrored by kAdaptiveSplatReach in caustics_light_space.hpp): at
// most 12 taps per axis. A wider side (a lattice spread far out of focus) is clamped there, and
// the kernel stops partitioning exactly at that photon.
const int kAdaptiveSplatReach = 6;
const float kMaxHatSide = float(kAdaptiveSplatReach) - 0.5;
// A side narrower than this (a focus: neighbours landing on the photon) is taken as this wide, so
// that no division is by zero; the hat then sits in one texel either way.
const float kMinHatSide = 1e-4;

// One axis of the hat: node `centre` (texel coordinates whose integers are texel centres, texel k
// spanning [k - 0.5, k + 0.5]), sides `left` and `right` texels wide, and the texels it overlaps,
// first .. first + count - 1.
struct HatAxis {
    int first;
    int count;
    float centre;
    float left;
    float right;
};

HatAxis hat_axis(float centre, float left, float right) {
    const int first = int(floor(centre - left + 0.5));
    const int last = int(floor(centre + right + 0.5));
    return HatAxis(first, last - first + 1, centre, left, right);
}

// The hat's whole integral, texels.
float hat_total(HatAxis a) { return 0.5 * (a.left + a.right); }

// The hat's integral from -infinity to x.
float hat_below(HatAxis a, float x) {
    const float d = x - a.centre;
    if (d <= -a.left) return 0.0;
    if (d <= 0.0) {
        const float e = d + a.left;
        return 0.5 * e * e / a.left;
    }
    if (d < a.right) {
        const float e = a.right - d;
        return hat_total(a) - 0.5 * e * e / a.right;
    }
    return hat_total(a);
}

// The cumulative integral up to the far edge of tap k, over the hat's total: the share of the
// photon's flux that taps 0 .. k take together.
float hat_share_upto(HatAxis a, int k) { return hat_below(a, float(a.first + k) + 0.5) / hat_total(a); }

// Where the sun's ray through point p crosses the plane y = origin.y, in map texel coordinates:
// the photon lattice before the water bends it.
vec2 caustic_sun_coord(vec3 p, CausticLightSpace space) {
    const vec3 s = space.sun.xyz;
    return caustic_texel_coord(p + ((space.origin.y - p.y) / s.y) * s, space);
}

// One neighbour of a photon in the lattice: where its sun ray enters (sun coordinates) and where
// its refracted ray crosses the photon's receiver plane y = plane (`landed`), in texels; `lands`
// is false where its ray does not enter the water, `exists` where it lies off the grid.
struct LatticeNeighbour {
    vec2 sun;
    vec2 landed;
    bool exists;
    bool lands;
};

LatticeNeighbour lattice_neighbour(ivec2 photon, CausticPhotonChunk chunk, CausticLightSpace space, float plane) {
    LatticeNeighbour n = LatticeNeighbour(vec2(0.0), vec2(0.0), false, false);
    const int side = int(chunk.resolution * chunk.sub);
    if (any(lessThan(photon, ivec2(0))) || any(greaterThanEqual(photon, ivec2(side)))) return n;
    const GridSubCell sub_cell = grid_sub_cell(uvec2(photon), chunk);
    vec3 p, t;
    n.exists = true;
    n.lands = caustic_patch_ray(sub_cell.cell, sub_cell.at, space, p, t);
    n.sun = caustic_sun_coord(p, space);
    if (n.lands) n.landed = caustic_texel_coord(p + ((p.y - plane) / -t.y) * t, space);
    return n;
}

// The photon's hat on both axes and the area its surface hat intercepts of the beam (m^2 normal
// to s). Per axis and side: the neighbour one photon along that axis, or, where there is none (the
// grid's edge) or its ray does not enter, the other side mirrored; with neither, half a texel.
// A lattice folded past a focus (a neighbour landing on the photon's far side) keeps the distance.
struct LatticeHat {
    HatAxis u, v;
    float intercepted;
};

LatticeHat lattice_hat(GridPhoton p, CausticPhotonChunk chunk, CausticLightSpace space, float plane) {
    const vec2 landed = caustic_texel_coord(p.photon.hit, space) - 0.5;
    const vec2 sun = caustic_sun_coord(p.photon.entry, space);
    vec2 span_sun;  // per axis: the surface hat's integral, texels of the sun coordinates
    float sides[4];  // u left, u right, v left, v right
    for (int axis = 0; axis < 2; ++axis) {
        const ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        const LatticeNeighbour before = lattice_neighbour(ivec2(p.index) - step, chunk, space, plane);
        const LatticeNeighbour after = lattice_neighbour(ivec2(p.index) + step, chunk, space, plane);
        const bool has_before = before.exists && before.lands, has_after = after.exists && after.lands;
        float left = has_before ? abs(landed[axis] - (before.landed[axis] - 0.5)) : 0.0;
        float right = has_after ? abs(after.landed[axis] - 0.5 - landed[axis]) : 0.0;
        float sun_left = has_before ? abs(sun[axis] - before.sun[axis]) : 0.0;
        float sun_right = has_after ? abs(after.sun[axis] - sun[axis]) : 0.0;
        if (!has_before && !has_after) {
            left = right = 0.5;
            sun_left = sun_right = 0.5;
        } else if (!has_before) {
            left = right;
            sun_left = sun_right;
        } else if (!has_after) {
            right = left;
            sun_right = sun_left;
        }
        sides[2 * axis] = clamp(left, kMinHatSide, kMaxHatSide);
        sides[2 * axis + 1] = clamp(right, kMinHatSide, kMaxHatSide);
        span_sun[axis] = 0.5 * (sun_left + sun_right);
    }
    LatticeHat hat;
    hat.u = hat_axis(landed.x, sides[0], sides[1]);
    hat.v = hat_axis(landed.y, sides[2], sides[3]);
    // Sun coordinates measure the plane y = origin.y: one texel there is 1 / |det| m^2 (the map's
    // axes restricted to it), and a horizontal area A intercepts A |s.y| of the beam.
    const vec3 u = space.u_axis.xyz, v = space.v_axis.xyz;
    const float texel_area = 1.0 / abs(u.x * v.z - u.z * v.x);
    hat.intercepted = span_sun.x * span_sun.y * texel_area * abs(space.sun.y);
    return hat;
}

#endif
