#include "engine/render/renderer.hpp"

#include "engine/core/errors.hpp"
#include "engine/render/blackboard_keys.hpp"
#include "engine/render/frame_constants.hpp"
#include "engine/render/frame_needs.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/resources.hpp"
#include "passes/floor.hpp"
#include "passes/frame_constants_upload.hpp"
#include "passes/readback.hpp"
#include "passes/sky.hpp"

#include <cstring>

namespace vkw {

namespace {
VkDeviceSize hdr_bytes(uint32_t width, uint32_t height) { return VkDeviceSize{width} * height * 4 * sizeof(float); }
}  // namespace

void build_frame_graph(fg::FrameGraph& graph, const Scene& scene, uint32_t width, uint32_t height,
                       VkBuffer readback) {
    passes::add_frame_constants_upload(graph, make_frame_constants(scene, width, height));
    passes::add_sky_pass(graph);
    passes::add_floor_pass(graph);
    passes::add_readback_pass(graph, graph.blackboard().get(keys::kHdrColor), readback, hdr_bytes(width, height));
}

RenderResult Renderer::render(const Scene& scene, const RenderOptions& options) {
    const uint32_t max_size = context_.properties().limits.maxImageDimension2D;
    if (options.width == 0 || options.height == 0 || options.width > max_size || options.height > max_size) {
        throw UserError("--width/--height: " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                        " is out of range (accepted: 1 to " + std::to_string(max_size) + " on '" +
                        context_.device_name() + "')");
    }
    Buffer readback(context_,
                    {hdr_bytes(options.width, options.height), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
                    "HDR readback");
    fg::FrameGraph graph(decide_frame_needs(scene));
    graph.set_default_recording(options.recording);
    build_frame_graph(graph, scene, options.width, options.height, readback.handle());
    graph.compile(options.width, options.height);

    fg::FrameExecutor executor(context_, graph, pipelines_, {options.check_finite, options.timing});
    RenderResult result;
    result.timing = executor.execute();

    result.image.width = static_cast<int>(options.width);
    result.image.height = static_cast<int>(options.height);
    result.image.rgba.resize(size_t{options.width} * options.height * 4);
    std::memcpy(result.image.rgba.data(), readback.mapped(), result.image.rgba.size() * sizeof(float));
    return result;
}

}  // namespace vkw
