#include "passes/common/calibration.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

void add_calibration_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::ImageHandle target;
    };
    graph.add_pass<Data>(
        kCalibrationPassName, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            // The frame's HDR format at the output size: the bytes per pixel of the real passes.
            d.target = builder.create_image("calibration target", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.target = builder.color_attachment(d.target, fg::LoadOp::DontCare);
            builder.side_effect();  // nothing reads its target; it runs to be timed
        },
        [](const Data&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "common/calibration.frag";
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
}

}  // namespace vkw::passes
