// The medium of this pixel's camera ray at its origin on the near plane: true in the
// water. With the stencil split (the *_per_pixel.frag variants define
// VKWATER_PER_PIXEL_MEDIUM and bind its mask at binding 3) it is exact per pixel; when
// the split is culled (no ray can start in the water) or the scene forces it off, the
// per-frame value of the frame constants stands in.
#ifndef VKWATER_CAMERA_MEDIUM_GLSL
#define VKWATER_CAMERA_MEDIUM_GLSL

#include "common/frame_constants.glsl"

#ifdef VKWATER_PER_PIXEL_MEDIUM
layout(set = 0, binding = 3) uniform sampler2D camera_medium_mask;
bool camera_in_water() { return texelFetch(camera_medium_mask, ivec2(gl_FragCoord.xy), 0).r > 0.5; }
#else
bool camera_in_water() { return frame.camera_medium.x > 0.5; }
#endif

#endif
