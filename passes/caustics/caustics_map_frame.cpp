#include "passes/caustics/caustics_map_frame.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

fg::BufferHandle add_caustic_map_frame_pass(fg::FrameGraph& graph, const CausticInputs& inputs) {
    const CausticLightSpacePush space = caustic_light_space_push(fit_caustic_map(inputs), inputs);
    struct Upload {
        fg::BufferHandle frame;
    };
    const auto& upload = graph.add_pass<Upload>(
        "caustic map frame", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Upload& d) {
            d.frame = builder.copy_destination(builder.create_buffer("caustic map frame", {sizeof space}));
        },
        [space](const Upload& d, fg::PassContext& context) {
            vkCmdUpdateBuffer(context.cmd(), context.buffer(d.frame), 0, sizeof space, &space);
        });
    return upload.frame;
}

fg::ImageInfo caustic_map_image(const CausticMapFrame& frame) {
    fg::ImageInfo info;
    info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    info.size_class = fg::SizeClass::Absolute;
    info.width = frame.width;
    info.height = frame.height;
    return info;
}

}  // namespace vkw::passes
