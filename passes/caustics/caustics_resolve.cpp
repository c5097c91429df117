// add_caustic_resolve_pass (caustics_resolve.hpp).
#include "passes/caustics/caustics_resolve.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_map_frame.hpp"

namespace vkw::passes {
namespace {

constexpr uint32_t kGroupSide = 8;  // local_size of caustic_resolve.comp

// Mirrors the push constants of shaders/caustics/caustic_resolve.comp.
struct ResolvePush {
    float factor[4];
    uint32_t width, band_first, band_rows, pad;
};

}  // namespace

CausticMap add_caustic_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle flux, const CausticInputs& inputs) {
    const CausticMapFrame frame = fit_caustic_map(inputs);
    ResolvePush push{};
    for (int c = 0; c < 3; ++c) push.factor[c] = float(frame.lsb[c] / frame.texel_area);
    push.width = frame.width;
    const fg::BufferHandle frame_buffer = add_caustic_map_frame_pass(graph, inputs);

    struct Data {
        fg::BufferHandle flux;
        fg::ImageHandle irradiance;
    };
    const uint32_t height = frame.height;
    const auto& data = graph.add_pass<Data>(
        "caustic resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.flux = builder.read_storage(flux, stage);
            d.irradiance =
                builder.write_storage(builder.create_image("caustic irradiance", caustic_map_image(frame)), stage);
        },
        [push, height](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "caustics/caustic_resolve.comp";
            const Pipeline& pipeline = context.pipeline("caustic resolve", desc);
            const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
            // Bands of at most 65535 groups of 8 rows, each within one binding.
            const auto bands =
                row_bands(height, VkDeviceSize{push.width} * kCausticTexelBytes, kCausticFluxHeaderBytes, 0,
                          limits.maxStorageBufferRange, limits.minStorageBufferOffsetAlignment, 65535 * kGroupSide);
            for (const RowBand& band : bands) {
                fg::DescriptorBinding in = context.storage_buffer(0, d.flux);
                in.buffer.offset = band.offset;
                in.buffer.range = band.bytes;
                ResolvePush p = push;
                p.band_first = band.first;
                p.band_rows = band.rows;
                context.bind(pipeline, {in, context.storage_image(1, d.irradiance)});
                context.push_constants(pipeline, p);
                vkCmdDispatch(context.cmd(), (push.width + kGroupSide - 1) / kGroupSide,
                              (band.rows + kGroupSide - 1) / kGroupSide, 1);
            }
        });
    return {data.irradiance, frame_buffer};
}

}  // namespace vkw::passes
