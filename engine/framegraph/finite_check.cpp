// Finite check mode: after a pass, every float colour image it wrote is copied to
// the host and scanned for NaN/Inf; the first offender is reported with the pass,
// the resource and the texel. The copy borrows the image between two barriers
// that return it to the state the graph's own barriers expect, so the derived
// barrier plan stays valid.
#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/vk/context.hpp"

#include <cmath>
#include <cstring>

namespace vkw::fg {

void FrameExecutor::record_finite_checks(VkCommandBuffer cmd, uint32_t position, std::vector<FiniteCheck>& checks) {
    const CompiledGraph& compiled = graph_->compiled();
    const uint32_t pass = compiled.order[position];
    for (const ResourceUse& use : graph_->passes()[pass].uses) {
        const ResourceDecl& decl = graph_->resources()[use.resource];
        if (use.version_written == use.version_read || !decl.is_image || !format_is_float_color(decl.image.format)) {
            continue;
        }
        if (decl.imported) continue;  // imported images may lack TRANSFER_SRC usage; their writers are checked by tests
        if (!checks.empty() && checks.back().resource == use.resource && checks.back().pass == pass) continue;
        AccessState in_pass{};
        for (const TimelineAccess& access : compiled.timelines[use.resource].accesses) {
            if (access.position == position) in_pass = access.state;
        }
        const uint32_t image_width = graph_->image_width(use.resource),
                       image_height = graph_->image_height(use.resource);
        // A pass that defines only part of the image (PassBuilder::defines_only) is checked there.
        const VkRect2D region = use.defined_region.value_or(VkRect2D{{0, 0}, {image_width, image_height}});
        const uint32_t width = region.extent.width, height = region.extent.height;
        if (width == 0 || height == 0) continue;
        // Sized for the whole image, so that a region that moves from frame to frame allocates nothing.
        const VkDeviceSize bytes = VkDeviceSize{image_width} * image_height * format_texel_bytes(decl.image.format);
        // The n-th check of a frame reuses the n-th buffer: a graph with the same signature checks
        // the same images in the same order, so frames after the first allocate nothing.
        const size_t slot = checks.size();
        if (slot >= finite_buffers_.size()) finite_buffers_.resize(slot + 1);
        if (finite_buffers_[slot].size() != bytes) {
            finite_buffers_[slot] =
                Buffer(context_, {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "finite check of " + decl.name);
        }
        const Buffer& readback = finite_buffers_[slot];

        const AccessState copy_state = access_state(Use::TransferSrc, PassKind::Transfer);
        const Barrier to_copy{use.resource, true, {in_pass.stages, in_pass.access, in_pass.layout}, copy_state};
        record_barriers(cmd, {to_copy});
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageOffset = {region.offset.x, region.offset.y, 0};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cmd, image(use.resource), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1,
                               &copy);
        // Back to the pass's own state; the copy only read, so no access to flush.
        const Barrier back{use.resource, true, {copy_state.stages, VK_ACCESS_2_NONE, copy_state.layout}, in_pass};
        record_barriers(cmd, {back});

        VkBufferMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        to_host.srcQueueFamilyIndex = to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        to_host.buffer = readback.handle();
        to_host.size = VK_WHOLE_SIZE;
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.bufferMemoryBarrierCount = 1;
        dependency.pBufferMemoryBarriers = &to_host;
        vkCmdPipelineBarrier2(cmd, &dependency);

        checks.push_back({pass, use.resource, region.offset, width, height, decl.image.format, slot});
    }
}

namespace {

bool half_is_finite(uint16_t bits) { return (bits & 0x7C00u) != 0x7C00u; }

uint32_t channels_of(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R16_SFLOAT: return 1;
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R16G16_SFLOAT: return 2;
        default: return 4;
    }
}

}  // namespace

void FrameExecutor::scan_finite_checks(const std::vector<FiniteCheck>& checks) const {
    for (const FiniteCheck& check : checks) {
        const uint32_t channels = channels_of(check.format);
        const bool half = format_texel_bytes(check.format) / channels == 2;
        const size_t values = size_t{check.width} * check.height * channels;
        const auto* bytes = static_cast<const unsigned char*>(finite_buffers_[check.buffer].mapped());
        for (size_t i = 0; i < values; ++i) {
            bool finite;
            float value;
            if (half) {
                uint16_t bits;
                std::memcpy(&bits, bytes + 2 * i, 2);
                finite = half_is_finite(bits);
                value = (bits & 0x3FFu) ? NAN : ((bits & 0x8000u) ? -INFINITY : INFINITY);
            } else {
                std::memcpy(&value, bytes + 4 * i, 4);
                finite = std::isfinite(value);
            }
            if (finite) continue;
            const size_t texel = i / channels;
            throw InternalError(
                "finite check: pass '" + graph_->passes()[check.pass].name + "' wrote " +
                (std::isnan(value) ? "NaN" : "Inf") + " into '" + graph_->resources()[check.resource].name +
                "' at texel (" + std::to_string(check.offset.x + texel % check.width) + ", " +
                std::to_string(check.offset.y + texel / check.width) + "), channel " + std::to_string(i % channels));
        }
    }
}

}  // namespace vkw::fg
