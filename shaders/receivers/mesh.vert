#version 450
#extension GL_GOOGLE_include_directive : require
// Receiver meshes, already in world space (the scene loader applies their transforms),
// seen from the camera or, in a scene view for the water's lookups, as that view sees them.
// The base colour's texture coordinates and vertex colour go on to the fragment stage
// (passes/receivers/receiver_meshes.hpp has the vertex layout).
#include "receivers/receiver_push.glsl"
#include "scene_views/scene_view.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec3 out_albedo;
layout(location = 3) out vec2 out_uv;
layout(location = 4) out vec4 out_color;

void main() {
    out_position = in_position;
    out_normal = in_normal;
    out_albedo = receiver.albedo.rgb;
    out_uv = in_uv;
    out_color = in_color;
    gl_Position = in_scene_view() ? scene_view_clip(in_position, scene_view_mirrored())
                                  : frame.view_proj * vec4(in_position, 1.0);
}
