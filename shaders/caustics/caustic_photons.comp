#version 460
// Photon grid -> light-space caustic flux, accumulated deterministically in 64-bit fixed point
// (passes/caustics_photons.hpp). Variants: plain (the floor plane is the receiver) and
// VKWATER_SUN_SHADOW (receiver meshes under the water and occluders above it, from the sun
// shadow map); the splat kernel is a variant too (VKWATER_SPLAT_BILINEAR, _ADAPTIVE,
// _FOOTPRINT): llvmpipe's compiled code for one kernel doubles in time when the others' code
// sits in the same shader, even behind a uniform branch (measured: 104 ms against 223 ms for the
// bilinear kernel's 1024^2 photons). One invocation per photon: sub-cell (a, b) of cell (i, j),
// invocation (i S + a, j_local S + b). Each photon's flux, in units of the map's LSB, is rounded
// once to an integer q and split over its splat kernel (caustic_splat.glsl: a tent one texel
// wide, the bilinear 2x2, or as wide as its neighbours' spacing; caustic_footprint.glsl: its
// sub-cell's footprint, by area) by cumulative rounding, so the taps sum to q exactly (a
// normalised kernel with no rounding drift) and integer addition makes the result independent of
// the order the atomics land in.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

#include "caustics/caustic_photon.glsl"
#ifdef VKWATER_SPLAT_FOOTPRINT
#include "caustics/caustic_footprint.glsl"
#endif
#include "caustics/caustic_splat.glsl"
#ifdef VKWATER_SUN_SHADOW
#include "caustics/caustic_receiver_hit.glsl"  // bindings 6 and 7: the sun shadow map
#endif

layout(local_size_x = 8, local_size_y = 8) in;

// The vertex rows first_row .. first_row + rows of the grid (a chunk's binding).
layout(set = 0, binding = 0, std430) readonly buffer Surface { WaterVertex vertices[]; };
// The map rows band_first .. band_first + band_rows - 1, three uint64 per texel (R, G, B).
layout(set = 0, binding = 1, std430) buffer Flux { uint64_t flux[]; };
// Flux whose kernel tap fell outside the map, per channel (added by the band-0 dispatches only).
layout(set = 0, binding = 2, std430) buffer Lost { uint64_t lost[]; };

// Mirrors CausticPhotonPush in passes/caustics_photons.cpp (128 bytes, the guaranteed minimum).
layout(push_constant) uniform Push {
    CausticLightSpace space;
    vec4 deposit_scale;  // rgb: E_s / LSB per channel (0 for a sun at or below the horizon)
    vec4 sigma_t;        // rgb: extinction, 1/m
    uint resolution;     // R cells per side
    uint sub;            // S: S x S photons per cell
    uint first_row;      // first cell row of this chunk
    uint rows;           // cell rows in this chunk
    uint band_first;     // first map row of this band
    uint band_rows;      // map rows in this band
    uint jitter;         // 1: each photon leaves from a hashed point of its sub-cell
    uint pad;
} pc;

// A point of [0, 1)^2 from the photon's index (two rounds of a 32-bit integer hash, after
// Wellons' "lowbias32"): the same point every frame and run, so renders stay bit-identical.
uint hash32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
vec2 jitter_point(uvec2 photon) {
    const uint a = hash32(photon.x * 0x9e3779b9u ^ hash32(photon.y));
    const uint b = hash32(a);
    return vec2(a >> 8, b >> 8) * (1.0 / 16777216.0);
}

void deposit(ivec2 texel, uint channel, uint64_t q) {
    if (q == 0ul) return;
    if (texel.x < 0 || texel.y < 0 || texel.x >= int(pc.space.u_axis.w) || texel.y >= int(pc.space.v_axis.w)) {
        if (pc.band_first == 0u) atomicAdd(lost[channel], q);
        return;
    }
    const int row = texel.y - int(pc.band_first);
    if (row < 0 || row >= int(pc.band_rows)) return;  // another band's dispatch adds it
    atomicAdd(flux[(uint(row) * uint(pc.space.u_axis.w) + uint(texel.x)) * 3u + channel], q);
}

// The cumulative share round(q w) for w in [0, 1], never above q.
uint64_t share(uint64_t q, float w) { return min(uint64_t(float(q) * w + 0.5), q); }

// Splits q over the taps of one axis by cumulative rounding: share k is
// round(q W_k / W) - round(q W_{k-1} / W) with W_k the partial sums of the weights, so the shares
// are non-negative and sum to q exactly.
uint64_t axis_share(uint64_t q, SplatAxis axis, float total, int k, inout float partial, inout uint64_t given) {
    partial += splat_weight(axis, k);
    const uint64_t upto = k == axis.count - 1 ? q : share(q, partial / total);
    const uint64_t s = upto - given;
    given = upto;
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
        const uint64_t x0 = share(total, 1.0 - f.x), x1 = total - x0;
        const uint64_t x0y0 = share(x0, 1.0 - f.y), x1y0 = share(x1, 1.0 - f.y);
        deposit(t0, ch, x0y0);
        deposit(t0 + ivec2(0, 1), ch, x0 - x0y0);
        deposit(t0 + ivec2(1, 0), ch, x1y0);
        deposit(t0 + ivec2(1, 1), ch, x1 - x1y0);
    }
}

// A tent of the given half-widths (at least one texel), split over its taps.
void deposit_tent(vec2 coord, vec2 half_width, vec3 q) {
    const SplatAxis x_axis = splat_axis(coord.x, half_width.x), y_axis = splat_axis(coord.y, half_width.y);
    const float x_total = splat_total(x_axis), y_total = splat_total(y_axis);
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t total = uint64_t(q[ch] + 0.5);
        float x_partial = 0.0;
        uint64_t x_given = 0ul;
        for (int i = 0; i < x_axis.count; ++i) {
            const uint64_t column = axis_share(total, x_axis, x_total, i, x_partial, x_given);
            float y_partial = 0.0;
            uint64_t y_given = 0ul;
            for (int j = 0; j < y_axis.count; ++j) {
                const uint64_t tap = axis_share(column, y_axis, y_total, j, y_partial, y_given);
                deposit(ivec2(x_axis.first + i, y_axis.first + j), ch, tap);
            }
        }
    }
}

#ifdef VKWATER_SPLAT_FOOTPRINT
// The footprint kernel: the photon's flux spread over its sub-cell's footprint by area, each
// channel split by cumulative rounding over the footprint's texels in row order; false (nothing
// deposited) where the footprint cannot be used.
bool deposit_footprint(CausticCell c, vec2 uv0, vec2 uv1, CausticPhoton photon, vec3 q) {
    vec2 corner[4];
    if (!footprint_corners(c, uv0, uv1, photon, pc.space, corner)) return false;
    ivec2 first, size;
    float weight[64];
    float total;
    if (!footprint_weights(corner, first, size, weight, total)) return false;
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t amount = uint64_t(q[ch] + 0.5);
        float partial = 0.0;
        uint64_t given = 0ul;
        for (int j = 0; j < size.y; ++j) {
            for (int i = 0; i < size.x; ++i) {
                partial += weight[j * kMaxFootprintTexels + i];
                const bool last = j == size.y - 1 && i == size.x - 1;
                const uint64_t upto = last ? amount : share(amount, partial / total);
                deposit(first + ivec2(i, j), ch, upto - given);
                given = upto;
            }
        }
    }
    return true;
}
#endif

void main() {
    const uint S = pc.sub;
    const uvec2 g = gl_GlobalInvocationID.xy;
    if (g.x >= pc.resolution * S || g.y >= pc.rows * S) return;
    const uvec2 cell = g / S;
    const uint row = pc.resolution + 1u;
    const uint k = cell.y * row + cell.x;
    const CausticCell c = CausticCell(vertices[k], vertices[k + 1u], vertices[k + row], vertices[k + row + 1u]);
    const vec2 uv0 = vec2(g % S) / float(S), uv1 = vec2(g % S + 1u) / float(S);
    const uvec2 index = uvec2(g.x, g.y + pc.first_row * S);  // the photon's place in the whole grid
    const vec2 at = pc.jitter != 0u ? mix(uv0, uv1, jitter_point(index)) : 0.5 * (uv0 + uv1);
    CausticPhoton photon;
    if (!trace_caustic_photon_at(c, uv0, uv1, at, pc.space, pc.sigma_t.rgb, photon)) return;
#ifdef VKWATER_SUN_SHADOW
    // Objects above the water stop it before it enters; those under it are receivers in front of
    // the floor.
    if (!caustic_entry_lit(photon, pc.space.sun.xyz)) return;
    const float l = receiver_path(photon, caustic_map_direction(pc.space), pc.space.origin.w, photon.path);
    caustic_photon_stop_at(photon, l, pc.sigma_t.rgb);
#endif

    const vec3 q = pc.deposit_scale.rgb * photon.energy;
    // Non-finite or absurd flux is dropped here, at its producer (uint64() of it is undefined).
    if (!(all(greaterThanEqual(q, vec3(0.0))) && all(lessThan(q, vec3(9.0e18))))) return;
    const vec2 coord = caustic_texel_coord(photon.hit, pc.space) - 0.5;
    // Far off the map (or not a number): every tap is outside, and int() of it is undefined.
    if (!all(lessThan(abs(coord), vec2(1e7)))) {
        for (uint ch = 0u; ch < 3u; ++ch) deposit(ivec2(-2), ch, uint64_t(q[ch] + 0.5));
        return;
    }
#if defined(VKWATER_SPLAT_BILINEAR)
    deposit_bilinear(coord, q);
#else
#if defined(VKWATER_SPLAT_FOOTPRINT)
    if (deposit_footprint(c, uv0, uv1, photon, q)) return;
#endif
    deposit_tent(coord, splat_half_width(c, at, 1.0 / float(S), photon, pc.space), q);
#endif
}
