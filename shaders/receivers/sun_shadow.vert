#version 450
// The receiver meshes' depth seen along a beam (passes/receivers/sun_shadow.hpp): world space to the
// orthographic light space of one half of the map, pushed as one matrix with the half's clip
// height, which the fragment stage applies; a cutout's coverage needs the base colour's texture
// coordinates and the vertex colour's alpha too.
layout(location = 0) in vec3 in_position;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 0) out float out_height;
layout(location = 1) out vec2 out_uv;
layout(location = 2) out float out_alpha;
layout(push_constant) uniform SunShadowPush {
    mat4 light_from_world;
    vec4 clip;      // x: meshes above this height cast nothing in this half
    vec4 material;  // x: the base colour factor's alpha, y: a cutout's threshold (negative: opaque)
} push;

void main() {
    out_height = in_position.y;
    out_uv = in_uv;
    out_alpha = in_color.a;
    gl_Position = push.light_from_world * vec4(in_position, 1.0);
}
