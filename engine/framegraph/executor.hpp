// Runs a compiled frame graph on a device: creates its transient resources (sharing
// memory where lifetimes do not overlap), records every living pass between debug
// labels with the derived barriers before it, begins and ends rendering for graphics
// passes (dynamic rendering or VkRenderPass objects), submits, and reports per-pass
// times. Optionally scans every float image a pass wrote for NaN/Inf.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/resources.hpp"

#include <string>
#include <vector>

namespace vkw::fg {

enum class TimingMode : uint8_t {
    Auto,        // fences on CPU devices (their timestamps leave out raster work), timestamps elsewhere
    None,        // one submission, whole-frame time only
    Timestamps,  // GPU timestamp queries around each pass
    Fences,      // each pass submitted alone and timed on the CPU clock
    // Note: Debian 12's synchronization validation checks hazards only within one
    // submission, so tests record with None (one command buffer for the frame).
};

struct ExecutorOptions {
    bool check_finite = false;  // scan each float image a pass writes, after the pass
    TimingMode timing = TimingMode::Auto;
};

struct PassTime {
    std::string pass;
    double ms = 0.0;
    uint64_t created_bytes = 0;  // the resources the pass brings into the frame (FrameGraph::created_bytes)
};

struct FrameReport {
    TimingMode method = TimingMode::None;  // the method that produced the figures
    std::vector<PassTime> passes;
    double total_ms = 0.0;
    std::string method_name() const;
};

class FrameExecutor {
public:
    // The graph must be compiled; it is kept by reference and must outlive the executor.
    FrameExecutor(Context& context, FrameGraph& graph, PipelineStore& pipelines, const ExecutorOptions& options);
    ~FrameExecutor();
    FrameExecutor(const FrameExecutor&) = delete;
    FrameExecutor& operator=(const FrameExecutor&) = delete;

    // Whether `graph` (compiled) can run on this executor's resources: its physical signature
    // is the one this executor was made for, under the same options.
    bool can_adopt(const FrameGraph& graph, const ExecutorOptions& options) const;
    // Runs `graph` from now on, on the same resources (can_adopt must hold): a frame declared
    // anew, with new values captured by its passes, creates no Vulkan object. `graph` must
    // outlive the executor or the next adopt.
    void adopt(FrameGraph& graph);

    // Records, submits and waits. Throws InternalError naming the pass, resource and
    // texel of the first non-finite value when check_finite is on.
    FrameReport execute();

    // Records the whole frame into `cmd` (begun by the caller, who submits it: the
    // window loop, with its swapchain semaphores). Finite checks are recorded too;
    // call scan_finite_checks() once the submission has completed.
    void record(VkCommandBuffer cmd);
    void scan_finite_checks();

    // Test hook: forget one derived barrier, to prove that validation sees the hazard.
    void drop_barrier_for_test(const std::string& pass, const std::string& resource);

    uint64_t transient_heap_bytes() const { return heap_bytes_; }
    uint64_t transient_unaliased_bytes() const { return unaliased_bytes_; }

    // For PassContext.
    Context& context() { return context_; }
    FrameGraph& graph() { return *graph_; }
    PipelineStore& pipelines() { return pipelines_; }
    VkImage image(uint32_t resource) const;
    VkImageView view(uint32_t resource) const;
    VkBuffer buffer(uint32_t resource) const;
    VkSampler linear_sampler() const { return linear_sampler_; }
    VkSampler nearest_sampler() const { return nearest_sampler_; }
    VkRenderPass render_pass(uint32_t pass) const { return render_passes_[pass]; }
    // The image layout the graph gives `resource` in `pass`.
    VkImageLayout layout_in_pass(uint32_t pass, uint32_t resource) const;

private:
    // A float image one pass wrote, copied to the host for the finite check.
    struct FiniteCheck {
        uint32_t pass;
        uint32_t resource;
        VkOffset2D offset;  // the scanned region's first texel in the image
        uint32_t width, height;
        VkFormat format;
        size_t buffer;  // index into finite_buffers_
    };
    // Auto made concrete: fences on CPU devices (their timestamps leave out raster work), else timestamps.
    TimingMode resolved_timing(TimingMode timing) const;
    void realize_resources(bool check_finite);

    void create_render_passes();
    void record_pass(VkCommandBuffer cmd, uint32_t position, std::vector<FiniteCheck>& checks);
    void record_barriers(VkCommandBuffer cmd, const std::vector<Barrier>& barriers) const;
    void begin_rendering(VkCommandBuffer cmd, uint32_t pass);
    void end_rendering(VkCommandBuffer cmd, uint32_t pass) const;
    void record_finite_checks(VkCommandBuffer cmd, uint32_t position, std::vector<FiniteCheck>& checks);
    void scan_finite_checks(const std::vector<FiniteCheck>& checks) const;
    std::vector<Buffer> finite_buffers_;       // host-visible copies of the checked images, kept across frames
    std::vector<FiniteCheck> pending_checks_;  // recorded by record(), scanned by scan_finite_checks()
    VkCommandBuffer begin_command_buffer(const std::string& name);
    double submit_and_wait(VkCommandBuffer cmd);

    Context& context_;
    PipelineStore& pipelines_;
    ExecutorOptions options_;
    FrameGraph* graph_;              // the graph it runs: the one it was made for, or one adopted since
    std::string signature_;          // graph_->physical_signature() of the graph it was made for
    AliasPlan alias_plan_;           // the transient heap's layout, handed to every adopted graph
    std::vector<uint32_t> aliased_;  // the resources placed in it
    std::vector<Image> images_;      // by resource index; empty for imported or unused resources
    std::vector<Buffer> buffers_;    // likewise
    std::vector<DeviceMemory> heaps_;
    uint64_t heap_bytes_ = 0;
    uint64_t unaliased_bytes_ = 0;
    VkSampler linear_sampler_ = VK_NULL_HANDLE;
    VkSampler nearest_sampler_ = VK_NULL_HANDLE;
    std::vector<VkRenderPass> render_passes_;  // by pass index; null unless recorded with a VkRenderPass
    std::vector<VkFramebuffer> framebuffers_;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkQueryPool query_pool_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace vkw::fg
