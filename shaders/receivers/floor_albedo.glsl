// The floor's albedo at world (x, z): tiles of side floor_plane.z with grout lines floor_plane.w
// wide centred on their edges (the multiples of the side), or one albedo when floor_plane.z is 0.
// The reference evaluates the same pattern in double (FloorPlane::albedo_at, engine/scene/scene.hpp).
#ifndef VKWATER_FLOOR_ALBEDO_GLSL
#define VKWATER_FLOOR_ALBEDO_GLSL

#include "common/frame_constants.glsl"

vec3 floor_albedo_at(vec2 xz) {
    const float side = frame.floor_plane.z;
    if (side <= 0.0) return frame.floor_albedo.rgb;
    // floor(v + 0.5), not round(): GLSL leaves round()'s direction at .5 to the implementation.
    const vec2 from_edge = abs(xz - side * floor(xz / side + 0.5));
    return any(lessThan(from_edge, vec2(0.5 * frame.floor_plane.w))) ? frame.floor_grout.rgb : frame.floor_albedo.rgb;
}

#endif
