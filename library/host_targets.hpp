// A host's targets (vkwater::Frame) checked against what the embedded frame can draw into, and
// turned into the frame graph's imported images. Every refusal is a vkw::UserError naming the
// target, the value and what is accepted.
#pragma once

#include <vkwater/world.hpp>
#include "engine/framegraph/frame_graph.hpp"

#include <optional>

namespace vkw {
class Context;
}

namespace vkwater::detail {

struct HostTargets {
    vkw::fg::ImportedImage color;
    vkw::fg::ImportedImage depth;
    std::optional<vkw::fg::ImportedImage> caustic_layer;
};

HostTargets check_host_targets(const vkw::Context& context, const Frame& frame);

}  // namespace vkwater::detail
