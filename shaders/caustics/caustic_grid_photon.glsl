// The photon of one invocation of the photon grid, shared by the kernels that
// splat it (caustic_photons.comp into the light-space map, caustic_camera_splats.comp into the
// camera's view) so that both trace identical photons: sub-cell (a, b) of cell (i, j) is
// invocation (i S + a, j_local S + b) of a chunk of cell rows; it leaves from the sub-cell's centre
// or a hashed point of it, and (VKWATER_SUN_SHADOW) is stopped by objects above the water and at
// the first receiver mesh under it.
//
// The includer declares, before including this file, the chunk's vertex rows as
//   layout(...) readonly buffer Surface { WaterVertex vertices[]; };
#ifndef VKWATER_CAUSTIC_GRID_PHOTON_GLSL
#define VKWATER_CAUSTIC_GRID_PHOTON_GLSL

#include "caustics/caustic_photon.glsl"
#ifdef VKWATER_SUN_SHADOW
#include "caustics/caustic_receiver_hit.glsl"  // bindings 6 and 7: the sun shadow map
#endif

// What every photon kernel's push constants begin with (std430 and std140 alike: six vec4).
struct CausticPhotonSource {
    CausticLightSpace space;
    vec4 deposit_scale;  // rgb: E_s / LSB per channel (0 for a sun at or below the horizon)
    vec4 sigma_t;        // rgb: extinction, 1/m
};

// Which photons one dispatch traces: cell rows first_row .. first_row + rows of an R x R grid, S x S
// photons per cell.
struct CausticPhotonChunk {
    uint resolution;  // R cells per side
    uint sub;         // S
    uint first_row;   // first cell row of this chunk
    uint rows;        // cell rows in this chunk
    bool jitter;      // each photon from a hashed point of its sub-cell
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

// One traced photon with what its splat kernels need: its cell, its sub-cell [uv0, uv1], the
// point `at` it left from, and its flux in units of the LSB (q, per RGB).
struct GridPhoton {
    CausticCell cell;
    vec2 uv0, uv1, at;
    CausticPhoton photon;
    vec3 q;
};

// False for an invocation outside the chunk and for a photon that carries nothing or whose flux
// is not finite (dropped here, at its producer: uint64() of it is undefined).
bool trace_grid_photon(uvec2 g, CausticPhotonChunk chunk, CausticPhotonSource source, out GridPhoton p) {
    const uint S = chunk.sub;
    if (g.x >= chunk.resolution * S || g.y >= chunk.rows * S) return false;
    const uvec2 cell = g / S;
    const uint row = chunk.resolution + 1u;
    const uint k = cell.y * row + cell.x;
    p.cell = CausticCell(vertices[k], vertices[k + 1u], vertices[k + row], vertices[k + row + 1u]);
    p.uv0 = vec2(g % S) / float(S);
    p.uv1 = vec2(g % S + 1u) / float(S);
    const uvec2 index = uvec2(g.x, g.y + chunk.first_row * S);  // the photon's place in the whole grid
    p.at = chunk.jitter ? mix(p.uv0, p.uv1, caustic_jitter_point(index)) : 0.5 * (p.uv0 + p.uv1);
    if (!trace_caustic_photon_at(p.cell, p.uv0, p.uv1, p.at, source.space, source.sigma_t.rgb, p.photon)) return false;
#ifdef VKWATER_SUN_SHADOW
    // Objects above the water stop it before it enters; those under it are receivers in front of
    // the floor.
    if (!caustic_entry_lit(p.photon, source.space.sun.xyz)) return false;
    const float l = receiver_path(p.photon, caustic_map_direction(source.space), source.space.origin.w, p.photon.path);
    caustic_photon_stop_at(p.photon, l, source.sigma_t.rgb);
#endif
    p.q = source.deposit_scale.rgb * p.photon.energy;
    return all(greaterThanEqual(p.q, vec3(0.0))) && all(lessThan(p.q, vec3(9.0e18)));
}

// The cumulative share round(q w) for w in [0, 1], never above q: the kernels split a photon's
// integer flux over their taps as differences of these, so the taps sum to it exactly.
uint64_t caustic_share(uint64_t q, float w) { return min(uint64_t(float(q) * w + 0.5), q); }

#endif
