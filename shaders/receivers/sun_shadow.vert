#version 450
// The receiver meshes' depth seen along a beam (passes/receivers/sun_shadow.hpp): world space to the
// orthographic light space of one half of the map, pushed as one matrix with the half's clip
// height, which the fragment stage applies.
layout(location = 0) in vec3 in_position;
layout(location = 0) out float out_height;
layout(push_constant) uniform SunShadowPush {
    mat4 light_from_world;
    vec4 clip;  // x: meshes above this height cast nothing in this half
} push;

void main() {
    out_height = in_position.y;
    gl_Position = push.light_from_world * vec4(in_position, 1.0);
}
