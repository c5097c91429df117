// The world-space direction of the camera ray through a pixel centre.
#ifndef VKWATER_CAMERA_RAY_GLSL
#define VKWATER_CAMERA_RAY_GLSL

#include "common/frame_constants.glsl"

// The unit direction from the eye through the point of normalised device coordinates `ndc`. The
// ray runs to that point on the far plane (depth 0: the projection is reversed-Z): a point on the
// near plane, centimetres from the eye, would lose about log2(|eye| / near) bits of the
// direction to the subtraction (about 1e-5 for an eye 2 m from the origin and a 1 cm near plane).
vec3 camera_ray_through_ndc(vec2 ndc) {
    vec4 on_far_plane = frame.inv_view_proj * vec4(ndc, 0.0, 1.0);
    return normalize(on_far_plane.xyz / on_far_plane.w - frame.camera_position.xyz);
}

// pixel: gl_FragCoord.xy (row 0 at the top of the image, which is +y in NDC
// because the frame graph flips the viewport).
vec3 camera_ray_direction(vec2 pixel) {
    return camera_ray_through_ndc(
        vec2(2.0 * pixel.x / frame.viewport.x - 1.0, 1.0 - 2.0 * pixel.y / frame.viewport.y));
}

#endif
