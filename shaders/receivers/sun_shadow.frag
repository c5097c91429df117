#version 450
// Depth only: keeps the parts of the meshes under the half's clip height (the beam half of
// passes/receivers/sun_shadow.hpp holds only what lies under the water; the sun half keeps everything).
layout(location = 0) in float in_height;
layout(push_constant) uniform SunShadowPush {
    mat4 light_from_world;
    vec4 clip;
} push;

void main() {
    if (in_height > push.clip.x) discard;
}
