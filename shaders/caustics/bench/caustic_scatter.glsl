// The scatter-only benchmark kernels' common part (tools/benchmarks/caustics_bench.cpp): one
// invocation per photon of an R x R grid, no tracing. Photon (i, j) lands where a photon of the
// same cell lands under flat water when the map has one texel per cell (texel (i + 1, j + 1),
// after the map's one-texel border and the extra texels margin_x, margin_y), offset by a quarter texel
// along both axes so that every one of the 2 x 2 bilinear taps is non-zero: 4 taps x 3 channels
// = 12 atomics per photon, what caustic_photons.comp performs for a photon under waves. The
// weights are the photon pass's 2x2 split of a fixed quantity.
#ifndef VKWATER_CAUSTIC_SCATTER_GLSL
#define VKWATER_CAUSTIC_SCATTER_GLSL

layout(local_size_x = 8, local_size_y = 8) in;  // as caustic_photons.comp

layout(push_constant) uniform Push {
    uint resolution;  // R photons per side
    uint width;       // map texels per row (W)
    uint height;      // map rows (H)
    uint margin_x;    // extra texels on each side beyond the one-texel border, along x
    uint margin_y;    // and along z
} pc;

// The photon's top-left tap and its bilinear fractions; false outside the grid.
bool scatter_photon(out ivec2 t0, out vec2 f) {
    const uvec2 g = gl_GlobalInvocationID.xy;
    t0 = ivec2(0);
    f = vec2(0.0);
    if (g.x >= pc.resolution || g.y >= pc.resolution) return false;
    t0 = ivec2(g) + ivec2(1u + pc.margin_x, 1u + pc.margin_y);
    f = vec2(0.25);
    return true;
}

bool scatter_on_map(ivec2 texel) {
    return texel.x >= 0 && texel.y >= 0 && texel.x < int(pc.width) && texel.y < int(pc.height);
}

// The float kernels' 12 deposits of one photon: the bilinear weights times a unit flux, each
// added by deposit_float, which the including shader defines (a float atomic or a CAS loop).
void deposit_float(ivec2 texel, uint channel, float value);
void scatter_float_taps(ivec2 t0, vec2 f) {
    for (uint ch = 0u; ch < 3u; ++ch) {
        deposit_float(t0, ch, (1.0 - f.x) * (1.0 - f.y));
        deposit_float(t0 + ivec2(0, 1), ch, (1.0 - f.x) * f.y);
        deposit_float(t0 + ivec2(1, 0), ch, f.x * (1.0 - f.y));
        deposit_float(t0 + ivec2(1, 1), ch, f.x * f.y);
    }
}

#endif
