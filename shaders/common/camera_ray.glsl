// The world-space direction of the camera ray through a pixel centre.
#ifndef VKWATER_CAMERA_RAY_GLSL
#define VKWATER_CAMERA_RAY_GLSL

#include "common/frame_constants.glsl"

// pixel: gl_FragCoord.xy (row 0 at the top of the image, which is +y in NDC
// because the frame graph flips the viewport). The ray runs to the pixel's point on the far
// plane (depth 0: the projection is reversed-Z): a point on the near plane, centimetres from
// the eye, would lose about log2(|eye| / near) bits of the direction to the subtraction.
vec3 camera_ray_direction(vec2 pixel) {
    vec2 ndc = vec2(2.0 * pixel.x / frame.viewport.x - 1.0, 1.0 - 2.0 * pixel.y / frame.viewport.y);
    vec4 on_far_plane = frame.inv_view_proj * vec4(ndc, 0.0, 1.0);
    return normalize(on_far_plane.xyz / on_far_plane.w - frame.camera_position.xyz);
}

#endif
