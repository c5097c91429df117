// add_caustic_map_keep_pass and import_kept_caustic_map (caustic_map_carry.hpp).
#include "passes/caustics/caustic_map_carry.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {
namespace {

// Between sub-frames the kept map waits where every reader of a caustic map samples it: the
// receivers' and the water's fragment shaders, and the marched godrays' compute shader.
fg::AccessState kept_state() {
    return fg::access_state(fg::Use::SampledRead, fg::PassKind::Graphics,
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

fg::ImportedImage imported(const KeptCausticMapImage& kept, const fg::AccessState& initial) {
    fg::ImportedImage image;
    image.image = kept.image;
    image.view = kept.view;
    image.width = kept.width;
    image.height = kept.height;
    image.format = kept.format;
    image.initial = initial;
    image.final_state = kept_state();
    return image;
}

}  // namespace

void add_caustic_map_keep_pass(fg::FrameGraph& graph, fg::ImageHandle irradiance, const KeptCausticMapImage& kept) {
    // Overwritten whole: what the image held before does not matter.
    const fg::ImageHandle target = graph.import_image("kept caustic irradiance", imported(kept, {}));
    struct Data {
        fg::ImageHandle source, target;
    };
    const auto& data = graph.add_pass<Data>(
        "keep caustic map", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(irradiance);
            d.target = builder.copy_destination(target);
        },
        [](const Data& d, fg::PassContext& context) {
            const VkExtent2D extent = context.extent(d.source);
            VkImageCopy region{};
            region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.extent = {extent.width, extent.height, 1};
            vkCmdCopyImage(context.cmd(), context.image(d.source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           context.image(d.target), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        });
    graph.request_output(data.target);
}

fg::ImageHandle import_kept_caustic_map(fg::FrameGraph& graph, const KeptCausticMapImage& kept) {
    return graph.import_image("kept caustic irradiance", imported(kept, kept_state()));
}

}  // namespace vkw::passes
