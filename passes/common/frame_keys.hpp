// The blackboard keys of the frame's shared targets: the constants every pass reads, and the HDR
// colour and scene depth that each drawing pass takes from the pass before it and hands on.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/handles.hpp"

namespace vkw::keys {

inline constexpr fg::BlackboardKey<fg::BufferHandle> kFrameConstants{"frame constants"};
inline constexpr fg::BlackboardKey<fg::ImageHandle> kHdrColor{"HDR colour"};
inline constexpr fg::BlackboardKey<fg::ImageHandle> kSceneDepth{"scene depth"};

}  // namespace vkw::keys
