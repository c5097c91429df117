#include "passes/water/scene_optics.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/common/frame_keys.hpp"

namespace vkw::passes {

void add_scene_optics_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle optics;
    };
    const auto& data = graph.add_pass<Data>(
        "scene optics", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.optics = builder.write_storage("Optics", builder.create_buffer("scene optics", {3 * 16}));
        },
        [](const Data&, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline("scene optics", ComputePipelineDesc{"water/scene_optics.comp"});
            context.bind(pipeline);
            vkCmdDispatch(context.cmd(), 1, 1, 1);
        });
    graph.blackboard().put(keys::kSceneOptics, data.optics);
}

}  // namespace vkw::passes
