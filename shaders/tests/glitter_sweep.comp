#version 450
#extension GL_GOOGLE_include_directive : require
// Test kernel: evaluates shaders/water/glitter_lobe.glsl over a grid of eye directions o and writes
// L(o) o_y times the grid cell's solid angle, so that the host's sum is the integral of L o_y over
// the eye's hemisphere (tests/optics/glitter_test.cpp). Mode bit 0 clear: a grid over (cos theta,
// phi) of the whole hemisphere; set: a grid over the plane tangent to `centre` at unit distance, o =
// normalize(centre + a t1 + b t2) with |a|, |b| <= half_width, where d(omega) = da db / (1 + a^2 +
// b^2)^(3/2), for narrow lobes. Mode bit 1: the transmission lobe toward an eye in the water (the
// lower hemisphere, |o_y| in place of o_y), else the reflection lobe. Fresnel: the exact form at the
// facet's cosine. Per sample: that value, and o (3 floats), for the lobe's centroid.
#include "common/fresnel.glsl"
#include "water/glitter_lobe.glsl"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) writeonly buffer Results { float values[]; } results;
layout(push_constant) uniform Params {
    vec4 to_source;   // xyz
    vec4 centre;      // xyz: mode 1's patch centre (unit); w: half width
    vec4 covariance;  // xyz: S_xx, S_xz, S_zz; w: ior
    vec2 mean_slope;
    uint n;           // samples per grid side
    uint mode;
} params;

void main() {
    const uint index = gl_GlobalInvocationID.x;
    if (index >= params.n * params.n) return;
    const float i = (float(index % params.n) + 0.5) / float(params.n);
    const float j = (float(index / params.n) + 0.5) / float(params.n);
    vec3 o;
    float solid_angle;
    const bool transmitted = (params.mode & 2u) != 0u;
    if ((params.mode & 1u) == 0u) {
        const float u = i, phi = 2.0 * GLITTER_PI * j;
        const float s = sqrt(max(0.0, 1.0 - u * u));
        o = vec3(s * cos(phi), transmitted ? -u : u, s * sin(phi));
        solid_angle = 2.0 * GLITTER_PI / float(params.n * params.n);
    } else {
        const vec3 c = params.centre.xyz;
        const vec3 t1 = normalize(abs(c.y) < 0.9 ? cross(c, vec3(0.0, 1.0, 0.0)) : cross(c, vec3(1.0, 0.0, 0.0)));
        const vec3 t2 = cross(c, t1);
        const float w = params.centre.w;
        const float a = (2.0 * i - 1.0) * w, b = (2.0 * j - 1.0) * w;
        const float r2 = 1.0 + a * a + b * b;
        o = (c + a * t1 + b * t2) / sqrt(r2);
        solid_angle = (2.0 * w / float(params.n)) * (2.0 * w / float(params.n)) / (r2 * sqrt(r2));
    }
    const vec3 l = params.to_source.xyz;
    const float n = params.covariance.w;
    float value = 0.0;
    if (transmitted && o.y < 0.0) {
        const float cos_h = max(0.0, dot(l, glitter_refraction_half_vector(o, l, n)));
        const float transmittance = fresnel_exact(cos_h, 1.0, n).T;
        value = glitter_transmission_lobe(o, l, n, params.mean_slope, params.covariance.xyz, transmittance) * -o.y *
                solid_angle;
    } else if (!transmitted && o.y > 0.0) {
        const float cos_h = max(0.0, dot(o, glitter_half_vector(o, l)));
        const float reflectance = fresnel_exact(cos_h, 1.0, n).R;
        value = glitter_lobe(o, l, params.mean_slope, params.covariance.xyz, reflectance) * o.y * solid_angle;
    }
    results.values[4u * index] = value;
    results.values[4u * index + 1u] = o.x;
    results.values[4u * index + 2u] = o.y;
    results.values[4u * index + 3u] = o.z;
}
