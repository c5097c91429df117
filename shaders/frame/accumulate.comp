#version 450
// One sub-frame of a box-filtered frame into the running sum (passes/frame/accumulate.hpp): the
// first sub-frame replaces the sum, each later one adds to it, and the last one's sum is scaled by
// 1 / k^2. These are the fp32 operations, in the order, that vkwater render's average takes on the
// CPU (passes/frame/supersampled_frame.cpp), so the window shows the same image.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba32f) uniform readonly image2D sub_frame;
layout(binding = 1, rgba32f) uniform image2D sum;

// Its C++ type (AccumulatePush in passes/frame/accumulate.cpp) is generated from this shader.
layout(push_constant) uniform Push {
    uint first;   // 1: the sum starts with this sub-frame
    uint last;    // 1: scale the sum by `scale`
    float scale;  // 1 / k^2
} push;

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(sum)))) return;
    vec4 value = imageLoad(sub_frame, pixel);
    if (push.first == 0u) value = imageLoad(sum, pixel) + value;
    if (push.last != 0u) value *= push.scale;
    imageStore(sum, pixel, value);
}
