// The embedded frame's last pass (include/vkwater/): the frame's HDR colour written into a host
// engine's colour target, depth-tested against the host's depth target, so that what the host drew
// nearer than vkwater's surfaces stays and the rest shows vkwater's frame. Both targets are
// imported (the host owns them); the graph derives the barriers from the states the host states
// they are in before and wants them in after.
//
// Depth is reverse Z, as vkwater's own scene depth (passes/common/scene_depth.hpp): 0 is the far
// plane, the test keeps a fragment whose depth is greater than or equal to the host's, and the
// host's depth target is left holding the nearer of the two (so its later passes can test
// against the water too). Where vkwater draws nothing but sky its depth is 0: the host's cleared
// pixels (0) take the sky, the ones it drew keep their colour.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

inline constexpr const char* kHostCompositePass = "host composite";

// `scene_depth`: the frame's scene depth (every frame draws the water into it). Returns the host colour target's version this pass writes (request it as the frame's output).
fg::ImageHandle add_host_composite_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, fg::ImageHandle scene_depth,
                                        fg::ImageHandle host_color, fg::ImageHandle host_depth);

}  // namespace vkw::passes
