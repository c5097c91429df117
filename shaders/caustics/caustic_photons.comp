#version 460
// Photon grid -> light-space caustic flux, accumulated deterministically in 64-bit fixed point
// (passes/caustics/caustics_photons.hpp). Variants: plain (the floor plane is the receiver) and
// VKWATER_SUN_SHADOW (receiver meshes under the water and occluders above it, from the sun
// shadow map); the splat kernel is a variant too (VKWATER_SPLAT_BILINEAR, _ADAPTIVE,
// _FOOTPRINT): llvmpipe's compiled code for one kernel doubles in time when the others' code
// sits in the same shader, even behind a uniform branch (measured: 104 ms against 223 ms for the
// bilinear kernel's 1024^2 photons); with the adaptive kernel, VKWATER_LANES_SHARE_RAYS where the
// device has subgroup shuffles. Photon (i S + a, j_local S + b) is sub-cell (a, b) of cell (i, j):
// one invocation each, except that the adaptive kernel's invocations walk kColumnRows of them down
// a column (below). Each photon's flux, in units of the map's LSB, is rounded
// once to an integer q and split over its splat kernel (the bilinear 2x2; caustic_splat.glsl:
// the hat of the landed photon lattice, integrated over each texel; caustic_footprint.glsl: its
// sub-cell's footprint, by area) by cumulative rounding, so the taps sum to q exactly (a
// normalised kernel with no rounding drift) and integer addition makes the result independent of
// the order the atomics land in.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#ifdef VKWATER_LANES_SHARE_RAYS
#extension GL_KHR_shader_subgroup_shuffle_relative : require
#endif

#include "water/water_vertex.glsl"

#if defined(VKWATER_SPLAT_ADAPTIVE)
// The adaptive kernel's invocation walks kColumnRows photons down one column of the grid, so that
// the rays of the photons before and after it along v are the ones it traced in the steps before
// and after (a photon's hat needs its four neighbours' rays: traced each for itself, they took
// about 45% of pool's pass). A row of 64 invocations per work group.
layout(local_size_x = 64, local_size_y = 1) in;
const uint kColumnRows = 8u;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

// The vertex rows first_row - 1 .. first_row + rows + 1 of the grid (those that exist), vertex
// (0, first_row) at element vertex_offset: a chunk's binding with the rows its photons'
// neighbours need.
layout(set = 0, binding = 0, std430) readonly buffer Surface { WaterVertex vertices[]; };

#include "caustics/caustic_grid_photon.glsl"  // with VKWATER_SUN_SHADOW: bindings 6 and 7
#ifdef VKWATER_SPLAT_FOOTPRINT
#include "caustics/caustic_footprint.glsl"
#endif
#include "caustics/caustic_splat.glsl"
// The map rows band_first .. band_first + band_rows - 1 of the held texels (bit 10 of
// sub_and_flags: the read texels' rectangle read_x x read_y; else the whole map), three uint64
// per texel (R, G, B), at the held rectangle's width.
layout(set = 0, binding = 1, std430) buffer Flux { uint64_t flux[]; };
// Flux whose kernel tap fell outside the map, per channel (added by the first band's dispatches only).
layout(set = 0, binding = 2, std430) buffer Lost { uint64_t lost[]; };
// With culling, per map row the texels [x0, x1) that the frame reads, as x0 | x1 << 16 (rows
// 0 .. H - 1), then the same widened by kAdaptiveSplatReach along both axes (rows H .. 2H - 1).
layout(set = 0, binding = 3, std430) readonly buffer ReadRows { uint read_rows[]; };

// Its C++ type (CausticPhotonPush in passes/caustics/caustics_photons.cpp) is generated from this
// shader; 128 bytes, the guaranteed minimum.
layout(push_constant) uniform Push {
    CausticPhotonSource source;
    uint resolution;     // R cells per side
    uint sub_and_flags;  // bits 0-7: S (S x S photons per cell); bit 8: jitter (each photon leaves from a
                         // hashed point of its sub-cell); bit 9: cull outside the read texels; bit 10:
                         // the flux holds only the read texels' rectangle
    uint chunk_rows;     // the chunk's first cell row | its cell rows << 16
    uint vertex_offset;  // the element of `vertices` that holds vertex (0, first cell row)
    uint band_first;     // first map row of this band (the first band's: the held rectangle's first row)
    uint band_rows;      // map rows in this band
    uint read_x;         // the texel columns the frame reads, [first, end): first | end << 16
    uint read_y;         // and rows
} pc;

// The held texels' columns (bit 10: the read texels' rectangle; else the whole map), and whether
// this dispatch is the first band's, which alone adds the flux that fell off the map: set once
// by main() rather than per tap.
int held_first_column, held_columns;
bool first_band;

void find_held_columns() {
    const bool held_part = (pc.sub_and_flags & 0x400u) != 0u;
    held_first_column = held_part ? int(pc.read_x & 0xffffu) : 0;
    held_columns = held_part ? int(pc.read_x >> 16) - held_first_column : int(pc.source.space.u_axis.w);
    first_band = pc.band_first == (held_part ? (pc.read_y & 0xffffu) : 0u);
}

void deposit(ivec2 texel, uint channel, uint64_t q) {
    if (q == 0ul) return;
    if (texel.x < 0 || texel.y < 0 || texel.x >= int(pc.source.space.u_axis.w) || texel.y >= int(pc.source.space.v_axis.w)) {
        if (first_band) atomicAdd(lost[channel], q);
        return;
    }
    // The bands cover the held rows alone, so a row outside them is in no band.
    const int row = texel.y - int(pc.band_first);
    if (row < 0 || row >= int(pc.band_rows)) return;  // another band's dispatch adds it, or no pass reads it
    const int column = texel.x - held_first_column;
    if (column < 0 || column >= held_columns) return;  // on the map, read by no pass
    atomicAdd(flux[(uint(row) * uint(held_columns) + uint(column)) * 3u + channel], q);
}

// Splits q over the taps of one axis of the hat by cumulative rounding: tap k's share is
// round(q F_k) - round(q F_{k-1}), F_k the hat's integral up to tap k's far edge over its total,
// so the shares are non-negative and sum to q exactly.
uint64_t hat_tap_share(uint64_t q, HatAxis axis, int k, inout uint64_t given) {
    const uint64_t upto = k == axis.count - 1 ? q : caustic_share(q, hat_share_upto(axis, k));
    const uint64_t s = upto - min(given, upto);
    given = max(given, upto);
    return s;
}

// The one-texel tent (the bilinear 2x2 splat) at texel coordinates `coord` (integers: centres),
// written out.
void deposit_bilinear(vec2 coord, vec3 q) {
    const vec2 base = floor(coord);
    const vec2 f = coord - base;
    const ivec2 t0 = ivec2(base);
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t total = uint64_t(q[ch] + 0.5);
        const uint64_t x0 = caustic_share(total, 1.0 - f.x), x1 = total - x0;
        const uint64_t x0y0 = caustic_share(x0, 1.0 - f.y), x1y0 = caustic_share(x1, 1.0 - f.y);
        deposit(t0, ch, x0y0);
        deposit(t0 + ivec2(0, 1), ch, x0 - x0y0);
        deposit(t0 + ivec2(1, 0), ch, x1y0);
        deposit(t0 + ivec2(1, 1), ch, x1 - x1y0);
    }
}

// The hat (caustic_splat.glsl), split over its taps: a column's share along u, then its taps'
// shares of that along v.
void deposit_hat(LatticeHat hat, vec3 q) {
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t total = uint64_t(q[ch] + 0.5);
        uint64_t x_given = 0ul;
        for (int i = 0; i < hat.u.count; ++i) {
            const uint64_t column = hat_tap_share(total, hat.u, i, x_given);
            uint64_t y_given = 0ul;
            for (int j = 0; j < hat.v.count; ++j) {
                deposit(ivec2(hat.u.first + i, hat.v.first + j), ch, hat_tap_share(column, hat.v, j, y_given));
            }
        }
    }
}

#ifdef VKWATER_SPLAT_FOOTPRINT
// The footprint kernel: the photon's flux spread over its sub-cell's footprint by area
// (footprint_weights' texel box and weights), each channel split by cumulative rounding over the
// footprint's texels in row order.
void deposit_footprint(ivec2 first, ivec2 size, float weight[64], float total, vec3 q) {
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t amount = uint64_t(q[ch] + 0.5);
        float partial = 0.0;
        uint64_t given = 0ul;
        for (int j = 0; j < size.y; ++j) {
            for (int i = 0; i < size.x; ++i) {
                partial += weight[j * kMaxFootprintTexels + i];
                const bool last = j == size.y - 1 && i == size.x - 1;
                const uint64_t upto = last ? amount : caustic_share(amount, partial / total);
                deposit(first + ivec2(i, j), ch, upto - given);
                given = upto;
            }
        }
    }
}
#endif

// True when the texel box lo .. hi (inclusive) misses the texels the frame reads: their bounding
// rectangle first, then the spans of the rows the box covers.
bool misses_read_texels(ivec2 lo, ivec2 hi) {
    const ivec2 first = ivec2(pc.read_x & 0xffffu, pc.read_y & 0xffffu), end = ivec2(pc.read_x >> 16, pc.read_y >> 16);
    if (any(lessThan(hi, first)) || any(greaterThanEqual(lo, end))) return true;
    for (int row = max(lo.y, first.y); row <= min(hi.y, end.y - 1); ++row) {
        const uint span = read_rows[row];
        if (lo.x < int(span >> 16) && hi.x >= int(span & 0xffffu)) return false;
    }
    return true;
}

// Where the photon lands in texel coordinates (integers: texel centres); false, with its flux
// added to the lost flux, where it lands far off the map (or not a number): every tap would be
// outside, and int() of it is undefined.
bool landed_coord(GridPhoton p, out vec2 coord) {
    coord = caustic_texel_coord(p.photon.hit, pc.source.space) - 0.5;
    if (all(lessThan(abs(coord), vec2(1e7)))) return true;
    for (uint ch = 0u; ch < 3u; ++ch) deposit(ivec2(-2), ch, uint64_t(p.q[ch] + 0.5));
    return false;
}

// The hat's taps lie within kAdaptiveSplatReach texels of its node's texel (the bilinear kernel's
// within one): one look-up in the widened rows leaves out a photon farther than that from every
// read texel, before its kernel is shaped.
bool near_read_texels(vec2 coord) {
    const ivec2 centre = ivec2(floor(coord));
    const int height = int(pc.source.space.v_axis.w);
    if (centre.y < 0 || centre.y >= height) {
        return !misses_read_texels(centre - kAdaptiveSplatReach, centre + kAdaptiveSplatReach);
    }
    const uint span = read_rows[height + centre.y];
    return centre.x >= int(span & 0xffffu) && centre.x < int(span >> 16);
}

bool culling() { return (pc.sub_and_flags & 0x200u) != 0u; }

CausticPhotonChunk this_chunk() {
    return CausticPhotonChunk(pc.resolution, pc.sub_and_flags & 0xffu, pc.chunk_rows & 0xffffu, pc.chunk_rows >> 16,
                              (pc.sub_and_flags & 0x100u) != 0u, pc.vertex_offset);
}

// The photon's hat from its neighbours' rays, and its deposit.
void deposit_lattice_hat(GridPhoton p, LatticeRays rays) {
    // The neighbours land on the photon's own receiver plane: the floor, or the horizontal plane
    // through the receiver mesh it hit.
#ifdef VKWATER_SUN_SHADOW
    const float plane = p.photon.hit.y;
#else
    const float plane = pc.source.space.origin.w;
#endif
    const LatticeHat hat = lattice_hat(p, rays, pc.source.space, plane);
#if defined(VKWATER_SPLAT_ADAPTIVE)
    // The adaptive kernel's photon carries what its surface hat intercepts (the footprint
    // kernel's fallback keeps its sub-cell's, which its neighbours' footprints tile with).
    const vec3 q = p.q * (hat.intercepted / p.photon.area);
    if (!caustic_flux_representable(q)) return;
#else
    const vec3 q = p.q;
#endif
    deposit_hat(hat, q);
}

#if defined(VKWATER_SPLAT_ADAPTIVE)
#ifdef VKWATER_LANES_SHARE_RAYS
// Every lane's ray, shuffled: from the lane before it in the subgroup (`from_before`) or after it.
// Every lane of the subgroup takes part, so it is called in uniform control flow.
LatticeRay shuffled_ray(LatticeRay r, bool from_before) {
    if (from_before) {
        return LatticeRay(subgroupShuffleUp(r.p, 1u), subgroupShuffleUp(r.t, 1u), subgroupShuffleUp(r.exists, 1u),
                          subgroupShuffleUp(r.lands, 1u));
    }
    return LatticeRay(subgroupShuffleDown(r.p, 1u), subgroupShuffleDown(r.t, 1u), subgroupShuffleDown(r.exists, 1u),
                      subgroupShuffleDown(r.lands, 1u));
}
#endif

// One step of the walk down a column: the photon at row `row` of the chunk (its ray, whether it
// carries flux, and if so the photon itself).
struct ColumnStep {
    LatticeRay ray;
    bool traced;
    GridPhoton photon;
};

ColumnStep column_step(uint x, uint row, CausticPhotonChunk chunk) {
    ColumnStep s;
    const uvec2 index = uvec2(x, row + chunk.first_row * chunk.sub);
    if (x < chunk.resolution * chunk.sub && row < chunk.rows * chunk.sub) {
        // One of the chunk's photons: its sub-cell read once for its ray and its trace.
        const GridSubCell sub_cell = grid_sub_cell(index, chunk);
        s.ray = sub_cell_ray(sub_cell, pc.source.space);
        s.traced = trace_sub_cell_photon(sub_cell, index, pc.source, s.photon);
    } else {
        s.ray = lattice_ray(ivec2(index), chunk, pc.source.space);
        s.traced = false;
    }
    return s;
}

// Walks the column from its first row, keeping the rays of the photon before and after the one it
// deposits. The photons beside it along u are the neighbouring lanes' where the subgroup holds the
// columns x - 1 and x + 1, so only the subgroup's two ends trace a ray of their own. (Tracing
// those end rays for all kColumnRows rows before the walk, spread over the lanes, and handing
// each step's to the end lanes by broadcast was not measurably faster on llvmpipe.)
void main() {
    find_held_columns();
    const CausticPhotonChunk chunk = this_chunk();
    const uint x = gl_GlobalInvocationID.x, first = gl_GlobalInvocationID.y * kColumnRows;
    const int base = int(chunk.first_row * chunk.sub);
#ifdef VKWATER_LANES_SHARE_RAYS
    const uint lane = gl_SubgroupInvocationID;
    // Whatever order a device gives its lanes in, a lane takes its neighbour's ray only where the
    // neighbouring lane holds the neighbouring column.
    const bool has_left = lane > 0u && subgroupShuffleUp(x, 1u) == x - 1u;
    const bool has_right = lane + 1u < gl_SubgroupSize && subgroupShuffleDown(x, 1u) == x + 1u;
#else
    const bool has_left = false, has_right = false;
#endif
    LatticeRay before = lattice_ray(ivec2(x, base + int(first) - 1), chunk, pc.source.space);
    ColumnStep here = column_step(x, first, chunk);
    for (uint k = 0u; k < kColumnRows; ++k) {
        const uint row = first + k;
        const ColumnStep next = column_step(x, row + 1u, chunk);
#ifdef VKWATER_LANES_SHARE_RAYS
        LatticeRay left = shuffled_ray(here.ray, true), right = shuffled_ray(here.ray, false);
#else
        LatticeRay left = here.ray, right = here.ray;
#endif
        const ivec2 at = ivec2(x, base + int(row));
        if (!has_left || !has_right) {
            // One branch for both ends: llvmpipe runs a branch for all 8 lanes if any takes it.
            const LatticeRay traced = lattice_ray(at + ivec2(has_left ? 1 : -1, 0), chunk, pc.source.space);
            if (!has_left) left = traced; else right = traced;
            // A lane that has neither (a subgroup of one) traces the other too.
            if (!has_left && !has_right) right = lattice_ray(at + ivec2(1, 0), chunk, pc.source.space);
        }
        if (here.traced) {
            vec2 coord;
            if (landed_coord(here.photon, coord) && (!culling() || near_read_texels(coord))) {
                deposit_lattice_hat(here.photon, LatticeRays(left, right, before, next.ray));
            }
        }
        before = here.ray;
        here = next;
    }
}
#else
// Traces the photon and deposits it unless its kernel can reach no texel the frame reads.
void main() {
    find_held_columns();
    GridPhoton p;
    const CausticPhotonChunk chunk = this_chunk();
    if (!trace_grid_photon(gl_GlobalInvocationID.xy, chunk, pc.source, p)) return;
    vec2 coord;
    if (!landed_coord(p, coord)) return;
#if defined(VKWATER_SPLAT_BILINEAR)
    if (culling() && !near_read_texels(coord)) return;
    deposit_bilinear(coord, p.q);
#else
    ivec2 first, size;
    float weight[64];
    float total;
    vec2 corner[4];
    if (footprint_corners(p.cell, p.uv0, p.uv1, p.photon, pc.source.space, corner) &&
        footprint_weights(corner, first, size, weight, total)) {
        // Left out: a footprint whose texels all fall outside the ones the frame can read
        // (caustics_read_region.hpp). What every read texel receives is unchanged.
        if (!(culling() && misses_read_texels(first, first + size - 1))) deposit_footprint(first, size, weight, total, p.q);
        return;
    }
    deposit_lattice_hat(p, traced_lattice_rays(p.index, chunk, pc.source.space));
#endif
}
#endif
