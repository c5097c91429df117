// Complex numbers as vec2 (x: real part, y: imaginary part), for the FFT ocean's spectra
// and transforms.
#ifndef VKWATER_WATER_COMPLEX_GLSL
#define VKWATER_WATER_COMPLEX_GLSL

const float kPi = 3.14159265358979;

vec2 complex_mul(vec2 a, vec2 b) {
    return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

vec2 complex_conj(vec2 a) { return vec2(a.x, -a.y); }

// i a: a rotated by a quarter turn (exact, no rounding).
vec2 complex_times_i(vec2 a) { return vec2(-a.y, a.x); }

// Two complex numbers in one vec4 (xy and zw), transformed alike: the FFT ocean moves its
// fields in pairs, which halves its memory accesses.
vec4 complex_pair_mul(vec4 pair, vec2 w) { return vec4(complex_mul(pair.xy, w), complex_mul(pair.zw, w)); }
vec4 complex_pair_times_i(vec4 pair) { return vec4(-pair.y, pair.x, -pair.w, pair.z); }

// exp(i angle). The angle is first brought into [-pi, pi]: the Vulkan precision rules bound
// sin and cos only there, and the FFT ocean's w t grows without limit with the time. The
// reduction costs one rounding of the angle's size, ulp(|angle|), which a phase carries
// anyway in fp32.
vec2 complex_exp_i(float angle) {
    const float turns = round(angle * (0.5 / kPi));
    const float reduced = angle - turns * (2.0 * kPi);
    return vec2(cos(reduced), sin(reduced));
}

#endif
