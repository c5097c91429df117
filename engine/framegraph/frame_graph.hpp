// The frame graph: passes declare what they read and write with verbs named after
// the Vulkan use (PassBuilder), and the graph culls, orders, derives every barrier
// and layout transition, aliases transient memory, and records (FrameExecutor).
// No pass records a barrier by hand.
//
// A pass has a name, a small Data struct of handles, a setup function that runs now
// (declares uses through the builder) and an execute function that runs at record
// time, only if the pass survived culling.
#pragma once

#include "engine/framegraph/access.hpp"
#include "engine/framegraph/aliasing.hpp"
#include "engine/framegraph/barriers.hpp"
#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_needs.hpp"
#include "engine/framegraph/handles.hpp"
#include "engine/framegraph/pass_arena.hpp"

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vkw::fg {

class PassContext;

// Size classes of images created by the graph.
enum class SizeClass : uint8_t { Absolute, OutputRelative };

struct ImageInfo {
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    SizeClass size_class = SizeClass::OutputRelative;
    float scale = 1.0f;              // OutputRelative: fraction of the output size
    uint32_t width = 0, height = 0;  // Absolute
};

struct BufferInfo {
    VkDeviceSize size = 0;
};

enum class LoadOp : uint8_t { Clear, Load, DontCare };

struct ClearValue {
    float color[4] = {0, 0, 0, 0};
    float depth = 0.0f;  // reversed-Z: 0 is the far plane
    uint32_t stencil = 0;
};

// An image owned outside the graph (a readback target, a swapchain image, a
// persistent texture). `initial` is the state it is in when the frame starts;
// `final`, if set, the state the graph leaves it in.
struct ImportedImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    uint32_t width = 0, height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    AccessState initial;
    std::optional<AccessState> final_state;
};

struct ImportedBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    AccessState initial;
    std::optional<AccessState> final_state;
};

enum class RecordingKind : uint8_t { DynamicRendering, RenderPassObject };

// How a sampled image is read: filtered bilinearly with clamped edges (the default), or nearest:
// for formats without linear filtering (depth) and for texelFetch reads, where no filter applies.
enum class Filter : uint8_t { Linear, Nearest };

// One declared use of a resource by a pass.
struct ResourceUse {
    uint32_t resource;
    uint32_t version_read;     // version the pass sees
    uint32_t version_written;  // version it produces (== version_read for reads)
    Use use;
    VkPipelineStageFlags2 shader_stages;
    LoadOp load = LoadOp::Clear;
    ClearValue clear;
    // The shader resource the use is bound to (PassContext::bind): a block's type name or a
    // sampler's or image's variable name; empty for a use no descriptor carries.
    std::string binding;
    Filter filter = Filter::Linear;  // sampled reads
    // A write that leaves only this rectangle of the image defined (PassBuilder::defines_only):
    // the finite check scans it alone. Not part of the physical signature: it may move each frame.
    std::optional<VkRect2D> defined_region;
};

struct ResourceDecl {
    std::string name;
    bool is_image = true;
    bool imported = false;
    ImageInfo image;
    BufferInfo buffer;
    ImportedImage imported_image;
    ImportedBuffer imported_buffer;
    uint32_t version = 0;                     // current version
    std::vector<uint32_t> writer_of_version;  // pass index that produced version v (v >= 1)
    VkImageUsageFlags image_usage = 0;        // union of declared uses
    VkBufferUsageFlags buffer_usage = 0;
};

// A pass's execute function with what it captured, both in the graph's PassArena: calling it
// runs the pass's execute with its Data. Empty until add_pass sets it.
class PassCallback {
public:
    PassCallback() = default;
    template <class Closure>
    explicit PassCallback(Closure& closure)
        : closure_(&closure), invoke_([](void* c, PassContext& context) { (*static_cast<Closure*>(c))(context); }) {}
    void operator()(PassContext& context) const { invoke_(closure_, context); }
    explicit operator bool() const { return invoke_ != nullptr; }

private:
    void* closure_ = nullptr;
    void (*invoke_)(void*, PassContext&) = nullptr;
};

struct PassDecl {
    std::string name;
    PassKind kind;
    std::vector<ResourceUse> uses;
    bool side_effect = false;
    std::optional<EffectTag> serves;
    std::optional<RecordingKind> recording;  // overrides the graph's default
    std::string note;                        // what the pass decided, for describe()
    PassCallback execute;
};

class FrameGraph;

class PassBuilder {
public:
    ImageHandle create_image(std::string_view name, const ImageInfo& info);
    BufferHandle create_buffer(std::string_view name, const BufferInfo& info);

    // Reads return the handle they were given; writes return the next version.
    ImageHandle sample(ImageHandle image, VkPipelineStageFlags2 shader_stages = 0);
    ImageHandle read_storage(ImageHandle image, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] ImageHandle write_storage(ImageHandle image, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] ImageHandle read_write_storage(ImageHandle image, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] ImageHandle color_attachment(ImageHandle image, LoadOp load = LoadOp::Clear,
                                               const ClearValue& clear = {});
    [[nodiscard]] ImageHandle depth_stencil_attachment(ImageHandle image, LoadOp load = LoadOp::Clear,
                                                       const ClearValue& clear = {});
    ImageHandle depth_stencil_read_only(ImageHandle image);
    ImageHandle copy_source(ImageHandle image);
    [[nodiscard]] ImageHandle copy_destination(ImageHandle image);

    BufferHandle uniform_buffer(BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);
    BufferHandle read_storage(BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] BufferHandle write_storage(BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] BufferHandle read_write_storage(BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);

    // The same shader reads and writes, each bound to the shader resource named `binding` (a
    // block's type name, as `Flux` in `buffer Flux { ... };`, else the variable's name, as
    // `source` in `uniform sampler2D source;`). PassContext::bind then pushes every binding that
    // a pipeline's shaders use from these declarations: a pass names each resource once.
    ImageHandle sample(std::string_view binding, ImageHandle image, Filter filter = Filter::Linear,
                       VkPipelineStageFlags2 shader_stages = 0);
    ImageHandle read_storage(std::string_view binding, ImageHandle image, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] ImageHandle write_storage(std::string_view binding, ImageHandle image,
                                            VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] ImageHandle read_write_storage(std::string_view binding, ImageHandle image,
                                                 VkPipelineStageFlags2 shader_stages = 0);
    BufferHandle uniform_buffer(std::string_view binding, BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);
    BufferHandle read_storage(std::string_view binding, BufferHandle buffer, VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] BufferHandle write_storage(std::string_view binding, BufferHandle buffer,
                                             VkPipelineStageFlags2 shader_stages = 0);
    [[nodiscard]] BufferHandle read_write_storage(std::string_view binding, BufferHandle buffer,
                                                  VkPipelineStageFlags2 shader_stages = 0);

    BufferHandle vertex_buffer(BufferHandle buffer);
    BufferHandle index_buffer(BufferHandle buffer);
    BufferHandle indirect_buffer(BufferHandle buffer);
    BufferHandle copy_source(BufferHandle buffer);
    [[nodiscard]] BufferHandle copy_destination(BufferHandle buffer);

    // The pass must run even if nothing reads its outputs (e.g. it writes a file).
    void side_effect();
    // The pass exists for this effect; it is culled when the frame does not need it.
    void serves(EffectTag effect);
    void record_with(RecordingKind kind);
    // One line on what the pass decided for this frame (e.g. what it leaves out, and why), printed
    // under the pass by FrameGraph::describe().
    void note(std::string text);
    // The pass writes only `region` of `written` (the version its write returned): the rest of the
    // image stays undefined this frame, and every later reader promises to read within the region.
    // The finite check scans the region alone.
    void defines_only(ImageHandle written, VkRect2D region);

private:
    friend class FrameGraph;
    PassBuilder(FrameGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    template <class Tag>
    Handle<Tag> use(Handle<Tag> handle, Use use, VkPipelineStageFlags2 stages, LoadOp load = LoadOp::Clear,
                    const ClearValue& clear = {});
    // `use` bound to the shader resource `binding`.
    template <class Tag>
    Handle<Tag> bound(std::string_view binding, Handle<Tag> handle, Use use, VkPipelineStageFlags2 stages,
                      Filter filter = Filter::Linear);
    FrameGraph& graph_;
    uint32_t pass_;
};

// Why a pass does not run.
struct CulledPass {
    std::string name;
    std::string reason;
};

// What compile() derives. Positions index passes in execution order.
struct CompiledGraph {
    std::vector<uint32_t> order;  // pass indices, execution order
    std::vector<CulledPass> culled;
    std::vector<ResourceTimeline> timelines;    // per resource (index = resource)
    std::vector<bool> resource_live;            // used by at least one living pass
    std::vector<uint32_t> first_use, last_use;  // execution positions, for live resources
    BarrierPlan barriers;
    AliasPlan aliasing;                       // transients only, estimated sizes
    std::vector<uint32_t> aliased_resources;  // resource index of each aliasing request
    uint32_t output_width = 0, output_height = 0;
};

class FrameGraph {
public:
    explicit FrameGraph(FrameNeeds needs = {});

    ImageHandle import_image(std::string_view name, const ImportedImage& image);
    BufferHandle import_buffer(std::string_view name, const ImportedBuffer& buffer);

    // Starts a new declaration in this graph's storage: the passes, resources and uses of the last
    // one, their names' buffers and the arena of their captures are kept for the next to fill, so a
    // frame declared into a cleared graph allocates next to nothing (the renderer declares each
    // frame into the graph of two frames before).
    void clear(FrameNeeds needs);
    // The same, keeping the graph's needs and their storage, for the next declaration to decide
    // its own into them through needs_to_decide().
    void clear();
    // The needs of the declaration to come, to be decided in place of the last ones (the renderer
    // decides every frame's needs into the strings of the graph's last reasons: fg::FrameNeeds::clear).
    // Only before the declaration's first pass or resource.
    FrameNeeds& needs_to_decide();

    // Data lives in the graph's arena until clear() or the graph's end, as does `execute`.
    template <class Data, class Setup, class Execute>
    const Data& add_pass(std::string_view name, PassKind kind, Setup&& setup, Execute&& execute) {
        const uint32_t index = add_pass_decl(name, kind);
        struct Closure {
            explicit Closure(Execute&& e) : execute(std::forward<Execute>(e)) {}
            void operator()(PassContext& context) { execute(data, context); }
            Data data{};
            std::decay_t<Execute> execute;
        };
        Closure& closure = arena_.make<Closure>(std::forward<Execute>(execute));
        PassBuilder builder(*this, index);
        setup(builder, closure.data);
        passes_[index].execute = PassCallback(closure);
        return closure.data;
    }

    // A requested output keeps the passes that produce it (transitively) alive.
    void request_output(ImageHandle image);
    void request_output(BufferHandle buffer);

    void set_default_recording(RecordingKind kind) { default_recording_ = kind; }
    RecordingKind recording_of(uint32_t pass) const;

    Blackboard& blackboard() { return blackboard_; }
    const FrameNeeds& needs() const { return needs_; }

    // Culling, ordering, lifetimes, barriers and an aliasing estimate. Pure: no GPU.
    // `previous` (optional): the last frame's graph. Where it was compiled at the same size and
    // compiles_like this one, its result is taken over (moved: `previous` is left uncompiled)
    // instead of derived again, with only the culled passes' reasons written anew. A running clock
    // or a moved slider changes what the passes capture, not what they declare, so most frames
    // take this path. The result taken over is the one `previous` ended with: if an executor
    // applied its memory plan to it (FrameExecutor::adopt), the plan comes with it.
    const CompiledGraph& compile(uint32_t output_width, uint32_t output_height, FrameGraph* previous = nullptr);
    // Whether the last compile() took its result over from `previous`.
    bool took_over_compilation() const { return taken_over_from_ != nullptr; }
    // Whether compile() would derive the same graph from this declaration as from `other`'s
    // (same_declaration.cpp says what that compares).
    bool compiles_like(const FrameGraph& other) const;
    const CompiledGraph& compiled() const;
    bool is_compiled() const { return compiled_.has_value(); }

    // Recomputes the barrier plan with aliasing predecessors from a real memory plan
    // (the executor calls this after querying memory requirements).
    void apply_aliasing(const AliasPlan& plan, const std::vector<uint32_t>& aliased_resources);

    const std::vector<PassDecl>& passes() const { return passes_; }
    const std::vector<ResourceDecl>& resources() const { return resources_; }
    uint32_t image_width(uint32_t resource) const;
    uint32_t image_height(uint32_t resource) const;
    // Bytes of a resource's texels or buffer (images: width x height x texel size, one mip level).
    uint64_t resource_bytes(uint32_t resource) const;
    // Whether `use` brings its resource into the frame (its first version, not imported), and the
    // bytes of all that pass `pass` brings: a method's memory is the sum over its passes.
    bool creates(const ResourceUse& use) const;
    uint64_t created_bytes(uint32_t pass) const;

    // Everything of the compiled graph that becomes a Vulkan object (transients with their
    // lifetimes, imports, living passes and their uses): an executor realized for one graph
    // runs any other graph with the same signature (FrameExecutor::adopt).
    std::string physical_signature() const;
    // Whether this graph's physical signature is `previous`'s, known without writing either out:
    // where the last compile() took over `previous`'s compilation (the same compiled graph from
    // the same declaration), what the signature adds is the imports' handles and the default
    // recording. False where that does not settle it; physical_signature() then tells.
    bool keeps_physical_signature_of(const FrameGraph* previous) const;

    // Printable forms, for `vkwater passes` and golden tests.
    std::string describe() const;
    std::string dump_barriers() const;
    std::string to_dot() const;

private:
    friend class PassBuilder;
    uint32_t add_pass_decl(std::string_view name, PassKind kind);
    // `decl` named `name` (its name and writers in the buffers clear() kept, where there are some).
    uint32_t add_resource(std::string_view name, ResourceDecl decl);
    void check_current(uint32_t pass, uint32_t resource, uint32_t version, const char* verb) const;
    void check_requestable(uint32_t resource, uint32_t version) const;
    std::vector<ResourceTimeline> build_timelines(const std::vector<uint32_t>& order) const;
    // Why pass `pass`, which compile() culled, does not run.
    std::string culled_reason(uint32_t pass) const;

    // Room for what a frame usually declares (the built-in scenes: about 25 to 35 passes with the
    // readbacks, most of them using fewer than 8 resources); a larger graph only grows the vectors.
    static constexpr size_t kReservedPasses = 48, kReservedResources = 96, kReservedUses = 8;
    FrameNeeds needs_;
    std::vector<PassDecl> passes_;
    std::vector<ResourceDecl> resources_;
    // What clear() kept of the last declaration, emptied, for add_pass_decl and add_resource to
    // fill again with their buffers' capacity.
    std::vector<PassDecl> spare_passes_;
    std::vector<ResourceDecl> spare_resources_;
    PassArena arena_;
    std::vector<std::pair<uint32_t, uint32_t>> requested_;  // (resource, version)
    Blackboard blackboard_;
    RecordingKind default_recording_ = RecordingKind::DynamicRendering;
    std::optional<CompiledGraph> compiled_;
    const FrameGraph* taken_over_from_ = nullptr;  // the graph whose compilation the last compile() took
};

}  // namespace vkw::fg
