#version 450
// The box's flat colour with simple N.L shading, so that its faces can be told apart.

layout(push_constant) uniform Box {
    mat4 model_view_projection;
    vec4 color;
} box;

layout(location = 0) flat in vec3 normal;
layout(location = 0) out vec4 color;

void main() {
    const vec3 to_light = normalize(vec3(0.3, 1.0, 0.5));  // from high up, roughly as the scenes' sun
    const float shade = 0.3 + 0.7 * max(dot(normal, to_light), 0.0);
    color = vec4(box.color.rgb * shade, 1.0);
}
