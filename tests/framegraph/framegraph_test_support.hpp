// Helpers shared by the frame-graph tests: declaring passes whose execute function is
// never called (compile() is pure), flattening a compiled barrier plan into records
// that compare field by field, and capturing error messages.
#pragma once

#include "engine/core/errors.hpp"
#include "engine/framegraph/frame_graph.hpp"
// The graph takes any enum as an effect tag; the tests tag their passes with the scene's effects.
#include "engine/scene/effects.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

namespace vkw::fg::test {

// Short names for the flags the expected barriers are written with.
inline constexpr VkPipelineStageFlags2 kNone = VK_PIPELINE_STAGE_2_NONE;
inline constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
inline constexpr VkPipelineStageFlags2 kVertexShader = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
inline constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
inline constexpr VkPipelineStageFlags2 kVertexInput = VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT;
inline constexpr VkPipelineStageFlags2 kColorOutput = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
inline constexpr VkPipelineStageFlags2 kCopy = VK_PIPELINE_STAGE_2_COPY_BIT;
inline constexpr VkPipelineStageFlags2 kHost = VK_PIPELINE_STAGE_2_HOST_BIT;

inline constexpr VkAccessFlags2 kNoAccess = VK_ACCESS_2_NONE;
inline constexpr VkAccessFlags2 kStorageRead = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
inline constexpr VkAccessFlags2 kStorageWrite = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
inline constexpr VkAccessFlags2 kSampledRead = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
inline constexpr VkAccessFlags2 kColorRead = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
inline constexpr VkAccessFlags2 kColorWrite = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
inline constexpr VkAccessFlags2 kTransferRead = VK_ACCESS_2_TRANSFER_READ_BIT;
inline constexpr VkAccessFlags2 kTransferWrite = VK_ACCESS_2_TRANSFER_WRITE_BIT;
inline constexpr VkAccessFlags2 kHostRead = VK_ACCESS_2_HOST_READ_BIT;
inline constexpr VkAccessFlags2 kVertexRead = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT;
inline constexpr VkAccessFlags2 kUniformRead = VK_ACCESS_2_UNIFORM_READ_BIT;

inline constexpr VkImageLayout kUndefined = VK_IMAGE_LAYOUT_UNDEFINED;
inline constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL;
inline constexpr VkImageLayout kShaderRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
inline constexpr VkImageLayout kColorAttachment = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
inline constexpr VkImageLayout kTransferSrc = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;

struct NoData {};

// Declares a pass; its execute function is an empty lambda that these tests never call.
inline void add_pass(FrameGraph& graph, std::string name, PassKind kind,
                     const std::function<void(PassBuilder&)>& setup) {
    graph.add_pass<NoData>(
        std::move(name), kind, [&](PassBuilder& builder, NoData&) { setup(builder); },
        [](const NoData&, PassContext&) {});
}

// A 64x64 image of a fixed size (so the aliasing estimate does not depend on the output size).
inline ImageInfo small_image(VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t size = 64) {
    return {format, SizeClass::Absolute, 1.0f, size, size};
}

// A readback buffer owned outside the graph, handed back for the CPU to read.
inline ImportedBuffer readback_buffer(VkDeviceSize size = 4096) {
    return {VK_NULL_HANDLE, size, {}, AccessState{kHost, kHostRead}};
}

// Living pass names in execution order.
inline std::vector<std::string> order_names(const FrameGraph& graph) {
    std::vector<std::string> names;
    for (uint32_t pass : graph.compiled().order) names.push_back(graph.passes()[pass].name);
    return names;
}

// The reason a pass was culled, or "" when it was not.
inline std::string culled_reason(const FrameGraph& graph, const std::string& pass) {
    for (const CulledPass& culled : graph.compiled().culled) {
        if (culled.name == pass) return culled.reason;
    }
    return "";
}

// One barrier of a compiled plan, with names instead of indices.
struct BarrierRecord {
    std::string before;  // the pass it precedes, or "after all"
    std::string resource;
    bool is_image = true;
    AccessState src, dst;  // stages, access, layout (UNDEFINED for buffers)

    bool operator==(const BarrierRecord&) const = default;
};

inline BarrierRecord image_barrier(std::string before, std::string resource, AccessState src, AccessState dst) {
    return {std::move(before), std::move(resource), true, src, dst};
}

inline BarrierRecord buffer_barrier(std::string before, std::string resource, AccessState src, AccessState dst) {
    return {std::move(before), std::move(resource), false, src, dst};
}

inline std::string describe_state(const AccessState& state) {
    return stage_names(state.stages) + "/" + access_names(state.access) + "/" + layout_name(state.layout);
}

// gtest prints mismatching records with this.
inline void PrintTo(const BarrierRecord& record, std::ostream* out) {
    *out << "before '" << record.before << "': " << (record.is_image ? "image '" : "buffer '") << record.resource
         << "' " << describe_state(record.src) << " -> " << describe_state(record.dst);
}

// Every barrier of the compiled plan, in the order it is recorded.
inline std::vector<BarrierRecord> barriers_of(const FrameGraph& graph) {
    const CompiledGraph& compiled = graph.compiled();
    std::vector<BarrierRecord> records;
    auto add = [&](const std::string& before, const Barrier& barrier) {
        records.push_back(
            {before, compiled.timelines[barrier.resource].name, barrier.is_image, barrier.src, barrier.dst});
    };
    for (size_t position = 0; position < compiled.barriers.before_pass.size(); ++position) {
        for (const Barrier& barrier : compiled.barriers.before_pass[position]) {
            add(graph.passes()[compiled.order[position]].name, barrier);
        }
    }
    for (const Barrier& barrier : compiled.barriers.after_last_pass) add("after all", barrier);
    return records;
}

// Runs `action`, which must throw vkw::InternalError, and returns its message
// ("" and a test failure otherwise).
inline std::string internal_error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const InternalError& error) {
        return error.what();
    } catch (const std::exception& error) {
        ADD_FAILURE() << "expected an InternalError, got: " << error.what();
        return "";
    }
    ADD_FAILURE() << "expected an InternalError, nothing was thrown";
    return "";
}

// Expects `text` to contain every fragment.
inline void expect_contains(const std::string& text, std::initializer_list<std::string> fragments) {
    for (const std::string& fragment : fragments) {
        EXPECT_NE(text.find(fragment), std::string::npos) << "'" << fragment << "' is missing from: " << text;
    }
}

}  // namespace vkw::fg::test
