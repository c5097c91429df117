// A transient buffer filled with zeros by a transfer pass: the start of every accumulation
// that adds into a buffer with atomics (the caustic flux, the godray radiance pyramid).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <optional>
#include <string>

namespace vkw::passes {

// Creates `buffer_name` (bytes long) and zeroes its first `zeroed_bytes` (a multiple of 4, or
// VK_WHOLE_SIZE: all of it) in the pass `pass_name`, which serves `effect` when given; returns the
// buffer. A buffer allocated at its bound but used only in part this frame zeroes only that part.
fg::BufferHandle add_zeroed_buffer_pass(fg::FrameGraph& graph, const std::string& pass_name,
                                        const std::string& buffer_name, VkDeviceSize bytes,
                                        std::optional<fg::EffectTag> effect = std::nullopt,
                                        VkDeviceSize zeroed_bytes = VK_WHOLE_SIZE);

}  // namespace vkw::passes
