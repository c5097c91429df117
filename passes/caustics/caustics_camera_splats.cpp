// add_caustic_camera_splat_passes (caustics_camera_splats.hpp).
#include "passes/caustics/caustics_camera_splats.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/zeroed_buffer.hpp"

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {
namespace {

// Mirrors the push constants of shaders/caustics/caustic_camera_splats.comp.
struct CameraSplatPush {
    CausticPhotonSourcePush source;
    uint32_t resolution, sub, first_row, rows, jitter, width, height, pad;
};
static_assert(sizeof(CameraSplatPush) == 128, "the push-constant size every device supports");

// Mirrors the push constants of shaders/caustics/caustic_camera_resolve.comp.
struct CameraResolvePush {
    float lsb[4];
    uint32_t width, height;  // no tail padding: the block ends here, at 24 bytes
};

constexpr uint32_t kGroupSide = 8;  // local_size of caustic_camera_resolve.comp

}  // namespace

uint32_t camera_caustic_level_pixels(CameraCausticExtent extent) {
    uint32_t pixels = 0;
    for (uint32_t level = 0; level < kCameraCausticLevels; ++level) {
        const uint32_t step = 1u << level;
        pixels += ((extent.width + step - 1) / step) * ((extent.height + step - 1) / step);
    }
    return pixels;
}

VkDeviceSize camera_caustic_flux_bytes(CameraCausticExtent extent) {
    return kCausticFluxHeaderBytes + VkDeviceSize{camera_caustic_level_pixels(extent)} * kCausticTexelBytes;
}

CameraCaustics add_caustic_camera_splat_passes(fg::FrameGraph& graph, const CausticInputs& inputs,
                                               fg::ImageHandle receivers, CameraCausticExtent extent,
                                               const SunShadowMap* shadow) {
    CameraSplatPush push{};
    push.source = caustic_photon_source(inputs);  // checks the inputs
    push.resolution = inputs.grid_resolution;
    push.sub = inputs.sub_photons;
    push.jitter = inputs.jitter ? 1u : 0u;
    push.width = extent.width;
    push.height = extent.height;
    const CausticMapFrame frame = fit_caustic_map(inputs);
    CameraResolvePush resolve{};
    for (int c = 0; c < 3; ++c) resolve.lsb[c] = float(frame.lsb[c]);
    resolve.width = extent.width;
    resolve.height = extent.height;

    const fg::BufferHandle cleared = add_zeroed_buffer_pass(graph, "camera caustic flux clear", kCameraCausticFluxName,
                                                            camera_caustic_flux_bytes(extent));

    struct SplatData {
        fg::BufferHandle constants, surface, flux;
        fg::ImageHandle receivers;
        SunShadowReads shadow;
    };
    const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    const auto& splats = graph.add_pass<SplatData>(
        "camera caustic splats", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, SplatData& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), stage);
            d.surface = builder.read_storage(inputs.surface, stage);
            d.flux = builder.read_write_storage(cleared, stage);
            d.receivers = builder.sample(receivers, stage);
            d.shadow.declare(builder, shadow, stage);
        },
        [push](const SplatData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = std::string("caustics/caustic_camera_splats.comp.") + (d.shadow ? "shadow" : "plain");
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            fg::DescriptorBinding lost = context.storage_buffer(3, d.flux);
            lost.buffer.offset = 0;
            lost.buffer.range = kCausticFluxHeaderBytes;
            fg::DescriptorBinding flux = context.storage_buffer(2, d.flux);
            flux.buffer.offset = kCausticFluxHeaderBytes;
            flux.buffer.range =
                VkDeviceSize{camera_caustic_level_pixels({push.width, push.height})} * kCausticTexelBytes;
            for (const RowBand& chunk : caustic_photon_chunks(context, push.resolution, push.sub)) {
                fg::DescriptorBinding surface = context.storage_buffer(1, d.surface);
                surface.buffer.offset = chunk.offset;
                surface.buffer.range = chunk.bytes;
                std::vector<fg::DescriptorBinding> bindings{context.uniform_buffer(0, d.constants), surface, flux, lost,
                                                            context.sampled_nearest(5, d.receivers)};
                d.shadow.add_bindings(context, bindings);
                CameraSplatPush p = push;
                p.first_row = chunk.first;
                p.rows = chunk.rows;
                context.bind(pipeline, bindings);
                context.push_constants(pipeline, p);
                vkCmdDispatch(context.cmd(), caustic_photon_groups(uint64_t{p.resolution} * p.sub),
                              caustic_photon_groups(uint64_t{chunk.rows} * p.sub), 1);
            }
        });

    struct ResolveData {
        fg::BufferHandle constants, flux;
        fg::ImageHandle receivers, irradiance;
    };
    const auto& resolved = graph.add_pass<ResolveData>(
        "camera caustic resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, ResolveData& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), stage);
            d.flux = builder.read_storage(splats.flux, stage);
            d.receivers = builder.sample(receivers, stage);
            const fg::ImageInfo image{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, extent.width,
                                      extent.height};
            d.irradiance = builder.write_storage(builder.create_image("camera caustic irradiance", image), stage);
        },
        [resolve](const ResolveData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "caustics/caustic_camera_resolve.comp";
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            fg::DescriptorBinding flux = context.storage_buffer(1, d.flux);
            flux.buffer.offset = kCausticFluxHeaderBytes;
            flux.buffer.range =
                VkDeviceSize{camera_caustic_level_pixels({resolve.width, resolve.height})} * kCausticTexelBytes;
            context.bind(pipeline, {context.uniform_buffer(0, d.constants), flux,
                                    context.sampled_nearest(2, d.receivers), context.storage_image(3, d.irradiance)});
            context.push_constants(pipeline, resolve);
            vkCmdDispatch(context.cmd(), (resolve.width + kGroupSide - 1) / kGroupSide,
                          (resolve.height + kGroupSide - 1) / kGroupSide, 1);
        });
    return {receivers, resolved.irradiance};
}

}  // namespace vkw::passes
