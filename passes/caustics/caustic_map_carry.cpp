// add_caustic_map_keep_pass and import_kept_caustic_map (caustic_map_carry.hpp).
#include "passes/caustics/caustic_map_carry.hpp"

#include "passes/common/whole_image_copy.hpp"

namespace vkw::passes {
namespace {

// Between sub-frames the kept map waits where every reader of a caustic map samples it: the
// receivers' and the water's fragment shaders, and the marched godrays' compute shader.
fg::AccessState kept_state() {
    return fg::access_state(fg::Use::SampledRead, fg::PassKind::Graphics,
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

fg::ImageHandle import_kept(fg::FrameGraph& graph, fg::ImportedImage kept, const fg::AccessState& initial) {
    kept.initial = initial;
    kept.final_state = kept_state();
    return graph.import_image("kept caustic irradiance", kept);
}

}  // namespace

void add_caustic_map_keep_pass(fg::FrameGraph& graph, fg::ImageHandle irradiance, const fg::ImportedImage& kept) {
    // Overwritten whole: what the image held before does not matter.
    add_whole_image_copy_pass(graph, "keep caustic map", irradiance, import_kept(graph, kept, {}));
}

fg::ImageHandle import_kept_caustic_map(fg::FrameGraph& graph, const fg::ImportedImage& kept) {
    return import_kept(graph, kept, kept_state());
}

}  // namespace vkw::passes
