#include "engine/framegraph/executor.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <chrono>
#include <cmath>
#include <cstring>

namespace vkw::fg {

std::string FrameReport::method_name() const {
    switch (method) {
        case TimingMode::Timestamps: return "GPU timestamp queries";
        case TimingMode::Fences: return "one submission per pass, fence-timed on the CPU clock";
        case TimingMode::None:
        case TimingMode::Auto: break;
    }
    return "whole frame, fence-timed on the CPU clock";
}

TimingMode FrameExecutor::resolved_timing(TimingMode timing) const {
    if (timing != TimingMode::Auto) return timing;
    return context_.is_cpu_device() ? TimingMode::Fences : TimingMode::Timestamps;
}

FrameExecutor::FrameExecutor(Context& context, FrameGraph& graph, PipelineStore& pipelines,
                             const ExecutorOptions& options)
    : context_(context),
      pipelines_(pipelines),
      options_(options),
      graph_(&graph),
      signature_(graph.physical_signature()) {
    options_.timing = resolved_timing(options_.timing);
    // Finite checks copy each written float image right after its pass, inside the
    // same command buffer, and are scanned in pass order once the frame is done, so
    // the first offender is still named and a single-submission frame stays one
    // submission (synchronization validation sees hazards only within one).
    VkDevice device = context_.device();
    const VkAllocationCallbacks* allocator = context_.allocator();

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = context_.queue_family();
    VKW_CHECK(vkCreateCommandPool(device, &pool_info, allocator, &command_pool_), "frame graph command pool");
    context_.set_name(command_pool_, VK_OBJECT_TYPE_COMMAND_POOL, "frame graph command pool");
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VKW_CHECK(vkCreateFence(device, &fence_info, allocator, &fence_), "frame graph fence");
    context_.set_name(fence_, VK_OBJECT_TYPE_FENCE, "frame graph fence");

    VkSamplerCreateInfo sampler_info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler_info.magFilter = sampler_info.minFilter = VK_FILTER_LINEAR;
    sampler_info.addressModeU = sampler_info.addressModeV = sampler_info.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler_info.maxLod = 0.0f;
    VKW_CHECK(vkCreateSampler(device, &sampler_info, allocator, &linear_sampler_), "linear sampler");
    context_.set_name(linear_sampler_, VK_OBJECT_TYPE_SAMPLER, "linear clamp sampler");
    // For formats without linear filtering (depth): validation checks the sampler's filter
    // against the format even where the shader only uses texelFetch.
    sampler_info.magFilter = sampler_info.minFilter = VK_FILTER_NEAREST;
    VKW_CHECK(vkCreateSampler(device, &sampler_info, allocator, &nearest_sampler_), "nearest sampler");
    context_.set_name(nearest_sampler_, VK_OBJECT_TYPE_SAMPLER, "nearest clamp sampler");

    realize_resources(options_.check_finite);
    create_render_passes();

    if (options_.timing == TimingMode::Timestamps) {
        VkQueryPoolCreateInfo query_info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        query_info.queryCount = static_cast<uint32_t>(2 * graph_->compiled().order.size() + 2);
        VKW_CHECK(vkCreateQueryPool(device, &query_info, allocator, &query_pool_), "timestamp query pool");
    }
}

FrameExecutor::~FrameExecutor() {
    VkDevice device = context_.device();
    const VkAllocationCallbacks* allocator = context_.allocator();
    vkDeviceWaitIdle(device);
    // Executors are made per window size and swapchain image: their names are dropped with them.
    for (VkFramebuffer framebuffer : framebuffers_) {
        context_.forget_name(framebuffer, VK_OBJECT_TYPE_FRAMEBUFFER);
        if (framebuffer) vkDestroyFramebuffer(device, framebuffer, allocator);
    }
    for (VkRenderPass render_pass : render_passes_) {
        context_.forget_name(render_pass, VK_OBJECT_TYPE_RENDER_PASS);
        if (render_pass) vkDestroyRenderPass(device, render_pass, allocator);
    }
    if (query_pool_) vkDestroyQueryPool(device, query_pool_, allocator);
    context_.forget_name(linear_sampler_, VK_OBJECT_TYPE_SAMPLER);
    if (linear_sampler_) vkDestroySampler(device, linear_sampler_, allocator);
    context_.forget_name(nearest_sampler_, VK_OBJECT_TYPE_SAMPLER);
    if (nearest_sampler_) vkDestroySampler(device, nearest_sampler_, allocator);
    context_.forget_name(fence_, VK_OBJECT_TYPE_FENCE);
    if (fence_) vkDestroyFence(device, fence_, allocator);
    context_.forget_name(command_pool_, VK_OBJECT_TYPE_COMMAND_POOL);
    if (command_pool_) vkDestroyCommandPool(device, command_pool_, allocator);
}

// ---------------------------------------------------------------- resources

void FrameExecutor::realize_resources(bool check_finite) {
    const CompiledGraph& compiled = graph_->compiled();
    const auto& resources = graph_->resources();
    images_.resize(resources.size());
    buffers_.resize(resources.size());

    // Create every transient unbound, then plan aliasing with the device's real sizes.
    std::vector<AliasRequest> requests;
    std::vector<uint32_t> aliased;
    std::vector<VkMemoryRequirements> requirements;
    uint32_t type_bits = ~0u;
    for (uint32_t r = 0; r < resources.size(); ++r) {
        const ResourceDecl& decl = resources[r];
        if (decl.imported || !compiled.resource_live[r]) continue;
        VkMemoryRequirements needs;
        if (decl.is_image) {
            VkImageUsageFlags usage = decl.image_usage;
            if (check_finite && format_is_float_color(decl.image.format)) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
            images_[r] = Image::create_unbound(
                context_, {graph_->image_width(r), graph_->image_height(r), decl.image.format, usage}, decl.name);
            needs = images_[r].memory_requirements();
        } else {
            buffers_[r] = Buffer::create_unbound(context_, {decl.buffer.size, decl.buffer_usage, false}, decl.name);
            needs = buffers_[r].memory_requirements();
        }
        requests.push_back({needs.size, needs.alignment, compiled.first_use[r], compiled.last_use[r]});
        requirements.push_back(needs);
        aliased.push_back(r);
        type_bits &= needs.memoryTypeBits;
    }
    if (aliased.empty()) {
        graph_->apply_aliasing({}, {});
        alias_plan_ = {};
        aliased_.clear();
        return;
    }
    if (type_bits == 0) {
        throw InternalError("frame graph: the transient resources share no memory type; aliasing is impossible");
    }
    AliasPlan plan = plan_aliasing(requests);
    heaps_.emplace_back(context_, plan.heap_size, type_bits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                        "frame graph transient heap");
    heap_bytes_ = plan.heap_size;
    unaliased_bytes_ = plan.unaliased_size;
    for (size_t i = 0; i < aliased.size(); ++i) {
        const uint32_t r = aliased[i];
        if (resources[r].is_image) {
            images_[r].bind(context_, heaps_.back().handle(), plan.offsets[i], resources[r].name);
        } else {
            buffers_[r].bind(heaps_.back().handle(), plan.offsets[i], resources[r].name);
        }
    }
    graph_->apply_aliasing(plan, aliased);
    alias_plan_ = std::move(plan);
    aliased_ = std::move(aliased);
}

bool FrameExecutor::can_adopt(const FrameGraph& graph, const ExecutorOptions& options) const {
    if (options.check_finite != options_.check_finite || resolved_timing(options.timing) != options_.timing) {
        return false;
    }
    // graph_'s signature is signature_ (this executor was made for it or adopted it); a graph that
    // took over its compilation keeps it where the imports are the same, and most frames do.
    return graph.keeps_physical_signature_of(graph_) || graph.physical_signature() == signature_;
}

void FrameExecutor::adopt(FrameGraph& graph) {
    graph_ = &graph;
    // The same memory plan, so the new graph's aliasing barriers are the ones recorded before. A
    // compilation taken over from the graph this executor ran (FrameGraph::compile) carries them
    // already: compile() and apply_aliasing() both end with the barriers of the plan they hold.
    const CompiledGraph& compiled = graph.compiled();
    if (compiled.aliasing == alias_plan_ && compiled.aliased_resources == aliased_) return;
    graph_->apply_aliasing(alias_plan_, aliased_);
}

VkImage FrameExecutor::image(uint32_t resource) const {
    const ResourceDecl& decl = graph_->resources()[resource];
    return decl.imported ? decl.imported_image.image : images_[resource].handle();
}

VkImageView FrameExecutor::view(uint32_t resource) const {
    const ResourceDecl& decl = graph_->resources()[resource];
    return decl.imported ? decl.imported_image.view : images_[resource].view();
}

VkBuffer FrameExecutor::buffer(uint32_t resource) const {
    const ResourceDecl& decl = graph_->resources()[resource];
    return decl.imported ? decl.imported_buffer.buffer : buffers_[resource].handle();
}

VkImageLayout FrameExecutor::layout_in_pass(uint32_t pass, uint32_t resource) const {
    const CompiledGraph& compiled = graph_->compiled();
    for (const TimelineAccess& access : compiled.timelines[resource].accesses) {
        if (compiled.order[access.position] == pass) return access.state.layout;
    }
    throw InternalError("pass '" + graph_->passes()[pass].name + "' did not declare '" +
                        graph_->resources()[resource].name + "'");
}

// ---------------------------------------------------------------- render passes

namespace {

VkAttachmentLoadOp vk_load_op(LoadOp load) {
    switch (load) {
        case LoadOp::Clear: return VK_ATTACHMENT_LOAD_OP_CLEAR;
        case LoadOp::Load: return VK_ATTACHMENT_LOAD_OP_LOAD;
        case LoadOp::DontCare: return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    }
    return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
}

bool is_color_attachment(Use use) { return use == Use::ColorAttachmentWrite || use == Use::ColorAttachmentBlend; }

// A read-only depth-stencil attachment stores nothing (VK_ATTACHMENT_STORE_OP_NONE, core in Vulkan
// 1.3): with STORE its end of pass counts as a write, which the graph's barriers, made for a read,
// do not cover (synchronization validation reports a later sampled read as a hazard).
VkAttachmentStoreOp store_op(Use use) {
    return use == Use::DepthStencilReadOnly ? VK_ATTACHMENT_STORE_OP_NONE : VK_ATTACHMENT_STORE_OP_STORE;
}

// Attachments of a graphics pass: colours in declaration order, then the depth-stencil.
std::vector<const ResourceUse*> attachments_of(const PassDecl& pass) {
    std::vector<const ResourceUse*> colors, depth;
    for (const ResourceUse& use : pass.uses) {
        if (is_color_attachment(use.use)) colors.push_back(&use);
        if (use.use == Use::DepthStencilWrite || use.use == Use::DepthStencilReadOnly) depth.push_back(&use);
    }
    if (depth.size() > 1) throw InternalError("pass '" + pass.name + "' declares two depth-stencil attachments");
    colors.insert(colors.end(), depth.begin(), depth.end());
    return colors;
}

}  // namespace

void FrameExecutor::create_render_passes() {
    const CompiledGraph& compiled = graph_->compiled();
    render_passes_.assign(graph_->passes().size(), VK_NULL_HANDLE);
    framebuffers_.assign(graph_->passes().size(), VK_NULL_HANDLE);
    for (uint32_t pass : compiled.order) {
        const PassDecl& decl = graph_->passes()[pass];
        if (decl.kind != PassKind::Graphics || graph_->recording_of(pass) != RecordingKind::RenderPassObject) continue;
        std::vector<VkAttachmentDescription> descriptions;
        std::vector<VkAttachmentReference> color_refs;
        VkAttachmentReference depth_ref{VK_ATTACHMENT_UNUSED, VK_IMAGE_LAYOUT_UNDEFINED};
        std::vector<VkImageView> views;
        VkExtent2D extent{};
        for (const ResourceUse* use : attachments_of(decl)) {
            const ResourceDecl& resource = graph_->resources()[use->resource];
            // The graph's barriers put the image in its layout before the render pass
            // begins, so the render pass itself transitions nothing.
            const VkImageLayout layout = layout_in_pass(pass, use->resource);
            VkAttachmentDescription description{};
            description.format = resource.image.format;
            description.samples = VK_SAMPLE_COUNT_1_BIT;
            description.loadOp = vk_load_op(use->load);
            description.storeOp = store_op(use->use);
            description.stencilLoadOp =
                format_has_stencil(resource.image.format) ? vk_load_op(use->load) : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
            description.stencilStoreOp =
                format_has_stencil(resource.image.format) ? store_op(use->use) : VK_ATTACHMENT_STORE_OP_DONT_CARE;
            description.initialLayout = description.finalLayout = layout;
            const VkAttachmentReference reference{static_cast<uint32_t>(descriptions.size()), layout};
            if (is_color_attachment(use->use)) {
                color_refs.push_back(reference);
            } else {
                depth_ref = reference;
            }
            descriptions.push_back(description);
            views.push_back(view(use->resource));
            extent = {graph_->image_width(use->resource), graph_->image_height(use->resource)};
        }
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = static_cast<uint32_t>(color_refs.size());
        subpass.pColorAttachments = color_refs.data();
        subpass.pDepthStencilAttachment = depth_ref.attachment == VK_ATTACHMENT_UNUSED ? nullptr : &depth_ref;
        VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        info.attachmentCount = static_cast<uint32_t>(descriptions.size());
        info.pAttachments = descriptions.data();
        info.subpassCount = 1;
        info.pSubpasses = &subpass;
        VKW_CHECK(vkCreateRenderPass(context_.device(), &info, context_.allocator(), &render_passes_[pass]),
                  "render pass of '" + decl.name + "'");
        context_.set_name(render_passes_[pass], VK_OBJECT_TYPE_RENDER_PASS, decl.name);

        VkFramebufferCreateInfo framebuffer_info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        framebuffer_info.renderPass = render_passes_[pass];
        framebuffer_info.attachmentCount = static_cast<uint32_t>(views.size());
        framebuffer_info.pAttachments = views.data();
        framebuffer_info.width = extent.width;
        framebuffer_info.height = extent.height;
        framebuffer_info.layers = 1;
        VKW_CHECK(vkCreateFramebuffer(context_.device(), &framebuffer_info, context_.allocator(), &framebuffers_[pass]),
                  "framebuffer of '" + decl.name + "'");
        context_.set_name(framebuffers_[pass], VK_OBJECT_TYPE_FRAMEBUFFER, decl.name);
    }
}

// ---------------------------------------------------------------- recording

void FrameExecutor::record_barriers(VkCommandBuffer cmd, const std::vector<Barrier>& barriers) const {
    if (barriers.empty()) return;
    std::vector<VkImageMemoryBarrier2> image_barriers;
    std::vector<VkBufferMemoryBarrier2> buffer_barriers;
    for (const Barrier& barrier : barriers) {
        if (barrier.is_image) {
            VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
            b.srcStageMask = barrier.src.stages;
            b.srcAccessMask = barrier.src.access;
            b.dstStageMask = barrier.dst.stages;
            b.dstAccessMask = barrier.dst.access;
            b.oldLayout = barrier.src.layout;
            b.newLayout = barrier.dst.layout;
            b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.image = image(barrier.resource);
            b.subresourceRange = {format_aspect(graph_->resources()[barrier.resource].image.format), 0, 1, 0, 1};
            image_barriers.push_back(b);
        } else {
            VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
            b.srcStageMask = barrier.src.stages;
            b.srcAccessMask = barrier.src.access;
            b.dstStageMask = barrier.dst.stages;
            b.dstAccessMask = barrier.dst.access;
            b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.buffer = buffer(barrier.resource);
            b.size = VK_WHOLE_SIZE;
            buffer_barriers.push_back(b);
        }
    }
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = static_cast<uint32_t>(image_barriers.size());
    dependency.pImageMemoryBarriers = image_barriers.data();
    dependency.bufferMemoryBarrierCount = static_cast<uint32_t>(buffer_barriers.size());
    dependency.pBufferMemoryBarriers = buffer_barriers.data();
    vkCmdPipelineBarrier2(cmd, &dependency);
}

void FrameExecutor::begin_rendering(VkCommandBuffer cmd, uint32_t pass) {
    const PassDecl& decl = graph_->passes()[pass];
    const auto attachments = attachments_of(decl);
    if (attachments.empty()) throw InternalError("graphics pass '" + decl.name + "' declares no attachment");
    const VkExtent2D extent{graph_->image_width(attachments.front()->resource),
                            graph_->image_height(attachments.front()->resource)};
    std::vector<VkClearValue> clears;
    for (const ResourceUse* use : attachments) {
        VkClearValue clear{};
        if (is_color_attachment(use->use)) {
            std::memcpy(clear.color.float32, use->clear.color, sizeof clear.color.float32);
        } else {
            clear.depthStencil = {use->clear.depth, use->clear.stencil};
        }
        clears.push_back(clear);
    }
    if (render_passes_[pass]) {
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = render_passes_[pass];
        begin.framebuffer = framebuffers_[pass];
        begin.renderArea = {{0, 0}, extent};
        begin.clearValueCount = static_cast<uint32_t>(clears.size());
        begin.pClearValues = clears.data();
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    } else {
        std::vector<VkRenderingAttachmentInfo> colors;
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        bool has_depth = false, has_stencil = false;
        for (size_t i = 0; i < attachments.size(); ++i) {
            const ResourceUse* use = attachments[i];
            VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
            info.imageView = view(use->resource);
            info.imageLayout = layout_in_pass(pass, use->resource);
            info.loadOp = vk_load_op(use->load);
            info.storeOp = store_op(use->use);
            info.clearValue = clears[i];
            if (is_color_attachment(use->use)) {
                colors.push_back(info);
            } else {
                depth = info;
                has_depth = true;
                has_stencil = format_has_stencil(graph_->resources()[use->resource].image.format);
            }
        }
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, extent};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = static_cast<uint32_t>(colors.size());
        rendering.pColorAttachments = colors.data();
        rendering.pDepthAttachment = has_depth ? &depth : nullptr;
        rendering.pStencilAttachment = has_stencil ? &depth : nullptr;
        vkCmdBeginRendering(cmd, &rendering);
    }
    // Flip Y so that +y is up in NDC as in OpenGL and glTF; row 0 of the image is the top.
    const VkViewport viewport{0.0f,
                              static_cast<float>(extent.height),
                              static_cast<float>(extent.width),
                              -static_cast<float>(extent.height),
                              0.0f,
                              1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void FrameExecutor::end_rendering(VkCommandBuffer cmd, uint32_t pass) const {
    if (render_passes_[pass]) {
        vkCmdEndRenderPass(cmd);
    } else {
        vkCmdEndRendering(cmd);
    }
}

void FrameExecutor::record_pass(VkCommandBuffer cmd, uint32_t position, std::vector<FiniteCheck>& checks) {
    const CompiledGraph& compiled = graph_->compiled();
    const uint32_t pass = compiled.order[position];
    const PassDecl& decl = graph_->passes()[pass];
    record_barriers(cmd, compiled.barriers.before_pass[position]);
    context_.begin_label(cmd, decl.name);
    if (decl.kind == PassKind::Graphics) begin_rendering(cmd, pass);
    PassContext pass_context(*this, cmd, pass);
    decl.execute(pass_context);
    if (decl.kind == PassKind::Graphics) end_rendering(cmd, pass);
    context_.end_label(cmd);
    if (options_.check_finite) record_finite_checks(cmd, position, checks);
    if (position + 1 == compiled.order.size()) record_barriers(cmd, compiled.barriers.after_last_pass);
}

void FrameExecutor::drop_barrier_for_test(const std::string& pass, const std::string& resource) {
    const CompiledGraph& compiled = graph_->compiled();
    for (size_t position = 0; position < compiled.order.size(); ++position) {
        if (graph_->passes()[compiled.order[position]].name != pass) continue;
        auto& barriers = const_cast<CompiledGraph&>(compiled).barriers.before_pass[position];
        std::erase_if(barriers, [&](const Barrier& b) { return compiled.timelines[b.resource].name == resource; });
    }
}

// ---------------------------------------------------------------- submission and timing

VkCommandBuffer FrameExecutor::begin_command_buffer(const std::string& name) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = command_pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VKW_CHECK(vkAllocateCommandBuffers(context_.device(), &alloc, &cmd), name);
    context_.set_name(cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, name);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VKW_CHECK(vkBeginCommandBuffer(cmd, &begin), name);
    return cmd;
}

double FrameExecutor::submit_and_wait(VkCommandBuffer cmd) {
    VKW_CHECK(vkEndCommandBuffer(cmd), "frame command buffer");
    VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmd_info.commandBuffer = cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd_info;
    const auto start = std::chrono::steady_clock::now();
    VKW_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, fence_), "frame submission");
    VKW_CHECK(vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX), "frame fence");
    const auto end = std::chrono::steady_clock::now();
    VKW_CHECK(vkResetFences(context_.device(), 1, &fence_), "frame fence");
    vkFreeCommandBuffers(context_.device(), command_pool_, 1, &cmd);
    return std::chrono::duration<double, std::milli>(end - start).count();
}

void FrameExecutor::record(VkCommandBuffer cmd) {
    pending_checks_.clear();
    for (uint32_t position = 0; position < graph_->compiled().order.size(); ++position) {
        record_pass(cmd, position, pending_checks_);
    }
}

void FrameExecutor::scan_finite_checks() {
    scan_finite_checks(pending_checks_);
    pending_checks_.clear();
}

FrameReport FrameExecutor::execute() {
    const CompiledGraph& compiled = graph_->compiled();
    FrameReport report;
    report.method = options_.timing;
    std::vector<FiniteCheck> checks;
    const size_t count = compiled.order.size();
    if (count == 0) return report;

    if (options_.timing == TimingMode::Fences) {
        for (uint32_t position = 0; position < count; ++position) {
            const std::string& name = graph_->passes()[compiled.order[position]].name;
            VkCommandBuffer cmd = begin_command_buffer(name);
            record_pass(cmd, position, checks);
            const double ms = submit_and_wait(cmd);
            report.passes.push_back({name, ms, graph_->created_bytes(compiled.order[position])});
            report.total_ms += ms;
            scan_finite_checks(checks);  // before the next pass, so the first offender is named
            checks.clear();
        }
        return report;
    }

    VkCommandBuffer cmd = begin_command_buffer("frame");
    const bool timestamps = options_.timing == TimingMode::Timestamps;
    if (timestamps) {
        vkCmdResetQueryPool(cmd, query_pool_, 0, static_cast<uint32_t>(2 * count));
        for (uint32_t position = 0; position < count; ++position) {
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, query_pool_, 2 * position);
            record_pass(cmd, position, checks);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, query_pool_, 2 * position + 1);
        }
    } else {
        record(cmd);
        checks = std::move(pending_checks_);
    }
    report.total_ms = submit_and_wait(cmd);
    scan_finite_checks(checks);
    if (timestamps) {
        std::vector<uint64_t> ticks(2 * count);
        VKW_CHECK(vkGetQueryPoolResults(context_.device(), query_pool_, 0, static_cast<uint32_t>(ticks.size()),
                                        ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "timestamp queries");
        const double period_ns = context_.properties().limits.timestampPeriod;
        for (uint32_t position = 0; position < count; ++position) {
            report.passes.push_back(
                {graph_->passes()[compiled.order[position]].name,
                 static_cast<double>(ticks[2 * position + 1] - ticks[2 * position]) * period_ns * 1e-6,
                 graph_->created_bytes(compiled.order[position])});
        }
    }
    return report;
}

}  // namespace vkw::fg
