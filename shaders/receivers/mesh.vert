#version 450
#extension GL_GOOGLE_include_directive : require
// Receiver meshes, already in world space (the scene loader applies their transforms).
#include "common/frame_constants.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec3 out_albedo;
layout(push_constant) uniform Receiver { vec4 albedo; } receiver;

void main() {
    out_position = in_position;
    out_normal = in_normal;
    out_albedo = receiver.albedo.rgb;
    gl_Position = frame.view_proj * vec4(in_position, 1.0);
}
