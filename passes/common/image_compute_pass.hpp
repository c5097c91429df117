// The shape most of the frame's compute passes share: read some resources, create one image and
// write every texel of it, one invocation per texel (the blurs, the resolves, the godray depth and
// march, the procedural caustics). The pass says what it reads and which shader variant runs; the
// image's declaration, the pipeline, its bindings (by the shader's names), the push and the
// dispatch over the image follow here (docs/architecture.md, "Adding a pass: the godray blur").
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"

#include <string>
#include <type_traits>
#include <utility>

namespace vkw::passes {

struct ImageComputePass {
    std::string name;                // the pass's name in the graph
    std::string image_name;          // the image it creates, by its name in the graph
    fg::ImageInfo image;             // and its format and size
    std::string binding = "target";  // the shader's name for the image (a writeonly image2D)
};

// For a shader without a push block.
struct NoPush {};

// Adds the pass and returns the image it writes. `declare(builder)` declares what the pass reads and
// what it serves, and returns the shader file to run (a path under shaders/, or
// ShaderVariant{...}.file() for a variant chosen by what it declared). `push` is the shader's push
// block (its generated struct), or NoPush{}.
template <class Push, class Declare>
fg::ImageHandle add_image_compute_pass(fg::FrameGraph& graph, const ImageComputePass& pass, const Push& push,
                                       Declare&& declare) {
    struct Data {
        fg::ImageHandle image;
        std::string shader;
    };
    const auto& data = graph.add_pass<Data>(
        pass.name, fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            d.shader = declare(builder);
            d.image = builder.write_storage(pass.binding, builder.create_image(pass.image_name, pass.image));
        },
        [push](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline(d.shader, ComputePipelineDesc{d.shader, {}});
            context.bind(pipeline);
            if constexpr (!std::is_same_v<Push, NoPush>) context.push_constants(pipeline, push);
            context.dispatch(pipeline, d.image);
        });
    return data.image;
}

}  // namespace vkw::passes
