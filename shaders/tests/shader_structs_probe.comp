#version 450
// Not a pass: the blocks whose generated C++ mirrors (tools/shader_structs) tests/shader_structs
// checks against offsets derived by hand from the std430 and std140 rules. Each block mixes the
// cases a mirror can get wrong: a vec3's tail taken by a float, padding before a 16-byte aligned
// member, a bool (a uint in a block), a 64-bit member, a std140 float array (stride 16), a nested
// struct and an array of it whose stride exceeds the struct, a C++ keyword as a member name.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
layout(local_size_x = 1) in;

// std430 (the push block's): vec3 at 0, the float in its tail at 12; 16 bytes, aligned to 16.
struct Inner {
    vec3 normal;
    float bias;
};

// std140: vec3 at 0, float at 12, vec2 at 16; 24 bytes declared, aligned to 16, so an array of it
// has stride 32 and the member after it starts at a multiple of 16.
struct Light {
    vec3 colour;
    float power;
    vec2 offset;
};

// Declared before Probe but bound after it: the header orders blocks by binding.
layout(set = 0, binding = 3, std140) uniform Scale { vec4 factor; } scale;

layout(set = 0, binding = 1, std140) uniform Probe {
    mat4 transform;
    vec3 position;
    float radius;
    float samples[4];
    bool enabled;
    int mode;
    uvec2 ids;
    Light lights[2];
    Light sun;
    float tail;
} probe;

layout(set = 0, binding = 0, std430) writeonly buffer Values { float values[]; };

layout(push_constant) uniform Push {
    uint count;
    int delta;
    bool flag;
    vec3 direction;
    float range;
    vec2 uv;
    uint64_t key;
    float weights[3];
    Inner inner;
    ivec2 texel;
    uint new;
    float last;
} pc;

void main() {
    values[0] = pc.range + float(pc.key) + pc.inner.bias + probe.radius + probe.samples[1] + probe.lights[1].power +
                probe.sun.offset.y + probe.tail + scale.factor.x;
}
