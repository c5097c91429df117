#version 460
// One axis of the caustic map's density-adaptive blur (passes/caustics/caustics_blur.hpp). Written as a
// gather that is exactly a scatter: every source texel spreads its irradiance over a tent of its
// own half-width h along the axis, with weights divided by their sum over the taps that lie on
// the map, so each source gives away exactly what it holds (energy preserved to fp32 rounding,
// whatever the widths). h = r + 1 with r the texel's blur radius: r = 0 is the identity.
// The radius comes from the photon density the texel's irradiance implies: photons carry about
// equal flux, so n / n_flat = E / E_flat, and a density estimate's noise is 1/sqrt(photons in the
// kernel): r = r0 sqrt(E_flat / E) keeps it about constant (focal lines stay sharp, sparse light
// is smoothed), at most kMaxBlurRadius. The first axis computes r from the irradiance; it leaves
// in its output's alpha the flux-weighted mean r of the light it brought to each texel, and the
// second axis spreads each texel with h = 1 + that r: light keeps the width of the texel it came
// from (a dark texel next to a focal line spreads the line's light with the line's narrow width).
// The alpha carries r, not h, so that r = 0 stays exactly 0 through the mean (0 / light): a mean
// of h = 1 would be weighted_h / light, which a device's division (2.5 ULP in Vulkan) can round to
// 1 + 2^-23, and a half-width above 1 reaches the neighbours.
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) readonly uniform image2D source;
layout(set = 0, binding = 1, rgba32f) writeonly uniform image2D target;

layout(push_constant) uniform Push {
    ivec2 size;        // the map's texels
    ivec2 axis;        // (1, 0) or (0, 1)
    float radius;      // r0, texels, at the flat-water photon density
    float flat_sum;    // E_flat summed over RGB, W m^-2 normal to the beam (the density's unit)
    uint first_axis;   // 1: r from the irradiance; 0: h from the source's alpha
    float pad;
} pc;

const float kMaxBlurRadius = 4.0;  // texels: at most 9 taps per axis
const int kMaxReach = 4;

float radius_of(vec4 texel) {
    if (pc.first_axis == 0u) return texel.a;
    // The darkest texels are held at E_flat / 256 (the radius then reaches its cap anyway).
    const float e = max(texel.r + texel.g + texel.b, pc.flat_sum * (1.0 / 256.0));
    return clamp(pc.radius * sqrt(pc.flat_sum / e), 0.0, kMaxBlurRadius);
}

// The sum of max(0, 1 - |d| / h) over the integers d strictly inside (-h, h) with at + d on the
// map [0, extent): n = ceil(h) - 1 taps per side, 1 + 2 n - n (n + 1) / h in all, less the taps
// beyond either edge (k = first .. n: (n - first + 1) - (n (n + 1) - first (first - 1)) / (2 h)).
float beyond(int first, int n, float h) {
    if (first > n) return 0.0;
    return float(n - first + 1) - float(n * (n + 1) - first * (first - 1)) / (2.0 * h);
}

float tent_sum(int at, int extent, float h) {
    const int n = int(ceil(h)) - 1;
    return 1.0 + 2.0 * float(n) - float(n * (n + 1)) / h - beyond(at + 1, n, h) - beyond(extent - at, n, h);
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, pc.size))) return;
    const int extent = pc.axis.x != 0 ? pc.size.x : pc.size.y;
    vec3 sum = vec3(0.0);
    float weighted_r = 0.0;  // sum of (light brought) x (its source's r), over RGB
    for (int d = -kMaxReach; d <= kMaxReach; ++d) {
        const ivec2 q = p - d * pc.axis;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, pc.size))) continue;
        const vec4 s = imageLoad(source, q);
        const float r = radius_of(s);
        const float h = 1.0 + r;
        const float w = 1.0 - float(abs(d)) / h;
        if (w <= 0.0) continue;
        const vec3 brought = s.rgb * (w / tent_sum(pc.axis.x != 0 ? q.x : q.y, extent, h));
        sum += brought;
        weighted_r += (brought.r + brought.g + brought.b) * r;
    }
    // The second axis's radius for this texel (0, the identity, where no light arrived).
    const float light = sum.r + sum.g + sum.b;
    const float own = pc.first_axis != 0u && light > 0.0 ? weighted_r / light : 0.0;
    imageStore(target, p, vec4(sum, own));
}
