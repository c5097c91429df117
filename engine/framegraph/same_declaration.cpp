// FrameGraph::compiles_like (frame_graph.hpp): whether two declarations compile to the same
// graph. It compares everything compile() reads and nothing else: the passes' names, kinds,
// uses, side effects and effects served, the resources' names, sizes, formats, usages and
// versions, the imports' sizes and states (not their handles: compile() never reads them), the
// requested outputs and which effects the frame needs (not the reasons, which only the list of
// culled passes prints, and compile() writes that list again).
#include "engine/framegraph/frame_graph.hpp"

#include <algorithm>

namespace vkw::fg {

namespace {

bool same_clear(const ClearValue& a, const ClearValue& b) {
    return std::equal(std::begin(a.color), std::end(a.color), std::begin(b.color)) && a.depth == b.depth &&
           a.stencil == b.stencil;
}

// Every field but `defined_region`, which may move each frame: the finite check reads it from
// the pass's declaration at record time, compile() never.
bool same_use(const ResourceUse& a, const ResourceUse& b) {
    return a.resource == b.resource && a.version_read == b.version_read && a.version_written == b.version_written &&
           a.use == b.use && a.shader_stages == b.shader_stages && a.load == b.load && same_clear(a.clear, b.clear) &&
           a.filter == b.filter && a.binding == b.binding;
}

bool same_pass(const PassDecl& a, const PassDecl& b) {
    return a.name == b.name && a.kind == b.kind && a.side_effect == b.side_effect && a.serves == b.serves &&
           a.recording == b.recording &&
           std::equal(a.uses.begin(), a.uses.end(), b.uses.begin(), b.uses.end(), same_use);
}

bool same_image_info(const ImageInfo& a, const ImageInfo& b) {
    return a.format == b.format && a.size_class == b.size_class && a.scale == b.scale && a.width == b.width &&
           a.height == b.height;
}

bool same_resource(const ResourceDecl& a, const ResourceDecl& b) {
    if (a.name != b.name || a.is_image != b.is_image || a.imported != b.imported || a.version != b.version ||
        a.writer_of_version != b.writer_of_version || a.image_usage != b.image_usage ||
        a.buffer_usage != b.buffer_usage || !same_image_info(a.image, b.image) || a.buffer.size != b.buffer.size) {
        return false;
    }
    if (!a.imported) return true;
    if (a.is_image) {
        const ImportedImage &x = a.imported_image, &y = b.imported_image;
        return x.width == y.width && x.height == y.height && x.format == y.format && x.initial == y.initial &&
               x.final_state == y.final_state;
    }
    const ImportedBuffer &x = a.imported_buffer, &y = b.imported_buffer;
    return x.size == y.size && x.initial == y.initial && x.final_state == y.final_state;
}

bool same_needs(const FrameNeeds& a, const FrameNeeds& b) {
    return std::equal(
        a.decisions.begin(), a.decisions.end(), b.decisions.begin(), b.decisions.end(),
        [](const EffectDecision& x, const EffectDecision& y) { return x.effect == y.effect && x.needed == y.needed; });
}

}  // namespace

bool FrameGraph::compiles_like(const FrameGraph& other) const {
    return requested_ == other.requested_ && same_needs(needs_, other.needs_) &&
           std::equal(passes_.begin(), passes_.end(), other.passes_.begin(), other.passes_.end(), same_pass) &&
           std::equal(resources_.begin(), resources_.end(), other.resources_.begin(), other.resources_.end(),
                      same_resource);
}

}  // namespace vkw::fg
