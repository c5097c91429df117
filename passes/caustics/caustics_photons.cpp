// add_caustic_photon_pass (caustics_photons.hpp).
#include "passes/caustics/caustics_photons.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/common/zeroed_buffer.hpp"
#include "passes/water/water_surface.hpp"

#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {
namespace {

constexpr uint32_t kGroupSide = 8;  // local_size of caustic_photons.comp
constexpr uint32_t kMaxGroups = 65535;

// Mirrors the push constants of shaders/caustics/caustic_photons.comp.
struct CausticPhotonPush {
    CausticPhotonSourcePush source;
    uint32_t resolution, sub, first_row, rows, band_first, band_rows, jitter, pad;
};
static_assert(sizeof(CausticPhotonPush) == 128, "the push-constant size every device supports");

}  // namespace

CausticPhotonSourcePush caustic_photon_source(const CausticInputs& in) {
    const CausticMapFrame frame = fit_caustic_map(in);
    CausticPhotonSourcePush push{};
    push.space = caustic_light_space_push(frame, in);
    for (int c = 0; c < 3; ++c) {
        push.deposit_scale[c] = frame.sun_up ? float(in.sun_irradiance[c] / frame.lsb[c]) : 0.0f;
        push.sigma_t[c] = float(in.sigma_t[c]);
    }
    return push;
}

std::vector<RowBand> caustic_photon_chunks(const fg::PassContext& context, uint32_t resolution, uint32_t sub) {
    const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
    // Cell rows j .. j + rows read vertex rows j .. j + rows: one extra row per chunk.
    return row_bands(resolution, VkDeviceSize{resolution + 1} * kWaterVertexBytes, 0, 1, limits.maxStorageBufferRange,
                     limits.minStorageBufferOffsetAlignment, kMaxGroups * kGroupSide / sub);
}

uint32_t caustic_photon_groups(uint64_t invocations) {
    return static_cast<uint32_t>((invocations + kGroupSide - 1) / kGroupSide);
}

fg::BufferHandle add_caustic_photon_pass(fg::FrameGraph& graph, const CausticInputs& inputs,
                                         const SunShadowMap* shadow) {
    CausticPhotonPush push{};
    push.source = caustic_photon_source(inputs);  // checks the inputs
    push.resolution = inputs.grid_resolution;
    push.sub = inputs.sub_photons;
    push.jitter = inputs.jitter ? 1u : 0u;
    const CausticMapFrame frame = fit_caustic_map(inputs);  // its size includes the margin for the waves
    const VkDeviceSize bytes = caustic_flux_bytes(frame.width, frame.height);

    const fg::BufferHandle cleared = add_zeroed_buffer_pass(graph, "caustic flux clear", "caustic flux", bytes);

    struct Data {
        fg::BufferHandle surface, flux;
        SunShadowReads shadow;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic photons", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.surface = builder.read_storage(inputs.surface, stage);
            d.flux = builder.read_write_storage(cleared, stage);
            d.shadow.declare(builder, shadow, stage);
        },
        [push, kernel_variant = inputs.kernel](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            // The variant: the kernel, then with the sun shadow map or without (shaders/CMakeLists.txt).
            const char* kernel = kernel_variant == CausticKernel::Bilinear   ? "bilinear"
                                 : kernel_variant == CausticKernel::Adaptive ? "adaptive"
                                                                             : "footprint";
            desc.shader = std::string("caustics/caustic_photons.comp.") + kernel + (d.shadow ? "_shadow" : "");
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT},
                                    {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT},
                                    {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
            d.shadow.add_layout(desc.layout.bindings, VK_SHADER_STAGE_COMPUTE_BIT);
            desc.layout.push_constant_bytes = sizeof(CausticPhotonPush);
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
            const uint32_t r = push.resolution, s = push.sub;
            const auto chunks = caustic_photon_chunks(context, r, s);
            const uint32_t width = static_cast<uint32_t>(push.source.space.u_axis[3]);
            const uint32_t height = static_cast<uint32_t>(push.source.space.v_axis[3]);
            const auto bands = row_bands(height, VkDeviceSize{width} * kCausticTexelBytes, kCausticFluxHeaderBytes, 0,
                                         limits.maxStorageBufferRange, limits.minStorageBufferOffsetAlignment, height);
            fg::DescriptorBinding lost = context.storage_buffer(2, d.flux);
            lost.buffer.offset = 0;
            lost.buffer.range = kCausticFluxHeaderBytes;
            for (const RowBand& chunk : chunks) {
                fg::DescriptorBinding surface = context.storage_buffer(0, d.surface);
                surface.buffer.offset = chunk.offset;
                surface.buffer.range = chunk.bytes;
                for (const RowBand& band : bands) {
                    fg::DescriptorBinding flux = context.storage_buffer(1, d.flux);
                    flux.buffer.offset = band.offset;
                    flux.buffer.range = band.bytes;
                    CausticPhotonPush p = push;
                    p.first_row = chunk.first;
                    p.rows = chunk.rows;
                    p.band_first = band.first;
                    p.band_rows = band.rows;
                    std::vector<fg::DescriptorBinding> bindings{surface, flux, lost};
                    d.shadow.add_bindings(context, bindings);
                    context.bind(pipeline, bindings);
                    context.push_constants(pipeline, p);
                    vkCmdDispatch(context.cmd(), caustic_photon_groups(uint64_t{r} * s),
                                  caustic_photon_groups(uint64_t{chunk.rows} * s), 1);
                }
            }
        });
    return data.flux;
}

}  // namespace vkw::passes
