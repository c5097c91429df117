// The memory of one frame: the transient heap the executor allocated plus each imported
// resource once (definitions in frame_memory.hpp).
#include "tools/benchmarks/frame_memory.hpp"

#include "engine/framegraph/executor.hpp"
#include "engine/vk/resources.hpp"
#include "passes/present/readback.hpp"

#include <set>

namespace vkw::bench {
namespace {

// RGBA32F, as the renderer reads the HDR colour back.
VkDeviceSize readback_bytes(const RenderOptions& options) {
    return VkDeviceSize{options.width} * options.height * 4 * sizeof(float);
}

// Imported resources of the passes that run, each VkBuffer or VkImage counted once (the
// receiver meshes are imported by every pass that draws them).
uint64_t imported_bytes(const fg::FrameGraph& graph) {
    const fg::CompiledGraph& compiled = graph.compiled();
    std::set<uint64_t> counted;
    uint64_t bytes = 0;
    for (uint32_t r = 0; r < graph.resources().size(); ++r) {
        const fg::ResourceDecl& decl = graph.resources()[r];
        if (!decl.imported || !compiled.resource_live[r]) continue;
        if (decl.is_image) {
            const fg::ImportedImage& image = decl.imported_image;
            if (!counted.insert(reinterpret_cast<uint64_t>(image.image)).second) continue;
            bytes += uint64_t{image.width} * image.height * format_texel_bytes(image.format);
        } else {
            const fg::ImportedBuffer& buffer = decl.imported_buffer;
            if (!counted.insert(reinterpret_cast<uint64_t>(buffer.buffer)).second) continue;
            bytes += buffer.size;
        }
    }
    return bytes;
}

}  // namespace

FrameMemory measure_frame_memory(Renderer& renderer, const Scene& scene, const RenderOptions& options) {
    // The same passes as render()'s frame, ending in a readback declared with its size but no
    // buffer (never recorded: this frame is only compiled and its transients allocated), as
    // `vkwater passes` declares it.
    const FrameOutput same_as_render{[&](fg::FrameGraph& graph, fg::ImageHandle hdr) {
        passes::add_readback_pass(graph, hdr, VK_NULL_HANDLE, readback_bytes(options));
    }};
    fg::FrameExecutor& executor = renderer.prepare_frame(scene, options, same_as_render);
    return {executor.transient_heap_bytes(), imported_bytes(executor.graph())};
}

}  // namespace vkw::bench
