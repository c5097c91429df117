// A transient buffer filled with zeros by a transfer pass: the start of every accumulation
// that adds into a buffer with atomics (the caustic flux, the godray radiance pyramid).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <optional>
#include <string>

namespace vkw::passes {

// Creates `buffer_name` (bytes long) and zeroes it in the pass `pass_name`, which serves
// `effect` when given; returns the zeroed buffer.
fg::BufferHandle add_zeroed_buffer_pass(fg::FrameGraph& graph, const std::string& pass_name,
                                        const std::string& buffer_name, VkDeviceSize bytes,
                                        std::optional<fg::EffectTag> effect = std::nullopt);

}  // namespace vkw::passes
