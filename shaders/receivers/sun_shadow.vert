#version 450
// The receiver meshes' depth seen from the sun (passes/sun_shadow.hpp): world space to the
// orthographic light space of fit_sun_shadow, pushed as one matrix. Depth only: no fragment stage.
layout(location = 0) in vec3 in_position;
layout(push_constant) uniform SunShadowPush { mat4 light_from_world; } push;

void main() {
    gl_Position = push.light_from_world * vec4(in_position, 1.0);
}
