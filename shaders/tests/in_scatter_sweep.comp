#version 450
#extension GL_GOOGLE_include_directive : require
// Test kernel: evaluates water_path_radiance (shaders/common/medium.glsl) over a grid
// of cases decoded from the invocation index (mixed radix): phase g, extinction,
// view elevation (including rays with 1 + c near 0), view azimuth, start depth,
// length and sun elevation. Output per case, 24 floats: the inputs as the shader used
// them, then the radiance (see the test for the layout).
#include "common/medium.glsl"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) writeonly buffer Results { float values[]; } results;
layout(push_constant) uniform Params { uint count; float ior; } params;

const float G[3] = float[](0.0, 0.9, -0.3);
const float SIGMA_T[4] = float[](1e-3, 0.1, 1.0, 10.0);
const float Z0[3] = float[](0.0, 0.5, 3.0);
const float S[3] = float[](0.1, 2.0, 20.0);
const float SUN_ELEVATION_DEG[3] = float[](90.0, 45.0, 10.0);

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    uint r = i;
    float g = G[r % 3]; r /= 3;
    float base = SIGMA_T[r % 4]; r /= 4;
    uint elevation_index = r % 15; r /= 15;
    float azimuth = (r % 2 == 0) ? 0.0 : 3.14159265; r /= 2;
    float z0 = Z0[r % 3]; r /= 3;
    float s = S[r % 3]; r /= 3;
    float sun_elevation = radians(SUN_ELEVATION_DEG[r % 3]);

    // The sun's refracted direction in the xz-plane (azimuth 0 is +x).
    float sin_t = cos(sun_elevation) / params.ior;
    vec3 t = vec3(sin_t, -sqrt(1.0 - sin_t * sin_t), 0.0);
    float cos_t = -t.y;
    // View elevations: 12 spread over [-89, 89] degrees, then three rays rising with
    // v.y = cos_t (1 + c = 0 exactly) and cos_t +- 1e-3.
    float v_y;
    if (elevation_index < 12) {
        v_y = sin(radians(-89.0 + 178.0 * float(elevation_index) / 11.0));
    } else {
        v_y = cos_t + 1e-3 * (float(elevation_index) - 13.0);
    }
    float horizontal = sqrt(max(0.0, 1.0 - v_y * v_y));
    vec3 v = vec3(horizontal * cos(azimuth), v_y, horizontal * sin(azimuth));
    // A rising ray ends at the surface.
    if (v.y > 0.0) s = min(s, z0 / v.y);

    vec3 sigma_t = base * vec3(1.0, 0.1, 10.0);
    vec3 sigma_s = 0.6 * sigma_t;
    vec3 e_perp0 = vec3(2.0, 1.0, 0.5);
    vec3 l_behind = vec3(0.3, 0.2, 0.1);
    vec3 radiance = water_path_radiance(sigma_s, sigma_t, g, z0, s, v, t, e_perp0, l_behind);

    float out_values[24] = float[](g, z0, s, v.x, v.y, v.z, t.x, t.y, t.z,
                                   sigma_t.r, sigma_t.g, sigma_t.b, sigma_s.r, sigma_s.g, sigma_s.b,
                                   e_perp0.r, e_perp0.g, e_perp0.b, l_behind.r, l_behind.g, l_behind.b,
                                   radiance.r, radiance.g, radiance.b);
    for (int k = 0; k < 24; ++k) results.values[24 * i + k] = out_values[k];
}
