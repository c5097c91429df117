#version 450
// The host's own geometry: a unit cube (corners at +-0.5) made from gl_VertexIndex alone, 6 faces of
// 2 triangles (36 vertices), so that the sample needs no vertex buffer.

layout(push_constant) uniform Box {
    mat4 model_view_projection;  // vkwater's projection * view (World::matrices) * the box's model
    vec4 color;                  // linear radiance, as vkwater writes
} box;

// The face's normal; the model only scales uniformly and translates, so it is also the world's.
layout(location = 0) flat out vec3 normal;

const vec3 kNormals[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1),
                                vec3(0, 0, -1));
// The face's two triangles in its own (u, v) square.
const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    const vec3 n = kNormals[gl_VertexIndex / 6];
    // Two axes perpendicular to n (and to each other): n's components rotated.
    const vec3 u = n.yzx;
    const vec3 v = n.zxy;
    const vec2 corner = kCorners[gl_VertexIndex % 6];
    normal = n;
    gl_Position = box.model_view_projection * vec4(0.5 * (n + corner.x * u + corner.y * v), 1.0);
}
