#version 450
// Not a pass: a block no generated C++ mirror can match (a std140 mat3's columns are 16 bytes
// apart, glm::mat3's 12), which tools/shader_structs must refuse, naming the shader, the block and
// the member (tests/shader_structs).
layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std140) uniform Refused {
    vec4 first;
    mat3 basis;
} refused;

layout(set = 0, binding = 1, std430) writeonly buffer Values { float values[]; };

void main() { values[0] = refused.first.x + refused.basis[1].y; }
