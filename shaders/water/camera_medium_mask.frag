#version 450
#extension GL_GOOGLE_include_directive : require
// The camera medium per pixel (passes/water/camera_medium.hpp): 1 where the camera ray's origin
// on the near plane lies in the water, against the exact surface (water/surface_refinement.glsl
// evaluates it, specialised for the scene's wave model).
#include "common/frame_constants.glsl"
#include "water/surface_refinement.glsl"

layout(location = 0) out float out_in_water;

// Newton steps of the horizontal inversion: Gerstner waves (steepness below 1) and the choppy
// ocean converge to fp32 in a few; a heightfield in one.
const int INVERSION_STEPS = 8;

void main() {
    const vec2 ndc = vec2(2.0 * gl_FragCoord.x / frame.viewport.x - 1.0, 1.0 - 2.0 * gl_FragCoord.y / frame.viewport.y);
    const vec4 on_near_plane = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    const vec3 q = on_near_plane.xyz / on_near_plane.w;
    const bool in_volume = all(lessThanEqual(abs(q.xz), vec2(params.half_extent))) && q.y > params.bottom_y;
    // Below every trough, or above every crest, q.y alone decides; between them the surface.
    const float amplitude = water_height_bound();
    bool in_water = in_volume && q.y < params.level - amplitude;
    const bool undecided = in_volume && WATER_SURFACE_MODEL != WATER_SURFACE_FLAT &&
                           abs(q.y - params.level) <= amplitude;
    if (WATER_SURFACE_MODEL == WATER_SURFACE_FLAT) in_water = in_volume && q.y < params.level;
    // The grid parameter whose point lies above or below q, x0 + D(x0) = q.xz, by Newton's
    // method, then the height there. A loop, not an if: llvmpipe skips a loop that no pixel of
    // its group enters, where it would run an if's body masked (docs/lavapipe.md).
    vec2 x = q.xz;
    for (int i = 0; undecided && i <= INVERSION_STEPS; ++i) {
        vec3 p, dP_du, dP_dv;
        water_surface_at(x, p, dP_du, dP_dv);
        const mat2 jacobian = mat2(dP_du.x, dP_du.z, dP_dv.x, dP_dv.z);  // columns
        if (i == INVERSION_STEPS || !(abs(determinant(jacobian)) > 1e-6)) {
            in_water = q.y < p.y;
            break;
        }
        x -= inverse(jacobian) * (p.xz - q.xz);
    }
    out_in_water = in_water ? 1.0 : 0.0;
}
