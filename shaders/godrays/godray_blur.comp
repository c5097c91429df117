#version 460
// One direction of the godray blur (passes/godrays/godrays_blur.hpp): binomial weights 1 4 6 4 1 / 16
// (variance 1 pixel^2), each tap kept only where the scene lies at the centre's distance within 5%
// (so the blur never carries light across a depth edge), renormalised over the kept taps: a field
// that is linear across the kept taps passes unchanged.
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1) uniform sampler2D source;
layout(set = 0, binding = 2) uniform sampler2D view_depth;  // r: the distance to the scene
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D target;

layout(push_constant) uniform Push {
    ivec2 step;  // (1, 0) or (0, 1)
} pc;

const float kWeights[5] = float[](1.0, 4.0, 6.0, 4.0, 1.0);
const float kSameSurface = 0.05;  // relative distance difference of taps on one surface

void main() {
    const ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(target);
    if (any(greaterThanEqual(g, size))) return;
    const float centre = texelFetch(view_depth, g, 0).r;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int k = -2; k <= 2; ++k) {
        const ivec2 tap = g + k * pc.step;
        if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, size))) continue;
        const float d = texelFetch(view_depth, tap, 0).r;
        if (abs(d - centre) > kSameSurface * max(d, centre)) continue;
        sum += kWeights[k + 2] * texelFetch(source, tap, 0).rgb;
        weight += kWeights[k + 2];
    }
    imageStore(target, g, vec4(sum / weight, 1.0));  // the centre tap always counts: weight >= 6
}
