#include "passes/water/scene_optics.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/common/frame_keys.hpp"

namespace vkw::passes {

void add_scene_optics_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle constants;
        fg::BufferHandle optics;
    };
    const auto& data = graph.add_pass<Data>(
        "scene optics", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants));
            d.optics = builder.write_storage(builder.create_buffer("scene optics", {3 * 16}));
        },
        [](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "water/scene_optics.comp";
            const Pipeline& pipeline = context.pipeline("scene optics", desc);
            context.bind(pipeline, {context.uniform_buffer(0, d.constants), context.storage_buffer(1, d.optics)});
            vkCmdDispatch(context.cmd(), 1, 1, 1);
        });
    graph.blackboard().put(keys::kSceneOptics, data.optics);
}

}  // namespace vkw::passes
