#version 450
#extension GL_GOOGLE_include_directive : require
// Unnormalised inverse DFT of n-point lines in shared memory:
//   out[j] = sum over m of in[m] exp(+2 pi i m j / n),  n a power of two in [16, 1024],
// of two complex numbers at once: each element is a vec4 holding two (xy and zw),
// transformed independently with the same twiddles (complex.glsl's pairs).
// like engine/water/fft.cpp: bit-reversed load, then log2(n) radix-2 butterfly stages
// (decimation in time, taken two at a time) with twiddles from exact angles. The lines are the rows
// (element_stride 1, line_stride n) or the columns (element_stride n, line_stride 1) of the
// n x n grids stored one after another, line g = grid * n + line; rows then columns is the
// 2D transform, as on the CPU. A work group takes 1024 / n consecutive lines, so that every
// group holds 1024 points: fewer, fuller groups and fewer barriers in all (on lavapipe each
// barrier switches every invocation's coroutine, and that cost dominated one-line groups).
// In place: a group reads all its lines into shared memory before it writes any back, and no
// two groups share a line.
#include "water/complex.glsl"

const uint kGroupSize = 64;     // invocations; each does 1024 / 4 / 64 = 4 stage pairs per step
const uint kMaxPoints = 1024;   // 16 KiB of shared memory for the lines, 4 KiB for twiddles
const uint kLog2MaxPoints = 10;

layout(local_size_x = kGroupSize) in;

layout(set = 0, binding = 0, std430) buffer Grids { vec4 data[]; };
layout(push_constant) uniform Params {
    uint n;
    uint log2n;
    uint element_stride;
    uint line_stride;
    uint line_count;  // grids * n
} params;

shared vec4 lines[kMaxPoints];
// exp(+2 pi i j / n) for j < n / 2, each from its own angle pi (j / (n / 2)) as on the CPU;
// made once per group here rather than once per butterfly.
shared vec2 twiddles[kMaxPoints / 2];

// Element `e` of the group's lines: the line within the group and the point within the line.
// Consecutive invocations take consecutive addresses: along a line for rows, across lines
// for columns.
void locate(uint e, out uint line, out uint point) {
    const uint log2_lines = kLog2MaxPoints - params.log2n;
    if (params.element_stride == 1) {
        line = e >> params.log2n;
        point = e & (params.n - 1);
    } else {
        line = e & ((1u << log2_lines) - 1);
        point = e >> log2_lines;
    }
}

// The address of `point` of the group's line `line`, or false past the last line.
bool address(uint line, uint point, out uint index) {
    const uint g = gl_WorkGroupID.x * (kMaxPoints >> params.log2n) + line;
    const uint grid = g >> params.log2n, within = g & (params.n - 1);
    index = grid * params.n * params.n + within * params.line_stride + point * params.element_stride;
    return g < params.line_count;
}

// Stages h and 2h at once on the four points offset + {0, 1, 2, 3} h of one 4h-block:
// half the shared-memory traffic and barriers of single stages (on lavapipe every shared
// access with a per-invocation index costs a per-lane loop). Stage h pairs (0, 1) and
// (2, 3) with twiddle exp(2 pi i offset / 2h); stage 2h pairs (0, 2) with
// w = exp(2 pi i offset / 4h) and (1, 3) with exp(2 pi i (offset + h) / 4h) = i w.
void radix2_stage_pair(uint j, uint h) {
    const uint log2_quarter = params.log2n - 2;
    const uint q = j & ((1u << log2_quarter) - 1);  // the quad within its line
    const uint offset = q & (h - 1);
    const uint i0 = (j >> log2_quarter) * params.n + 4 * (q - offset) + offset;
    // Table entries offset n / 2h and offset n / 4h: the same fp32 angles as computing
    // pi (offset / h) and pi (offset / 2h) directly, the quotients of powers of two being exact.
    const vec2 w_half = twiddles[offset * (params.n / (2 * h))];
    const vec2 w = twiddles[offset * (params.n / (4 * h))];
    const vec4 x0 = lines[i0], x1 = lines[i0 + h], x2 = lines[i0 + 2 * h], x3 = lines[i0 + 3 * h];
    const vec4 a1 = complex_pair_mul(x1, w_half), a3 = complex_pair_mul(x3, w_half);
    const vec4 b0 = x0 + a1, b1 = x0 - a1, b2 = x2 + a3, b3 = x2 - a3;
    const vec4 c2 = complex_pair_mul(b2, w), c3 = complex_pair_times_i(complex_pair_mul(b3, w));
    lines[i0] = b0 + c2;
    lines[i0 + h] = b1 + c3;
    lines[i0 + 2 * h] = b0 - c2;
    lines[i0 + 3 * h] = b1 - c3;
}

void main() {
    const uint n = params.n;
    const uint t = gl_LocalInvocationID.x;
    for (uint e = t; e < kMaxPoints; e += kGroupSize) {
        uint line, point, index;
        locate(e, line, point);
        if (address(line, point, index)) {
            lines[line * n + (bitfieldReverse(point) >> (32 - params.log2n))] = data[index];
        }
    }
    for (uint j = t; j < n / 2; j += kGroupSize) {
        twiddles[j] = complex_exp_i(kPi * (float(j) / float(n / 2)));
    }
    barrier();
    uint h = 1;  // the half length of the next radix-2 stage
    if ((params.log2n & 1) != 0) {
        // An odd number of stages: the first alone. Its twiddle is exp(0) = 1.
        for (uint j = t; j < kMaxPoints / 2; j += kGroupSize) {
            const vec4 e = lines[2 * j], o = lines[2 * j + 1];
            lines[2 * j] = e + o;
            lines[2 * j + 1] = e - o;
        }
        barrier();
        h = 2;
    }
    for (; h < n; h *= 4) {
        for (uint j = t; j < kMaxPoints / 4; j += kGroupSize) {
            radix2_stage_pair(j, h);
        }
        barrier();
    }
    for (uint e = t; e < kMaxPoints; e += kGroupSize) {
        uint line, point, index;
        locate(e, line, point);
        if (address(line, point, index)) data[index] = lines[line * n + point];
    }
}
