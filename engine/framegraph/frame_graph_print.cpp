// Printable forms of a compiled frame graph: the report of `vkwater passes`, the
// barrier dump of the golden tests, and Graphviz.
#include "engine/framegraph/frame_graph.hpp"

#include "engine/vk/resources.hpp"

#include <cstdio>

namespace vkw::fg {
namespace {

// Bytes in the unit that shows them: KiB below a MiB.
std::string byte_size(uint64_t bytes) {
    char text[32];
    if (bytes < 1024 * 1024) {
        std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
        return text;
    }
    std::snprintf(text, sizeof text, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

std::string megabytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

const char* kind_name(PassKind kind) {
    switch (kind) {
        case PassKind::Graphics: return "graphics";
        case PassKind::Compute: return "compute";
        case PassKind::Transfer: return "transfer";
    }
    return "?";
}

std::vector<std::string> pass_names_in_order(const FrameGraph& graph) {
    std::vector<std::string> names;
    for (uint32_t pass : graph.compiled().order) names.push_back(graph.passes()[pass].name);
    return names;
}

}  // namespace

uint64_t FrameGraph::resource_bytes(uint32_t resource) const {
    const ResourceDecl& decl = resources_[resource];
    if (!decl.is_image) return decl.buffer.size;
    return uint64_t{image_width(resource)} * image_height(resource) * format_texel_bytes(decl.image.format);
}

bool FrameGraph::creates(const ResourceUse& use) const {
    return !resources_[use.resource].imported && use.version_read == 0 && use.version_written == 1;
}

uint64_t FrameGraph::created_bytes(uint32_t pass) const {
    uint64_t bytes = 0;
    for (const ResourceUse& use : passes_[pass].uses) {
        if (creates(use)) bytes += resource_bytes(use.resource);
    }
    return bytes;
}

std::string FrameGraph::describe() const {
    const CompiledGraph& compiled = this->compiled();
    std::string text = needs_.describe();
    text += "passes, in execution order:\n";
    for (size_t position = 0; position < compiled.order.size(); ++position) {
        const PassDecl& pass = passes_[compiled.order[position]];
        text += "  " + std::to_string(position + 1) + ". " + pass.name + " [" + kind_name(pass.kind) + "]\n";
        std::string reads, writes, created;
        uint64_t created_bytes = 0;
        int created_count = 0;
        for (const ResourceUse& use : pass.uses) {
            std::string& list = use.version_written != use.version_read ? writes : reads;
            list += (list.empty() ? "" : ", ") + resources_[use.resource].name + " (" + use_name(use.use) + ")";
            // The resources this pass brings into the frame: what its method costs in memory.
            const ResourceDecl& resource = resources_[use.resource];
            if (creates(use)) {
                const uint64_t bytes = resource_bytes(use.resource);
                created_bytes += bytes;
                ++created_count;
                created += (created.empty() ? "" : ", ") + resource.name + " " + byte_size(bytes);
            }
        }
        if (!reads.empty()) text += "       reads:  " + reads + "\n";
        if (!writes.empty()) text += "       writes: " + writes + "\n";
        if (created_count > 1) created += " (" + byte_size(created_bytes) + " in all)";
        if (!created.empty()) text += "       creates: " + created + "\n";
        if (!pass.note.empty()) text += "       note:   " + pass.note + "\n";
    }
    text += "culled passes:\n";
    if (compiled.culled.empty()) text += "  (none)\n";
    for (const CulledPass& culled : compiled.culled) text += "  " + culled.name + ": " + culled.reason + "\n";
    text += "transient memory: " + megabytes(compiled.aliasing.unaliased_size) + " without aliasing, " +
            megabytes(compiled.aliasing.heap_size) + " with aliasing (" +
            std::to_string(compiled.aliased_resources.size()) + " resources)\n";
    return text;
}

std::string FrameGraph::dump_barriers() const {
    return vkw::fg::dump_barriers(compiled().barriers, compiled().timelines, pass_names_in_order(*this));
}

std::string FrameGraph::to_dot() const {
    const CompiledGraph& compiled = this->compiled();
    std::vector<bool> live(passes_.size(), false);
    for (uint32_t pass : compiled.order) live[pass] = true;
    std::string dot = "digraph framegraph {\n  rankdir=LR;\n";
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        dot += "  p" + std::to_string(p) + " [shape=box, label=\"" + passes_[p].name + "\"" +
               (live[p] ? "" : ", style=dashed, color=gray") + "];\n";
    }
    for (uint32_t r = 0; r < resources_.size(); ++r) {
        dot += "  r" + std::to_string(r) + " [shape=ellipse, label=\"" + resources_[r].name + "\"" +
               (resources_[r].imported ? ", style=bold" : "") + "];\n";
    }
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        for (const ResourceUse& use : passes_[p].uses) {
            const std::string pass = "p" + std::to_string(p), resource = "r" + std::to_string(use.resource);
            dot += use.version_written != use.version_read ? "  " + pass + " -> " + resource + ";\n"
                                                           : "  " + resource + " -> " + pass + ";\n";
        }
    }
    return dot + "}\n";
}

}  // namespace vkw::fg
