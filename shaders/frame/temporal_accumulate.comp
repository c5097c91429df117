#version 450
// Temporal accumulation (passes/frame/temporal_accumulation.hpp): this frame's colour, rendered
// with the camera's image plane shifted by a sub-pixel jitter, blended into the accumulated colour
// of the frames before it. The history is read where this pixel's surface point was in the
// previous frame's (unjittered) image, through the scene depth, and clamped to the range of this
// frame's 3 x 3 neighbourhood, so that a history the scene no longer shows (moving caustics, a
// moved camera's disocclusions) fades within a frame instead of ghosting.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba32f) uniform readonly image2D current;
layout(binding = 1) uniform sampler2D scene_depth;  // D32, reversed Z, nearest: read at this pixel's centre
layout(binding = 2, rgba32f) uniform readonly image2D history;
layout(binding = 3, rgba32f) uniform writeonly image2D accumulated;

// Its C++ type is generated from this shader (tools/shader_structs).
layout(push_constant) uniform Push {
    mat4 reprojection;  // this frame's unjittered clip space -> the previous frame's
    float blend;        // this frame's weight: 1 / (frames accumulated + 1), at least blend_floor
    uint first;         // 1: no history (the first frame, or a reset): the frame as it is
    uint clamp_history;  // 1: clamp the history to the neighbourhood (0 only in tests: the plain running mean)
    uint still;          // 1: the camera has not moved: each pixel's history is its own (no resampling)
} push;

vec3 history_texel(ivec2 texel, ivec2 size) { return imageLoad(history, clamp(texel, ivec2(0), size - 1)).rgb; }

// The history bilinearly at `position` (pixels, texel centres at + 0.5).
vec3 history_at(vec2 position, ivec2 size) {
    const vec2 p = position - 0.5;
    const ivec2 corner = ivec2(floor(p));
    const vec2 f = p - vec2(corner);
    const vec3 top = mix(history_texel(corner, size), history_texel(corner + ivec2(1, 0), size), f.x);
    const vec3 bottom = mix(history_texel(corner + ivec2(0, 1), size), history_texel(corner + ivec2(1, 1), size), f.x);
    return mix(top, bottom, f.y);
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(accumulated);
    if (any(greaterThanEqual(pixel, size))) return;
    const vec4 colour = imageLoad(current, pixel);
    if (push.first != 0u) {
        imageStore(accumulated, pixel, colour);
        return;
    }
    vec3 past;
    if (push.still != 0u) {
        past = imageLoad(history, pixel).rgb;
    } else {
        // Where this pixel's surface point lay in the previous frame: NDC y is up, image rows go down
        // (the frame graph flips the viewport).
        const vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
        const float depth = texture(scene_depth, uv).r;
        const vec4 previous = push.reprojection * vec4(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y, depth, 1.0);
        const vec2 previous_uv = vec2(0.5 * (previous.x / previous.w) + 0.5, 0.5 - 0.5 * (previous.y / previous.w));
        if (!(previous.w > 0.0) || any(lessThan(previous_uv, vec2(0.0))) ||
            any(greaterThan(previous_uv, vec2(1.0)))) {
            imageStore(accumulated, pixel, colour);  // off the previous image: nothing to accumulate
            return;
        }
        past = history_at(previous_uv * vec2(size), size);
    }
    if (push.clamp_history != 0u) {
        // The neighbourhood's range, narrowed to its mean +- VARIANCE_CLIP standard deviations
        // (Salvi's variance clipping): a caustic's bright line beside dark water widens the range
        // to nearly all of it, while the mean and spread follow what this frame shows there.
        const float VARIANCE_CLIP = 1.25;
        vec3 lowest = colour.rgb, highest = colour.rgb, sum = vec3(0.0), sum_squares = vec3(0.0);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const vec3 near = imageLoad(current, clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1)).rgb;
                lowest = min(lowest, near);
                highest = max(highest, near);
                sum += near;
                sum_squares += near * near;
            }
        }
        const vec3 mean = sum / 9.0;
        const vec3 spread = VARIANCE_CLIP * sqrt(max(sum_squares / 9.0 - mean * mean, vec3(0.0)));
        // (The mean can round an ulp past the range: the lower end is kept at most the upper.)
        const vec3 upper = min(highest, mean + spread);
        past = clamp(past, min(max(lowest, mean - spread), upper), upper);
    }
    imageStore(accumulated, pixel, vec4(past + (colour.rgb - past) * push.blend, colour.a));
}
