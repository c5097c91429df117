#version 460
// Scatter only, 64-bit fixed point through a workgroup tile (tools/benchmarks/caustics_bench.cpp):
// the same 12 deposits per photon as caustic_scatter_fixed.comp, added first to a tile of the
// group's texels in shared memory (shaderSharedInt64Atomics) and then to the map once per touched
// texel and channel: 8 x 8 photons one texel apart touch 9 x 9 texels, so 243 global atomics
// replace 768. Integer addition commutes, so the map equals caustic_scatter_fixed.comp's bit for
// bit. The tile is the box of the group's taps (found with shared atomicMin/Max between two
// barriers); taps outside it, and every tap of a box beyond kTileTexels, go to the map directly.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

#include "caustics/bench/caustic_scatter.glsl"

layout(set = 0, binding = 0, std430) buffer Flux { uint64_t flux[]; };

const int kTileTexels = 1024;  // 24 KiB of the 32 KiB of shared memory every device offers
shared uint64_t tile_flux[kTileTexels * 3];
shared int tile_lo_x, tile_lo_y, tile_hi_x, tile_hi_y;
ivec2 tile_origin = ivec2(0), tile_size = ivec2(0);

void deposit_global(ivec2 texel, uint channel, uint64_t q) {
    if (q == 0ul || !scatter_on_map(texel)) return;
    atomicAdd(flux[(uint(texel.y) * pc.width + uint(texel.x)) * 3u + channel], q);
}

void deposit(ivec2 texel, uint channel, uint64_t q) {
    const ivec2 local = texel - tile_origin;
    if (q != 0ul && all(greaterThanEqual(local, ivec2(0))) && all(lessThan(local, tile_size))) {
        atomicAdd(tile_flux[(local.y * tile_size.x + local.x) * 3 + int(channel)], q);
        return;
    }
    deposit_global(texel, channel, q);
}

uint64_t share(uint64_t q, float w) { return min(uint64_t(float(q) * w + 0.5), q); }

void main() {
    ivec2 t0;
    vec2 f;
    const bool photon = scatter_photon(t0, f);  // no early return: every invocation meets the barriers
    if (gl_LocalInvocationIndex == 0u) {
        tile_lo_x = tile_lo_y = 0x7fffffff;
        tile_hi_x = tile_hi_y = -0x7fffffff;
    }
    barrier();
    if (photon) {
        atomicMin(tile_lo_x, t0.x);
        atomicMin(tile_lo_y, t0.y);
        atomicMax(tile_hi_x, t0.x + 1);
        atomicMax(tile_hi_y, t0.y + 1);
    }
    barrier();
    tile_origin = ivec2(tile_lo_x, tile_lo_y);
    const ivec2 box = max(ivec2(tile_hi_x, tile_hi_y) - tile_origin + 1, ivec2(0));  // 0 x 0 for an empty group
    tile_size.x = min(box.x, kTileTexels);
    tile_size.y = tile_size.x == 0 ? 0 : min(box.y, kTileTexels / tile_size.x);
    const uint invocations = gl_WorkGroupSize.x * gl_WorkGroupSize.y, values = uint(tile_size.x * tile_size.y) * 3u;
    for (uint i = gl_LocalInvocationIndex; i < values; i += invocations) tile_flux[i] = 0ul;
    barrier();
    if (photon) {
        for (uint ch = 0u; ch < 3u; ++ch) {
            const uint64_t total = uint64_t(1u << 20);
            const uint64_t x0 = share(total, 1.0 - f.x), x1 = total - x0;
            const uint64_t x0y0 = share(x0, 1.0 - f.y), x1y0 = share(x1, 1.0 - f.y);
            deposit(t0, ch, x0y0);
            deposit(t0 + ivec2(0, 1), ch, x0 - x0y0);
            deposit(t0 + ivec2(1, 0), ch, x1y0);
            deposit(t0 + ivec2(1, 1), ch, x1 - x1y0);
        }
    }
    barrier();
    for (uint i = gl_LocalInvocationIndex; i < values; i += invocations) {
        const int texel = int(i / 3u);
        deposit_global(tile_origin + ivec2(texel % tile_size.x, texel / tile_size.x), i % 3u, tile_flux[i]);
    }
}
