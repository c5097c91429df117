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

// The ray of one photon of the lattice as its neighbours see it: where it enters (p) and its
// refracted direction (t); `lands` is false where its ray does not enter the water, `exists` where
// it lies off the grid or outside the rows the chunk's binding holds.
struct LatticeRay {
    vec3 p;
    vec3 t;
    bool exists;
    bool lands;
};

// The ray of the photon of a sub-cell already read.
LatticeRay sub_cell_ray(GridSubCell sub_cell, CausticLightSpace space) {
    LatticeRay r = LatticeRay(vec3(0.0), vec3(0.0, -1.0, 0.0), true, false);
    r.lands = caustic_patch_ray(sub_cell.cell, sub_cell.at, space, r.p, r.t);
    return r;
}

LatticeRay lattice_ray(ivec2 photon, CausticPhotonChunk chunk, CausticLightSpace space) {
    LatticeRay r = LatticeRay(vec3(0.0), vec3(0.0, -1.0, 0.0), false, false);
    const int side = int(chunk.resolution * chunk.sub);
    if (any(lessThan(photon, ivec2(0))) || any(greaterThanEqual(photon, ivec2(side)))) return r;
    // Only the chunk's cell rows and the one on each side of them are in its binding.
    const int cell_row = photon.y / int(chunk.sub);
    if (cell_row < int(chunk.first_row) - 1 || cell_row > int(chunk.first_row + chunk.rows)) return r;
    return sub_cell_ray(grid_sub_cell(uvec2(photon), chunk), space);
}

// One neighbour of a photon in the lattice: where its sun ray enters (sun coordinates) and where
// its refracted ray crosses the photon's receiver plane y = plane (`landed`), in texels.
struct LatticeNeighbour {
    vec2 sun;
    vec2 landed;
    bool exists;
    bool lands;
};

LatticeNeighbour lattice_neighbour(LatticeRay r, CausticLightSpace space, float plane) {
    LatticeNeighbour n = LatticeNeighbour(vec2(0.0), vec2(0.0), r.exists, r.exists && r.lands);
    if (!r.exists) return n;
    n.sun = caustic_sun_coord(r.p, space);
    if (r.lands) n.landed = caustic_texel_coord(r.p + ((r.p.y - plane) / -r.t.y) * r.t, space);
    return n;
}

// A photon's four lattice neighbours' rays: before and after it along the grid's u (x) and v (y).
struct LatticeRays {
    LatticeRay u_before, u_after, v_before, v_after;
};

// Traces them, each in full: the kernels that do not share rays between invocations.
LatticeRays traced_lattice_rays(uvec2 index, CausticPhotonChunk chunk, CausticLightSpace space) {
    const ivec2 i = ivec2(index);
    return LatticeRays(lattice_ray(i - ivec2(1, 0), chunk, space), lattice_ray(i + ivec2(1, 0), chunk, space),
                       lattice_ray(i - ivec2(0, 1), chunk, space), lattice_ray(i + ivec2(0, 1), chunk, space));
}

// The photon's hat on both axes and the area its surface hat intercepts of the beam (m^2 normal
// to s). Per axis and side the neighbour is the next photon along that axis of the grid; where
// there is none (the grid's edge) or its ray does not enter, the other side mirrored, and with
// neither, half a texel. Along an axis where the lattice is folded over the photon (both
// neighbours land on one side of it, where the light is a sum over the fold's branches and no hat
// partitions it) the photon spreads over a symmetric hat as wide as its farther neighbour lands,
// at least a texel: the tent of de la Fuente 2011's size regulation, done in light space.
struct LatticeHat {
    HatAxis u, v;
    float intercepted;
};

LatticeHat lattice_hat(GridPhoton p, LatticeRays rays, CausticLightSpace space, float plane) {
    const vec2 landed = caustic_texel_coord(p.photon.hit, space);
    const vec2 sun = caustic_sun_coord(p.photon.entry, space);
    // Per grid axis: the offsets of the neighbours before and after the photon, where they land and
    // where the sun's rays through their entry points cross the plane.
    vec2 landed_before[2], landed_after[2], sun_before[2], sun_after[2];
    for (int axis = 0; axis < 2; ++axis) {
        const LatticeNeighbour before = lattice_neighbour(axis == 0 ? rays.u_before : rays.v_before, space, plane);
        const LatticeNeighbour after = lattice_neighbour(axis == 0 ? rays.u_after : rays.v_after, space, plane);
        const bool has_before = before.exists && before.lands, has_after = after.exists && after.lands;
        landed_before[axis] = before.landed - landed;
        landed_after[axis] = after.landed - landed;
        sun_before[axis] = before.sun - sun;
        sun_after[axis] = after.sun - sun;
        if (!has_before && !has_after) {
            const vec2 half_texel = axis == 0 ? vec2(0.5, 0.0) : vec2(0.0, 0.5);
            landed_after[axis] = sun_after[axis] = half_texel;
            landed_before[axis] = sun_before[axis] = -half_texel;
        } else if (!has_before) {
            landed_before[axis] = -landed_after[axis];
            sun_before[axis] = -sun_after[axis];
        } else if (!has_after) {
            landed_after[axis] = -landed_before[axis];
            sun_after[axis] = -sun_before[axis];
        }
    }
    float sides[4];  // u before, u after, v before, v after
    for (int axis = 0; axis < 2; ++axis) {
        // A lattice reversed along the axis (both neighbours on swapped sides, the image of a
        // focus) still has its hats; one folded over the photon (both on one side) has none.
        const float before = -landed_before[axis][axis], after = landed_after[axis][axis];
        if (before * after > 0.0) {
            sides[2 * axis] = clamp(abs(before), kMinHatSide, kMaxHatSide);
            sides[2 * axis + 1] = clamp(abs(after), kMinHatSide, kMaxHatSide);
        } else {
            sides[2 * axis] = sides[2 * axis + 1] = clamp(max(abs(before), abs(after)), 1.0, kMaxHatSide);
        }
    }
    LatticeHat hat;
    hat.u = hat_axis(landed.x - 0.5, sides[0], sides[1]);
    hat.v = hat_axis(landed.y - 0.5, sides[2], sides[3]);
    // The surface hat's integral per axis, texels of the sun coordinates, which measure the plane
    // y = origin.y: one texel there is 1 / |det| m^2 (the map's axes restricted to it), and a
    // horizontal area A intercepts A |s.y| of the beam.
    const vec2 span_sun = 0.5 * vec2(abs(sun_after[0].x) + abs(sun_before[0].x), abs(sun_after[1].y) + abs(sun_before[1].y));
    const vec3 u = space.u_axis.xyz, v = space.v_axis.xyz;
    const float texel_area = 1.0 / abs(u.x * v.z - u.z * v.x);
    hat.intercepted = span_sun.x * span_sun.y * texel_area * abs(space.sun.y);
    return hat;
}

#endif
