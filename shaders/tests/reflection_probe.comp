#version 450
// Not a pass: one resource of each kind the SPIR-V reflection maps to a descriptor type
// (engine/vk/spirv_reflection.hpp), for its tests (tests/vk). Each is read, so each counts as
// used, except `never_read`. Variant other_set (VKWATER_PROBE_OTHER_SET) also reads set 1, which
// no Pipeline layout has.
layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std140) uniform Constants { vec4 scale; } constants;
layout(set = 0, binding = 1, std430) buffer Values { float values[]; };
layout(set = 0, binding = 2) uniform sampler2D textures[3];
layout(set = 0, binding = 3) uniform texture2D separate_texture;
layout(set = 0, binding = 4) uniform sampler separate_sampler;
layout(set = 0, binding = 5, r32f) uniform readonly image2D storage;
layout(set = 0, binding = 6) uniform samplerBuffer texels;
layout(set = 0, binding = 7, r32f) uniform readonly imageBuffer storage_texels;
layout(set = 0, binding = 8) uniform sampler2D never_read;
#ifdef VKWATER_PROBE_OTHER_SET
layout(set = 1, binding = 0, std430) readonly buffer Other { float other[]; };
#endif

// std430 offsets 0 and 16: the block ends at 20 bytes (a C++ struct with alignas(16) would be 32).
layout(push_constant) uniform Push { vec4 offset; float gain; } pc;

void main() {
    float sum = constants.scale.x + pc.offset.x * pc.gain;
    for (int i = 0; i < 3; ++i) sum += textureLod(textures[i], vec2(0.5), 0.0).r;
    sum += textureLod(sampler2D(separate_texture, separate_sampler), vec2(0.5), 0.0).r;
    sum += imageLoad(storage, ivec2(0)).r;
    sum += texelFetch(texels, 0).r;
    sum += imageLoad(storage_texels, 0).r;
#ifdef VKWATER_PROBE_OTHER_SET
    sum += other[0];
#endif
    values[0] = sum;
}
