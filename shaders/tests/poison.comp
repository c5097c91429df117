#version 450
// Frame-graph test: fills a storage image with 1.0 except one texel, which gets a
// NaN (or +Inf), so the finite check must name this pass, the image and that texel.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D target;
layout(push_constant) uniform Params { ivec2 bad_texel; uint bad_channel; uint use_infinity; } params;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(target)))) return;
    vec4 value = vec4(1.0);
    if (texel == params.bad_texel) {
        value[params.bad_channel] = uintBitsToFloat(params.use_infinity != 0u ? 0x7f800000u : 0x7fc00000u);
    }
    imageStore(target, texel, value);
}
