#version 450
// The calibration pass (passes/common/calibration.hpp): a constant written to every pixel, the
// cheapest full-screen work there is. Frame and pass times are reported in units of it.
layout(location = 0) out vec4 out_value;

void main() { out_value = vec4(0.5, 0.25, 0.125, 1.0); }
