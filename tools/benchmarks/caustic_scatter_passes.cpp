// The scatter-only benchmark passes (caustic_scatter_passes.hpp).
#include "tools/benchmarks/caustic_scatter_passes.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/common/zeroed_buffer.hpp"

#include <algorithm>

namespace vkwbench {
namespace {

using namespace vkw;

}  // namespace

ScatterPush scatter_push(uint32_t resolution, const passes::CausticMapFrame& frame) {
    const uint32_t requested = resolution + 2;
    return {resolution, frame.width, frame.height, (frame.width - std::min(frame.width, requested)) / 2,
            (frame.height - std::min(frame.height, requested)) / 2};
}

std::string scatter_pass_name(ScatterKind kind) {
    switch (kind) {
        case ScatterKind::FixedPoint64: return "scatter int64 fixed point";
        case ScatterKind::FixedPoint64Tile: return "scatter int64 workgroup tile";
        case ScatterKind::FloatCas32: return "scatter float32 CAS";
    }
    return "scatter";
}

VkDeviceSize scatter_target_bytes(ScatterKind kind, const passes::CausticMapFrame& frame) {
    // The fixed-point targets are the photon pass's flux buffer (header, then three uint64 per
    // texel); the float one holds three floats per texel.
    const VkDeviceSize texels = VkDeviceSize{frame.width} * frame.height;
    return kind == ScatterKind::FloatCas32 ? texels * 3 * sizeof(float)
                                           : passes::kCausticFluxHeaderBytes + texels * passes::kCausticTexelBytes;
}

fg::BufferHandle add_caustic_scatter_pass(fg::FrameGraph& graph, ScatterKind kind, uint32_t resolution,
                                          const passes::CausticMapFrame& frame) {
    const VkDeviceSize header = kind == ScatterKind::FloatCas32 ? 0 : passes::kCausticFluxHeaderBytes;
    const VkDeviceSize bytes = scatter_target_bytes(kind, frame);
    const std::string name = scatter_pass_name(kind);
    const fg::BufferHandle cleared = passes::add_zeroed_buffer_pass(graph, name + " clear", name + " target", bytes);

    const ScatterPush push = scatter_push(resolution, frame);
    struct Data {
        fg::BufferHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) { d.target = builder.read_write_storage("Flux", cleared); },
        [push, kind, header, bytes, name](const Data& d, fg::PassContext& context) {
            const VkDeviceSize range = bytes - header;
            if (range > context.context().properties().limits.maxStorageBufferRange) {
                throw InternalError(name + ": a map of " + std::to_string(push.width) + " x " +
                                    std::to_string(push.height) + " texels exceeds one storage-buffer binding");
            }
            if (kind == ScatterKind::FixedPoint64Tile && !context.context().features().shared_int64_atomics) {
                throw InternalError(name + ": the device has no shared-memory int64 atomics");
            }
            ComputePipelineDesc desc;
            desc.shader = kind == ScatterKind::FixedPoint64       ? "caustics/bench/caustic_scatter_fixed.comp"
                          : kind == ScatterKind::FixedPoint64Tile ? "caustics/bench/caustic_scatter_tile.comp"
                                                                  : "caustics/bench/caustic_scatter_float_cas.comp";
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
            desc.layout.push_constant_bytes = sizeof(ScatterPush);
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            context.bind(pipeline, {context.storage_buffer("Flux", d.target, header, range)});
            context.push_constants(pipeline, push);
            const uint32_t groups = (push.resolution + kScatterGroupSide - 1) / kScatterGroupSide;
            vkCmdDispatch(context.cmd(), groups, groups, 1);
        });
    graph.request_output(data.target);
    return data.target;
}

}  // namespace vkwbench
