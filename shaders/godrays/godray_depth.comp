#version 460
// The scene as the godray passes need it at their resolution (passes/godrays/godrays_depth.hpp): per
// godray pixel, r = the distance along its ray to the farthest scene surface among the output pixels
// it covers (reversed-Z: the smallest depth), so that a beam point is kept wherever any of them
// sees it; g = 1 where the camera ray starts in the water (the stencil split's mask at the pixel's
// centre with VKWATER_PER_PIXEL_MEDIUM, else the frame's camera medium).
#extension GL_GOOGLE_include_directive : require

#include "godrays/godray_view.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1) uniform sampler2D scene_depth;  // D32, output size
layout(set = 0, binding = 2, rgba32f) writeonly uniform image2D view_depth;
#ifdef VKWATER_PER_PIXEL_MEDIUM
layout(set = 0, binding = 3) uniform sampler2D camera_medium_mask;  // R8, output size
#endif

void main() {
    const ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(view_depth);
    if (any(greaterThanEqual(g, size))) return;
    const ivec2 full = textureSize(scene_depth, 0);
    const vec2 scale = vec2(full) / vec2(size);
    const ivec2 lo = ivec2(vec2(g) * scale);
    const ivec2 hi = max(lo + 1, min(ivec2(vec2(g + 1) * scale), full));
    float depth = 2.0;
    ivec2 farthest = lo;
    for (int y = lo.y; y < hi.y; ++y) {
        for (int x = lo.x; x < hi.x; ++x) {
            const float d = texelFetch(scene_depth, ivec2(x, y), 0).r;
            if (d < depth) {
                depth = d;
                farthest = ivec2(x, y);
            }
        }
    }
    const float distance_to_scene = godray_scene_distance(vec2(farthest) + 0.5, vec2(full), depth);
#ifdef VKWATER_PER_PIXEL_MEDIUM
    const ivec2 centre = min(ivec2((vec2(g) + 0.5) * scale), full - 1);
    const float medium = texelFetch(camera_medium_mask, centre, 0).r > 0.5 ? 1.0 : 0.0;
#else
    const float medium = frame.camera_medium.x > 0.5 ? 1.0 : 0.0;
#endif
    imageStore(view_depth, g, vec4(distance_to_scene, medium, 0.0, 1.0));
}
