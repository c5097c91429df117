#include "engine/framegraph/frame_graph.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/dependency_graph.hpp"
#include "engine/vk/resources.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vkw::fg {

// ---------------------------------------------------------------- declaration

FrameGraph::FrameGraph(FrameNeeds needs) : needs_(std::move(needs)) {
    // Room for a whole frame's passes and resources at once: the renderer declares its graph every
    // frame, and growing these vectors moved every declaration made so far several times over.
    passes_.reserve(kReservedPasses);
    resources_.reserve(kReservedResources);
}

void FrameGraph::clear(FrameNeeds needs) {
    clear();
    needs_ = std::move(needs);
}

FrameNeeds& FrameGraph::needs_to_decide() {
    if (!passes_.empty() || !resources_.empty()) {
        throw InternalError("frame graph: the needs are decided before the declaration's first pass or resource");
    }
    return needs_;
}

void FrameGraph::clear() {
    arena_.clear();  // the captures first: nothing else refers to them
    // Kept last to first, so that the next declaration, taking from the back, gives each pass the
    // storage of the pass at its place last time: most frames declare the same passes, and each
    // finds room for its uses.
    for (auto pass = passes_.rbegin(); pass != passes_.rend(); ++pass) {
        pass->name.clear();
        pass->uses.clear();
        pass->note.clear();
        spare_passes_.push_back(std::move(*pass));
    }
    passes_.clear();
    for (auto resource = resources_.rbegin(); resource != resources_.rend(); ++resource) {
        resource->name.clear();
        resource->writer_of_version.clear();
        spare_resources_.push_back(std::move(*resource));
    }
    resources_.clear();
    requested_.clear();
    blackboard_.clear();
    default_recording_ = RecordingKind::DynamicRendering;
    compiled_.reset();
    taken_over_from_ = nullptr;
}

uint32_t FrameGraph::add_pass_decl(std::string_view name, PassKind kind) {
    for (const PassDecl& pass : passes_) {
        if (pass.name == name) throw InternalError("frame graph: two passes are named '" + std::string(name) + "'");
    }
    compiled_.reset();
    // A new declaration with every field at its default, in the buffers of the name, the uses and
    // the note that clear() kept (emptied) where there are some.
    PassDecl pass{};
    if (spare_passes_.empty()) {
        pass.uses.reserve(kReservedUses);
    } else {
        PassDecl& kept = spare_passes_.back();
        pass.name = std::move(kept.name);
        pass.uses = std::move(kept.uses);
        pass.note = std::move(kept.note);
        spare_passes_.pop_back();
    }
    pass.name.assign(name);
    pass.kind = kind;
    passes_.push_back(std::move(pass));
    return static_cast<uint32_t>(passes_.size() - 1);
}

uint32_t FrameGraph::add_resource(std::string_view name, ResourceDecl decl) {
    compiled_.reset();
    // The name's and the writers' buffers that clear() kept (emptied), where there are some.
    if (!spare_resources_.empty()) {
        ResourceDecl& kept = spare_resources_.back();
        decl.name = std::move(kept.name);
        decl.writer_of_version = std::move(kept.writer_of_version);
        spare_resources_.pop_back();
    }
    decl.name.assign(name);
    decl.writer_of_version.push_back(Handle<ImageTag>::kInvalid);  // version 0 has no writer
    resources_.push_back(std::move(decl));
    return static_cast<uint32_t>(resources_.size() - 1);
}

ImageHandle FrameGraph::import_image(std::string_view name, const ImportedImage& image) {
    ResourceDecl decl;
    decl.is_image = true;
    decl.imported = true;
    decl.imported_image = image;
    decl.image = {image.format, SizeClass::Absolute, 1.0f, image.width, image.height};
    return {add_resource(name, std::move(decl)), 0};
}

BufferHandle FrameGraph::import_buffer(std::string_view name, const ImportedBuffer& buffer) {
    ResourceDecl decl;
    decl.is_image = false;
    decl.imported = true;
    decl.imported_buffer = buffer;
    decl.buffer.size = buffer.size;
    return {add_resource(name, std::move(decl)), 0};
}

void FrameGraph::check_current(uint32_t pass, uint32_t resource, uint32_t version, const char* verb) const {
    if (resource >= resources_.size()) {
        throw InternalError("pass '" + passes_[pass].name + "' " + verb + " an invalid handle");
    }
    const ResourceDecl& decl = resources_[resource];
    if (version != decl.version) {
        const uint32_t writer = decl.writer_of_version[decl.version];
        throw InternalError("pass '" + passes_[pass].name + "' " + verb + " a stale handle of '" + decl.name +
                            "' (version " + std::to_string(version) + "; the current version " +
                            std::to_string(decl.version) + " was written by pass '" + passes_[writer].name + "')");
    }
}

void FrameGraph::request_output(ImageHandle image) {
    check_requestable(image.index, image.version);
    requested_.emplace_back(image.index, image.version);
    compiled_.reset();
}

void FrameGraph::request_output(BufferHandle buffer) {
    check_requestable(buffer.index, buffer.version);
    requested_.emplace_back(buffer.index, buffer.version);
    compiled_.reset();
}

void FrameGraph::check_requestable(uint32_t resource, uint32_t version) const {
    if (resource >= resources_.size()) throw InternalError("request_output: invalid handle");
    const ResourceDecl& decl = resources_[resource];
    if (version != decl.version) {
        throw InternalError("request_output: stale handle of '" + decl.name + "' (version " + std::to_string(version) +
                            "; the current version " + std::to_string(decl.version) + " was written by pass '" +
                            passes_[decl.writer_of_version[decl.version]].name + "')");
    }
}

RecordingKind FrameGraph::recording_of(uint32_t pass) const {
    return passes_[pass].recording.value_or(default_recording_);
}

uint32_t FrameGraph::image_width(uint32_t resource) const {
    const ImageInfo& info = resources_[resource].image;
    if (info.size_class == SizeClass::Absolute) return info.width;
    return std::max(1u, static_cast<uint32_t>(std::lround(info.scale * compiled().output_width)));
}

uint32_t FrameGraph::image_height(uint32_t resource) const {
    const ImageInfo& info = resources_[resource].image;
    if (info.size_class == SizeClass::Absolute) return info.height;
    return std::max(1u, static_cast<uint32_t>(std::lround(info.scale * compiled().output_height)));
}

ImageHandle PassBuilder::create_image(std::string_view name, const ImageInfo& info) {
    ResourceDecl decl;
    decl.is_image = true;
    decl.image = info;
    return {graph_.add_resource(name, std::move(decl)), 0};
}

BufferHandle PassBuilder::create_buffer(std::string_view name, const BufferInfo& info) {
    ResourceDecl decl;
    decl.is_image = false;
    decl.buffer = info;
    return {graph_.add_resource(name, std::move(decl)), 0};
}

template <class Tag>
Handle<Tag> PassBuilder::use(Handle<Tag> handle, Use use, VkPipelineStageFlags2 stages, LoadOp load,
                             const ClearValue& clear) {
    constexpr bool image = std::is_same_v<Tag, ImageTag>;
    graph_.check_current(pass_, handle.index, handle.version, use_name(use));
    ResourceDecl& decl = graph_.resources_[handle.index];
    if (decl.is_image != image) throw InternalError("pass '" + graph_.passes_[pass_].name + "': wrong handle kind");
    if (image) {
        decl.image_usage |= image_usage(use);
    } else {
        decl.buffer_usage |= buffer_usage(use);
    }
    ResourceUse record{handle.index, handle.version, handle.version, use, stages, load, clear};
    if (is_write(use)) {
        record.version_written = ++decl.version;
        decl.writer_of_version.push_back(pass_);
    }
    graph_.passes_[pass_].uses.push_back(record);
    return {handle.index, record.version_written};
}

ImageHandle PassBuilder::sample(ImageHandle h, VkPipelineStageFlags2 s) { return use(h, Use::SampledRead, s); }
ImageHandle PassBuilder::read_storage(ImageHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageImageRead, s);
}
ImageHandle PassBuilder::write_storage(ImageHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageImageWrite, s);
}
ImageHandle PassBuilder::read_write_storage(ImageHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageImageReadWrite, s);
}
ImageHandle PassBuilder::color_attachment(ImageHandle h, LoadOp load, const ClearValue& clear) {
    return use(h, load == LoadOp::Load ? Use::ColorAttachmentBlend : Use::ColorAttachmentWrite, 0, load, clear);
}
ImageHandle PassBuilder::depth_stencil_attachment(ImageHandle h, LoadOp load, const ClearValue& clear) {
    return use(h, Use::DepthStencilWrite, 0, load, clear);
}
ImageHandle PassBuilder::depth_stencil_read_only(ImageHandle h) {
    return use(h, Use::DepthStencilReadOnly, 0, LoadOp::Load);
}
ImageHandle PassBuilder::copy_source(ImageHandle h) { return use(h, Use::TransferSrc, 0); }
ImageHandle PassBuilder::copy_destination(ImageHandle h) { return use(h, Use::TransferDst, 0); }

BufferHandle PassBuilder::uniform_buffer(BufferHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::UniformBuffer, s);
}
BufferHandle PassBuilder::read_storage(BufferHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageBufferRead, s);
}
BufferHandle PassBuilder::write_storage(BufferHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageBufferWrite, s);
}
BufferHandle PassBuilder::read_write_storage(BufferHandle h, VkPipelineStageFlags2 s) {
    return use(h, Use::StorageBufferReadWrite, s);
}
template <class Tag>
Handle<Tag> PassBuilder::bound(std::string_view binding, Handle<Tag> handle, Use use_kind, VkPipelineStageFlags2 stages,
                               Filter filter) {
    std::vector<ResourceUse>& uses = graph_.passes_[pass_].uses;
    for (const ResourceUse& other : uses) {
        if (other.binding == binding) {
            throw InternalError("pass '" + graph_.passes_[pass_].name + "' binds two resources to '" +
                                std::string(binding) + "'");
        }
    }
    const Handle<Tag> result = use(handle, use_kind, stages);
    uses.back().binding.assign(binding);
    uses.back().filter = filter;
    return result;
}

ImageHandle PassBuilder::sample(std::string_view b, ImageHandle h, Filter f, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::SampledRead, s, f);
}
ImageHandle PassBuilder::read_storage(std::string_view b, ImageHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageImageRead, s);
}
ImageHandle PassBuilder::write_storage(std::string_view b, ImageHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageImageWrite, s);
}
ImageHandle PassBuilder::read_write_storage(std::string_view b, ImageHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageImageReadWrite, s);
}
BufferHandle PassBuilder::uniform_buffer(std::string_view b, BufferHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::UniformBuffer, s);
}
BufferHandle PassBuilder::read_storage(std::string_view b, BufferHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageBufferRead, s);
}
BufferHandle PassBuilder::write_storage(std::string_view b, BufferHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageBufferWrite, s);
}
BufferHandle PassBuilder::read_write_storage(std::string_view b, BufferHandle h, VkPipelineStageFlags2 s) {
    return bound(b, h, Use::StorageBufferReadWrite, s);
}

BufferHandle PassBuilder::vertex_buffer(BufferHandle h) { return use(h, Use::VertexBuffer, 0); }
BufferHandle PassBuilder::index_buffer(BufferHandle h) { return use(h, Use::IndexBuffer, 0); }
BufferHandle PassBuilder::indirect_buffer(BufferHandle h) { return use(h, Use::IndirectBuffer, 0); }
BufferHandle PassBuilder::copy_source(BufferHandle h) { return use(h, Use::TransferSrc, 0); }
BufferHandle PassBuilder::copy_destination(BufferHandle h) { return use(h, Use::TransferDst, 0); }

void PassBuilder::side_effect() { graph_.passes_[pass_].side_effect = true; }
void PassBuilder::serves(EffectTag effect) { graph_.passes_[pass_].serves = effect; }

void PassBuilder::note(std::string text) { graph_.passes_[pass_].note = std::move(text); }

void PassBuilder::defines_only(ImageHandle written, VkRect2D region) {
    PassDecl& pass = graph_.passes_[pass_];
    for (ResourceUse& use : pass.uses) {
        if (use.resource != written.index || use.version_written != written.version || !is_write(use.use)) continue;
        const ImageInfo& info = graph_.resources_[written.index].image;
        if (info.size_class != SizeClass::Absolute || region.offset.x < 0 || region.offset.y < 0 ||
            region.offset.x + region.extent.width > info.width ||
            region.offset.y + region.extent.height > info.height) {
            throw InternalError("pass '" + pass.name + "': the region it defines of '" +
                                graph_.resources_[written.index].name + "' is not within the image");
        }
        use.defined_region = region;
        return;
    }
    throw InternalError("pass '" + pass.name + "' defines a region of an image it did not write");
}
void PassBuilder::record_with(RecordingKind kind) { graph_.passes_[pass_].recording = kind; }

// ---------------------------------------------------------------- compile

namespace {

// Does this use depend on the resource's previous contents?
bool reads_previous_contents(const ResourceUse& use) {
    switch (use.use) {
        case Use::StorageImageWrite:
        case Use::StorageBufferWrite:
        case Use::TransferDst: return false;
        case Use::ColorAttachmentWrite:
        case Use::DepthStencilWrite: return use.load == LoadOp::Load;
        default: return true;
    }
}

uint64_t estimated_bytes(const FrameGraph& graph, uint32_t resource) {
    const ResourceDecl& decl = graph.resources()[resource];
    if (!decl.is_image) return decl.buffer.size;
    return uint64_t{graph.image_width(resource)} * graph.image_height(resource) * format_texel_bytes(decl.image.format);
}

}  // namespace

const CompiledGraph& FrameGraph::compiled() const {
    if (!compiled_) throw InternalError("frame graph: compile() has not run since the last change");
    return *compiled_;
}

std::string FrameGraph::culled_reason(uint32_t pass_index) const {
    const PassDecl& pass = passes_[pass_index];
    if (pass.serves && !needs_.needs(*pass.serves)) {
        const EffectDecision* decision = needs_.find(*pass.serves);
        return std::string("effect '") + decision->effect.name + "' not needed" +
               (decision->forced ? " (forced off)" : "") + ": " + decision->reason;
    }
    std::string outputs;
    for (const ResourceUse& use : pass.uses) {
        if (use.version_written == use.version_read) continue;
        outputs += (outputs.empty() ? "'" : ", '") + resources_[use.resource].name + "'";
    }
    return outputs.empty() ? "writes nothing and has no side effect"
                           : "no living pass or requested output uses what it writes (" + outputs + ")";
}

const CompiledGraph& FrameGraph::compile(uint32_t output_width, uint32_t output_height, FrameGraph* previous) {
    const bool take_over = previous && previous->compiled_ && previous->compiled_->output_width == output_width &&
                           previous->compiled_->output_height == output_height && compiles_like(*previous);
    taken_over_from_ = take_over ? previous : nullptr;
    if (take_over) {
        compiled_ = std::move(previous->compiled_);
        previous->compiled_.reset();
        // The reasons name the needs' own words, which may change while the decisions stand.
        compiled_->culled.clear();
        std::vector<bool> living(passes_.size(), false);
        for (uint32_t p : compiled_->order) living[p] = true;
        for (uint32_t p = 0; p < passes_.size(); ++p) {
            if (!living[p]) compiled_->culled.push_back({passes_[p].name, culled_reason(p)});
        }
        return *compiled_;
    }
    CompiledGraph result;
    result.output_width = output_width;
    result.output_height = output_height;

    // Nodes: passes first (node id == pass index), then one node per resource version.
    DependencyGraph dag;
    for (const PassDecl& pass : passes_) dag.add_node(pass.name);
    std::map<std::pair<uint32_t, uint32_t>, DependencyGraph::NodeId> version_node;
    auto node_of = [&](uint32_t resource, uint32_t version) {
        auto [it, inserted] = version_node.try_emplace({resource, version}, 0);
        if (inserted) {
            it->second = dag.add_node(resources_[resource].name + " v" + std::to_string(version));
        }
        return it->second;
    };
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        for (const ResourceUse& use : passes_[p].uses) {
            const ResourceDecl& decl = resources_[use.resource];
            if (reads_previous_contents(use)) {
                if (use.version_read == 0 && !decl.imported) {
                    throw InternalError("pass '" + passes_[p].name + "' reads '" + decl.name +
                                        "', which no pass writes before it");
                }
                dag.add_edge(node_of(use.resource, use.version_read), p);
            }
            if (use.version_written != use.version_read) dag.add_edge(p, node_of(use.resource, use.version_written));
        }
        if (passes_[p].side_effect) dag.pin(p);
        if (passes_[p].serves && !needs_.needs(*passes_[p].serves)) dag.force_cull(p);
    }
    for (auto [resource, version] : requested_) dag.pin(node_of(resource, version));
    dag.cull();

    // A living pass must not read what a pass culled for an unneeded effect would write.
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        if (dag.is_culled(p)) continue;
        for (const ResourceUse& use : passes_[p].uses) {
            if (!reads_previous_contents(use) || use.version_read == 0) continue;
            const uint32_t writer = resources_[use.resource].writer_of_version[use.version_read];
            if (dag.is_culled(writer)) {
                const EffectDecision* decision = needs_.find(*passes_[writer].serves);
                throw InternalError("pass '" + passes_[p].name + "' reads '" + resources_[use.resource].name +
                                    "' from pass '" + passes_[writer].name + "', which serves effect '" +
                                    decision->effect.name + "' that this frame does not need (" + decision->reason +
                                    ")");
            }
        }
    }

    for (uint32_t p = 0; p < passes_.size(); ++p) {
        if (dag.is_culled(p)) result.culled.push_back({passes_[p].name, culled_reason(p)});
    }

    // Execution order is the declaration order of the living passes. Versioned handles
    // make it a valid topological order (a pass can only read versions written by
    // earlier passes), and it is the only order that also keeps write-after-read
    // right: a reader of version v must run before the writer of v + 1, an ordering
    // the DAG does not state (it would keep readers alive). The DAG's own topological
    // sort still runs, as a check that it has no cycle.
    dag.topological_order();
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        if (!dag.is_culled(p)) result.order.push_back(p);
    }
    compiled_ = std::move(result);
    compiled_->timelines = build_timelines(compiled_->order);

    // Lifetimes and the aliasing estimate (formats' texel sizes, 4 KiB alignment);
    // the executor replaces it with the device's real memory requirements.
    CompiledGraph& compiled = *compiled_;
    compiled.resource_live.assign(resources_.size(), false);
    compiled.first_use.assign(resources_.size(), 0);
    compiled.last_use.assign(resources_.size(), 0);
    std::vector<AliasRequest> requests;
    for (uint32_t r = 0; r < resources_.size(); ++r) {
        const auto& accesses = compiled.timelines[r].accesses;
        if (accesses.empty()) continue;
        compiled.resource_live[r] = true;
        compiled.first_use[r] = accesses.front().position;
        compiled.last_use[r] = accesses.back().position;
        if (resources_[r].imported) continue;
        requests.push_back({estimated_bytes(*this, r), 4096, compiled.first_use[r], compiled.last_use[r]});
        compiled.aliased_resources.push_back(r);
    }
    apply_aliasing(plan_aliasing(requests), compiled.aliased_resources);
    return *compiled_;
}

std::vector<ResourceTimeline> FrameGraph::build_timelines(const std::vector<uint32_t>& order) const {
    std::vector<ResourceTimeline> timelines(resources_.size());
    for (uint32_t r = 0; r < resources_.size(); ++r) {
        const ResourceDecl& decl = resources_[r];
        timelines[r].name = decl.name;
        timelines[r].is_image = decl.is_image;
        if (decl.imported) {
            timelines[r].initial = decl.is_image ? decl.imported_image.initial : decl.imported_buffer.initial;
            timelines[r].final_state =
                decl.is_image ? decl.imported_image.final_state : decl.imported_buffer.final_state;
        }
    }
    for (uint32_t position = 0; position < order.size(); ++position) {
        const PassDecl& pass = passes_[order[position]];
        for (const ResourceUse& use : pass.uses) {
            const ResourceDecl& decl = resources_[use.resource];
            const AccessState state = access_state(use.use, pass.kind, use.shader_stages,
                                                   decl.is_image && format_is_depth(decl.image.format));
            auto& accesses = timelines[use.resource].accesses;
            if (!accesses.empty() && accesses.back().position == position) {
                // Several uses of one resource in one pass merge into one state.
                TimelineAccess& merged = accesses.back();
                if (decl.is_image && merged.state.layout != state.layout) {
                    throw InternalError("pass '" + pass.name + "' uses '" + decl.name + "' in two layouts (" +
                                        layout_name(merged.state.layout) + " and " + layout_name(state.layout) + ")");
                }
                merged.state.stages |= state.stages;
                merged.state.access |= state.access;
                merged.writes = merged.writes || is_write(use.use);
            } else {
                accesses.push_back({position, state, is_write(use.use)});
            }
        }
    }
    return timelines;
}

void FrameGraph::apply_aliasing(const AliasPlan& plan, const std::vector<uint32_t>& aliased_resources) {
    CompiledGraph& compiled = *compiled_;
    // A transient that reuses memory waits for every stage that touched the memory before.
    for (size_t i = 0; i < aliased_resources.size(); ++i) {
        ResourceTimeline& timeline = compiled.timelines[aliased_resources[i]];
        timeline.initial = {};
        for (uint32_t predecessor : plan.predecessors[i]) {
            for (const TimelineAccess& access : compiled.timelines[aliased_resources[predecessor]].accesses) {
                timeline.initial.stages |= access.state.stages;
                if (access.writes) timeline.initial.access |= access.state.access;
            }
        }
    }
    compiled.aliasing = plan;
    compiled.aliased_resources = aliased_resources;
    compiled.barriers = derive_barriers(compiled.timelines, compiled.order.size());
}

}  // namespace vkw::fg
