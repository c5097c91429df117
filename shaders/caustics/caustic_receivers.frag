#version 450
#extension GL_GOOGLE_include_directive : require
// The receivers as the camera sees them without the water (Ojeda & Susín 2013 section 4, step 1), for the
// camera-space caustic splats (passes/caustics/caustics_camera_receivers.hpp): the floor and the meshes
// below the mean level plus the clip margin, each texel holding the receiver's unit normal turned
// toward the eye (rgb) and its distance from the eye (a; 0 where no receiver is seen). Variant
// VKWATER_CUTOUT (meshes with glTF alphaMode MASK parts): a cutout's holes show what lies behind,
// as in receivers/receiver.frag.
#include "receivers/receiver_push.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_receiver;
#ifdef VKWATER_CUTOUT
layout(set = 0, binding = 8) uniform sampler2D base_color_texture;
layout(location = 3) in vec2 in_uv;
layout(location = 4) in vec4 in_color;
#endif

void main() {
    const vec3 p = in_world_position;
    if (p.y > frame.water.x + receiver.view.z) discard;  // above the water: no photon reaches it
#ifdef VKWATER_CUTOUT
    if (texture(base_color_texture, in_uv).a * in_color.a * receiver.material.x < receiver.material.y) discard;
#endif
    const vec3 eye = frame.camera_position.xyz;
    vec3 normal = normalize(in_normal);
    if (dot(normal, eye - p) < 0.0) normal = -normal;  // the side the eye sees
    out_receiver = vec4(normal, distance(eye, p));
}
