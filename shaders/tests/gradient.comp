#version 450
// Frame-graph test: writes a known pattern into a storage image,
// value(x, y) = (x, y, x + y, 1) as floats.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D target;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(target)))) return;
    imageStore(target, texel, vec4(texel.x, texel.y, texel.x + texel.y, 1.0));
}
