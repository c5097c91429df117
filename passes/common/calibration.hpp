// The calibration pass: a constant fragment shader writing all W x H pixels of a target of the
// frame's HDR format, with no depth or stencil test, never culled. It is the unit of the frame
// and pass times in docs/performance.md (tools/benchmarks/frame_ratio.sh): the same frame's
// passes divided by it cancel most of the speed of the machine they ran on, which moves by 2x on
// a shared machine. The renderer records it in every timed frame; its target feeds nothing.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

inline constexpr const char* kCalibrationPassName = "calibration";

void add_calibration_pass(fg::FrameGraph& graph);

}  // namespace vkw::passes
