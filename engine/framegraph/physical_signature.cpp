// FrameGraph::physical_signature (frame_graph.hpp): everything of a compiled graph that the
// executor turns into Vulkan objects. Two graphs with the same signature can run on the same
// images, buffers, memory, render passes and framebuffers: what differs between them (the
// values their passes captured, the constants they read) reaches the device only when the
// passes record.
#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>
#include <cstring>
#include <string>

namespace vkw::fg {

namespace {

// Appends the raw bytes of plain values: the signature is compared, never shown.
class SignatureWriter {
public:
    template <class T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        text_.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void add(const std::string& value) {
        add(value.size());
        text_ += value;
    }
    std::string take() { return std::move(text_); }

private:
    std::string text_;
};

void add_access(SignatureWriter& out, const AccessState& state) {
    out.add(state.stages);
    out.add(state.access);
    out.add(state.layout);
}

}  // namespace

std::string FrameGraph::physical_signature() const {
    const CompiledGraph& graph = compiled();
    SignatureWriter out;
    out.add(graph.output_width);
    out.add(graph.output_height);
    out.add(resources_.size());
    // Framebuffers (VkRenderPass recording) hold an imported image's view; with dynamic rendering
    // the executor reads the imported handles from the graph it runs, so another image of the same
    // size, format and states (a host's next target) needs no new objects.
    bool framebuffers = false;
    for (uint32_t pass : graph.order) {
        framebuffers = framebuffers || (passes_[pass].kind == PassKind::Graphics &&
                                        recording_of(pass) == RecordingKind::RenderPassObject);
    }
    out.add(framebuffers);
    for (uint32_t r = 0; r < resources_.size(); ++r) {
        const ResourceDecl& decl = resources_[r];
        const bool live = graph.resource_live[r];
        out.add(decl.name);
        out.add(decl.is_image);
        out.add(decl.imported);
        out.add(live);
        if (!live) continue;
        if (decl.imported) {
            // The same objects in the same states: the executor keeps no copy of them, but
            // framebuffers name their views.
            if (decl.is_image) {
                const ImportedImage& image = decl.imported_image;
                if (framebuffers) {
                    out.add(image.image);
                    out.add(image.view);
                }
                out.add(image.width);
                out.add(image.height);
                out.add(image.format);
                add_access(out, image.initial);
                out.add(image.final_state.has_value());
                if (image.final_state) add_access(out, *image.final_state);
            } else {
                const ImportedBuffer& buffer = decl.imported_buffer;
                out.add(buffer.buffer);
                out.add(buffer.size);
                add_access(out, buffer.initial);
                out.add(buffer.final_state.has_value());
                if (buffer.final_state) add_access(out, *buffer.final_state);
            }
            continue;
        }
        // A transient: its creation info and the lifetime that places it in the shared heap.
        if (decl.is_image) {
            out.add(decl.image.format);
            out.add(image_width(r));
            out.add(image_height(r));
            out.add(decl.image_usage);
        } else {
            out.add(decl.buffer.size);
            out.add(decl.buffer_usage);
        }
        out.add(graph.first_use[r]);
        out.add(graph.last_use[r]);
    }
    // The living passes in order, with every use: render passes, framebuffers and the query
    // pool follow from them (and the barriers, which the executor reads from the graph anyway).
    out.add(graph.order.size());
    for (const uint32_t p : graph.order) {
        const PassDecl& pass = passes_[p];
        out.add(pass.name);
        out.add(pass.kind);
        out.add(recording_of(p));
        out.add(pass.uses.size());
        for (const ResourceUse& use : pass.uses) {
            out.add(use.resource);
            out.add(use.use);
            out.add(use.shader_stages);
            out.add(use.load);
        }
    }
    return out.take();
}

bool FrameGraph::keeps_physical_signature_of(const FrameGraph* previous) const {
    // The pointer is compared before `previous` is read: only the graph compile() took over from
    // qualifies, and it was alive then.
    if (previous == nullptr || taken_over_from_ != previous || default_recording_ != previous->default_recording_) {
        return false;
    }
    for (size_t r = 0; r < resources_.size(); ++r) {  // compiles_like: the same resources, in order
        const ResourceDecl &mine = resources_[r], &theirs = previous->resources_[r];
        if (!mine.imported) continue;
        const bool same_handles = mine.is_image ? mine.imported_image.image == theirs.imported_image.image &&
                                                      mine.imported_image.view == theirs.imported_image.view
                                                : mine.imported_buffer.buffer == theirs.imported_buffer.buffer;
        if (!same_handles) return false;
    }
    return true;
}

}  // namespace vkw::fg
