// The photon of one invocation of the photon grid, shared by the kernels that
// splat it (caustic_photons.comp into the light-space map, caustic_camera_splats.comp into the
// camera's view) so that both trace identical photons: sub-cell (a, b) of cell (i, j) is
// invocation (i S + a, j_local S + b) of a chunk of cell rows; it leaves from the sub-cell's centre
// or a hashed point of it, and (VKWATER_SUN_SHADOW) is stopped by objects above the water and at
// the first receiver mesh under it.
//
// The includer declares, before including this file, the chunk's vertex rows as
//   layout(...) readonly buffer Surface { WaterVertex vertices[]; };
// whose element vertex_offset is the first vertex of the chunk's first row (a binding may start
// earlier, with the row before it: the adaptive kernel reads its photons' neighbours there).
#ifndef VKWATER_CAUSTIC_GRID_PHOTON_GLSL
#define VKWATER_CAUSTIC_GRID_PHOTON_GLSL

#include "caustics/caustic_photon.glsl"
#include "caustics/caustic_photon_source.glsl"
#ifdef VKWATER_SUN_SHADOW
#include "caustics/caustic_receiver_hit.glsl"  // bindings 6 and 7: the sun shadow map
#endif


// Which photons one dispatch traces: cell rows first_row .. first_row + rows of an R x R grid, S x S
// photons per cell.
struct CausticPhotonChunk {
    uint resolution;  // R cells per side
    uint sub;         // S
    uint first_row;   // first cell row of this chunk
    uint rows;        // cell rows in this chunk
    bool jitter;      // each photon from a hashed point of its sub-cell
    uint vertex_offset;  // the element of `vertices` that holds vertex (0, first_row)
};

// A point of [0, 1)^2 from the photon's index (two rounds of a 32-bit integer hash, after
// Wellons' "lowbias32"): the same point every frame and run, so renders stay bit-identical.
uint caustic_hash32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
vec2 caustic_jitter_point(uvec2 photon) {
    const uint a = caustic_hash32(photon.x * 0x9e3779b9u ^ caustic_hash32(photon.y));
    const uint b = caustic_hash32(a);
    return vec2(a >> 8, b >> 8) * (1.0 / 16777216.0);
}

// One photon's place on the surface: its cell, its sub-cell [uv0, uv1] of it, and the point `at` it
// leaves from (the sub-cell's centre, or a hashed point of it).
struct GridSubCell {
    CausticCell cell;
    vec2 uv0, uv1, at;
};

// Sub-cell `photon` (its place in the whole grid, x and y in [0, R S)) of a cell row from
// first_row - 1 to first_row + rows: the rows next to the chunk need its binding to hold them.
GridSubCell grid_sub_cell(uvec2 photon, CausticPhotonChunk chunk) {
    const uint S = chunk.sub;
    const uvec2 cell = photon / S;
    const uint row = chunk.resolution + 1u;
    const uint k = uint(int(chunk.vertex_offset) + (int(cell.y) - int(chunk.first_row)) * int(row)) + cell.x;
    GridSubCell c;
    c.cell = CausticCell(vertices[k], vertices[k + 1u], vertices[k + row], vertices[k + row + 1u]);
    c.uv0 = vec2(photon % S) / float(S);
    c.uv1 = vec2(photon % S + 1u) / float(S);
    c.at = chunk.jitter ? mix(c.uv0, c.uv1, caustic_jitter_point(photon)) : 0.5 * (c.uv0 + c.uv1);
    return c;
}

// One traced photon with what its splat kernels need: its place in the whole grid, its cell, its
// sub-cell [uv0, uv1], the point `at` it left from, and its flux in units of the LSB (q, per RGB).
struct GridPhoton {
    uvec2 index;
    CausticCell cell;
    vec2 uv0, uv1, at;
    CausticPhoton photon;
    vec3 q;
};

// True for a flux (LSB units) that uint64() converts exactly: finite, non-negative, below 2^63.
bool caustic_flux_representable(vec3 q) { return all(greaterThanEqual(q, vec3(0.0))) && all(lessThan(q, vec3(9.0e18))); }

// The photon `index` (its place in the whole grid) of the sub-cell read for it; false for a photon
// that carries nothing or whose flux is not finite (dropped here, at its producer: uint64() of it
// is undefined).
bool trace_sub_cell_photon(GridSubCell sub_cell, uvec2 index, CausticPhotonSource source, out GridPhoton p) {
    p.index = index;
    p.cell = sub_cell.cell;
    p.uv0 = sub_cell.uv0;
    p.uv1 = sub_cell.uv1;
    p.at = sub_cell.at;
    if (!trace_caustic_photon_at(p.cell, p.uv0, p.uv1, p.at, source.space, source.sigma_t.rgb, p.photon)) return false;
#ifdef VKWATER_SUN_SHADOW
    // Objects above the water stop it before it enters; those under it are receivers in front of
    // the floor.
    if (!caustic_entry_lit(p.photon, source.space.sun.xyz)) return false;
    const float l = receiver_path(p.photon, caustic_map_direction(source.space), source.space.origin.w, p.photon.path);
    caustic_photon_stop_at(p.photon, l, source.sigma_t.rgb);
#endif
    p.q = source.deposit_scale.rgb * p.photon.energy;
    return caustic_flux_representable(p.q);
}

// The photon of invocation g of the chunk; false also for an invocation outside it.
bool trace_grid_photon(uvec2 g, CausticPhotonChunk chunk, CausticPhotonSource source, out GridPhoton p) {
    const uint S = chunk.sub;
    if (g.x >= chunk.resolution * S || g.y >= chunk.rows * S) return false;
    const uvec2 index = uvec2(g.x, g.y + chunk.first_row * S);
    return trace_sub_cell_photon(grid_sub_cell(index, chunk), index, source, p);
}

// The cumulative share round(q w) for w in [0, 1], never above q: the kernels split a photon's
// integer flux over their taps as differences of these, so the taps sum to it exactly.
uint64_t caustic_share(uint64_t q, float w) { return min(uint64_t(float(q) * w + 0.5), q); }

#endif
