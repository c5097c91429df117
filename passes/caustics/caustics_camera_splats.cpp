// add_caustic_camera_splat_passes (caustics_camera_splats.hpp).
#include "passes/caustics/caustics_camera_splats.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/zeroed_buffer.hpp"

#include <shader_structs/caustics/caustic_camera_resolve.comp.hpp>
#include <shader_structs/caustics/caustic_camera_splats.comp.hpp>

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {
namespace {

// The push constants of shaders/caustics/caustic_camera_splats.comp, generated from its SPIR-V.
using CameraSplatPush = glsl::caustic_camera_splats_comp::Push;
static_assert(sizeof(CameraSplatPush) == 128, "the push-constant size every device supports");

// The push-constant block of shaders/caustics/caustic_camera_resolve.comp, generated from its SPIR-V (tools/shader_structs).
using CameraResolvePush = glsl::caustic_camera_resolve_comp::Push;

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
        fg::BufferHandle surface, flux;
        SunShadowReads shadow;
    };
    const auto& splats = graph.add_pass<SplatData>(
        "camera caustic splats", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, SplatData& d) {
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.surface = builder.read_storage("Surface", inputs.surface);
            d.flux = builder.read_write_storage("Flux", cleared);
            builder.sample("receivers", receivers, fg::Filter::Nearest);
            d.shadow.declare(builder, shadow);
        },
        [push](const SplatData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = ShaderVariant{"caustics/caustic_camera_splats.comp"}
                              .define("VKWATER_SUN_SHADOW", static_cast<bool>(d.shadow))
                              .file();
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            // The flux buffer's header (the lost photons' count) and its pixels, in two bindings.
            const fg::DescriptorBinding lost = context.storage_buffer("Lost", d.flux, 0, kCausticFluxHeaderBytes);
            const fg::DescriptorBinding flux = context.storage_buffer(
                "Flux", d.flux, kCausticFluxHeaderBytes,
                VkDeviceSize{camera_caustic_level_pixels({push.width, push.height})} * kCausticTexelBytes);
            for (const RowBand& chunk : caustic_photon_chunks(context, push.resolution, push.sub)) {
                CameraSplatPush p = push;
                p.first_row = chunk.first;
                p.rows = chunk.rows;
                context.bind(pipeline,
                             {context.storage_buffer("Surface", d.surface, chunk.offset, chunk.bytes), flux, lost});
                context.push_constants(pipeline, p);
                context.dispatch(pipeline, p.resolution * p.sub, chunk.rows * p.sub);
            }
        });

    struct ResolveData {
        fg::BufferHandle flux;
        fg::ImageHandle irradiance;
    };
    const auto& resolved = graph.add_pass<ResolveData>(
        "camera caustic resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, ResolveData& d) {
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.flux = builder.read_storage("Flux", splats.flux);
            builder.sample("receivers", receivers, fg::Filter::Nearest);
            const fg::ImageInfo image{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, extent.width,
                                      extent.height};
            d.irradiance =
                builder.write_storage("irradiance", builder.create_image("camera caustic irradiance", image));
        },
        [resolve](const ResolveData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "caustics/caustic_camera_resolve.comp";
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            // The flux buffer's pixels, past its header.
            context.bind(pipeline, {context.storage_buffer(
                                       "Flux", d.flux, kCausticFluxHeaderBytes,
                                       VkDeviceSize{camera_caustic_level_pixels({resolve.width, resolve.height})} *
                                           kCausticTexelBytes)});
            context.push_constants(pipeline, resolve);
            context.dispatch(pipeline, d.irradiance);
        });
    return {receivers, resolved.irradiance};
}

}  // namespace vkw::passes
