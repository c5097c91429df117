// Push constants of the receiver shaders: the mesh's albedo, which scene view (if any) the draw
// renders (passes/scene_views/scene_view.hpp), and a mesh part's cutout.
#ifndef VKWATER_RECEIVER_PUSH_GLSL
#define VKWATER_RECEIVER_PUSH_GLSL

#include "common/frame_constants.glsl"

layout(push_constant) uniform Receiver {
    vec4 albedo;  // rgb (meshes; the floor's comes from the frame constants)
    vec4 view;    // x: 1 for the mirrored view; y: which side the view keeps (+1 the camera's side of the
                  // surface, -1 the other side, 0 not a scene view: everything, as the camera sees it);
                  // z: clip margin beyond the mean level, m (the waves' amplitude and a millimetre)
    vec4 material;  // meshes: x the base colour factor's alpha, y the cutout's threshold (negative: opaque)
} receiver;

bool in_scene_view() { return receiver.view.y != 0.0; }
bool scene_view_mirrored() { return receiver.view.x > 0.5; }

// Whether world point p lies on the side of the water plane the view keeps (clip planes
// a margin beyond the mean level, so that the waves' band is in both views).
bool kept_by_scene_view(vec3 p) {
    bool camera_above = frame.camera_medium.x < 0.5;
    bool keep_above = (receiver.view.y > 0.0) == camera_above;
    float level = frame.water.x;
    return keep_above ? p.y >= level - receiver.view.z : p.y <= level + receiver.view.z;
}

#endif
