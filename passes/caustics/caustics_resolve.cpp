// add_caustic_resolve_pass (caustics_resolve.hpp).
#include "passes/caustics/caustics_resolve.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_map_frame.hpp"

#include <shader_structs/caustics/caustic_resolve.comp.hpp>

#include <cmath>
#include <string>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/caustics/caustic_resolve.comp, generated from its SPIR-V (tools/shader_structs).
using ResolvePush = glsl::caustic_resolve_comp::Push;

}  // namespace

CausticMap add_caustic_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle flux, const CausticInputs& inputs) {
    const CausticMapFrame frame = fit_caustic_map(inputs);
    ResolvePush push{};
    for (int c = 0; c < 3; ++c) push.factor[c] = float(frame.lsb[c] / frame.texel_area);
    // The held texels alone (CausticMapFrame::held): the map's others stay undefined, unread.
    const CausticTexelRect held = frame.held;
    push.width = held.width();
    push.first_column = held.x0;
    const fg::BufferHandle frame_buffer = add_caustic_map_frame_pass(graph, inputs);

    struct Data {
        fg::BufferHandle flux;
        fg::ImageHandle irradiance;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            d.flux = builder.read_storage("Flux", flux);
            d.irradiance = builder.write_storage("irradiance",
                                                 builder.create_image("caustic irradiance", caustic_map_image(frame)));
            if (frame.holds_part()) {
                builder.defines_only(d.irradiance,
                                     {{int32_t(held.x0), int32_t(held.y0)}, {held.width(), held.height()}});
                const double share = double(held.width()) * held.height() / (double(frame.width) * frame.height);
                builder.note("resolves the " + std::to_string(held.width()) + " x " + std::to_string(held.height()) +
                             " texels that hold what the frame reads (" + std::to_string(std::lround(100.0 * share)) +
                             "% of the map)");
            }
        },
        [push, held](const Data& d, fg::PassContext& context) {
            if (held.width() == 0 || held.height() == 0) return;  // the frame reads no texel
            const Pipeline& pipeline =
                context.pipeline("caustic resolve", ComputePipelineDesc{"caustics/caustic_resolve.comp"});
            const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
            // Bands of at most 65535 groups of rows, each within one binding.
            const auto bands = row_bands(held.height(), VkDeviceSize{push.width} * kCausticTexelBytes,
                                         kCausticFluxHeaderBytes, 0, limits.maxStorageBufferRange,
                                         limits.minStorageBufferOffsetAlignment, 65535 * pipeline.local_size()[1]);
            for (const RowBand& band : bands) {
                ResolvePush p = push;
                p.band_first = held.y0 + band.first;
                p.band_rows = band.rows;
                context.bind(pipeline, {context.storage_buffer("Flux", d.flux, band.offset, band.bytes)});
                context.push_constants(pipeline, p);
                context.dispatch(pipeline, push.width, band.rows);
            }
        });
    return {data.irradiance, frame_buffer};
}

}  // namespace vkw::passes
