// The window's hand-off of a frame: the frame's HDR colour copied into an image the window
// owns (imported, so it outlives this frame graph), where the window's present graph samples
// it for display and a screenshot reads it back. The copy overwrites the whole image, so it
// enters each frame UNDEFINED; the frame before it is ordered by the window's submissions
// (passes/present/present_*.cpp are the window's; passes/present/present_graph.cpp imports the image
// in the state this pass leaves it in).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// `target`: R32G32B32A32_SFLOAT of the HDR colour's size, with TRANSFER_DST and SAMPLED usage.
void add_present_handoff_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, const fg::ImportedImage& target);

// The state the hand-off leaves its target in: sampled by a fragment shader.
fg::AccessState present_handoff_final_state();

}  // namespace vkw::passes
