// add_present_handoff_pass (present_handoff.hpp).
#include "passes/present/present_handoff.hpp"

#include "passes/common/whole_image_copy.hpp"

namespace vkw::passes {

fg::AccessState present_handoff_final_state() { return fg::access_state(fg::Use::SampledRead, fg::PassKind::Graphics); }

void add_present_handoff_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, const fg::ImportedImage& target) {
    fg::ImportedImage imported = target;
    imported.initial = {};  // overwritten whole: nothing of the last frame is kept
    imported.final_state = present_handoff_final_state();
    add_whole_image_copy_pass(graph, "present handoff", hdr, graph.import_image("window HDR", imported));
}

}  // namespace vkw::passes
