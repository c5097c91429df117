// add_godray_beams_pass (godrays_beams.hpp).
#include "passes/godrays/godrays_beams.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/water_surface.hpp"

#include <shader_structs/godrays/godray_beams.comp.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/godrays/godray_beams.comp, generated from its SPIR-V (tools/shader_structs).
using GodrayBeamsPush = glsl::godray_beams_comp::Push;

// A chunk of beam rows and the binding of the surface rows they read.
struct BeamChunk {
    uint32_t first_row = 0, rows = 0;
    uint32_t vertex_row0 = 0, vertex_base = 0;
    VkDeviceSize offset = 0, bytes = 0;
};

// Beam row j reads vertex rows floor(j R / G) .. floor((j + 1) R / G) + 1 (at most R). Chunks take
// as many beam rows as keep their vertex rows, plus the alignment slack before them, within one
// binding; the binding's offset is aligned down and the slack handed to the shader as vertex_base.
std::vector<BeamChunk> beam_chunks(uint32_t resolution, uint32_t grid, VkDeviceSize max_range, VkDeviceSize alignment) {
    const VkDeviceSize row_bytes = VkDeviceSize{resolution + 1} * kWaterVertexBytes;
    auto first_vertex_row = [&](uint32_t row) { return uint32_t(uint64_t{row} * resolution / grid); };
    auto last_vertex_row = [&](uint32_t row) {
        return std::min(resolution, uint32_t(uint64_t{row + 1} * resolution / grid) + 1);
    };
    std::vector<BeamChunk> chunks;
    for (uint32_t row = 0; row < grid;) {
        BeamChunk chunk;
        chunk.first_row = row;
        chunk.vertex_row0 = first_vertex_row(row);
        const VkDeviceSize start = VkDeviceSize{chunk.vertex_row0} * row_bytes;
        chunk.offset = start - start % alignment;
        chunk.vertex_base = uint32_t((start - chunk.offset) / kWaterVertexBytes);
        while (row < grid &&
               start - chunk.offset + VkDeviceSize{last_vertex_row(row) - chunk.vertex_row0 + 1} * row_bytes <=
                   max_range) {
            ++row;
        }
        if (row == chunk.first_row) {
            throw InternalError("godray beams: one row of " + std::to_string(resolution + 1) +
                                " surface vertices does not fit one storage binding");
        }
        chunk.rows = row - chunk.first_row;
        chunk.bytes = start - chunk.offset + VkDeviceSize{last_vertex_row(row - 1) - chunk.vertex_row0 + 1} * row_bytes;
        chunks.push_back(chunk);
    }
    return chunks;
}

}  // namespace

fg::BufferHandle add_godray_beams_pass(fg::FrameGraph& graph, const GodrayBeamInputs& inputs) {
    if (inputs.grid < 2 || inputs.grid > 1024 || inputs.surface_resolution < 1 || inputs.surface_resolution > 16384 ||
        !(inputs.max_depth > 0.0)) {
        throw InternalError("godray beams: grid " + std::to_string(inputs.grid) + ", surface resolution " +
                            std::to_string(inputs.surface_resolution) +
                            " or max_depth out of range (accepted: 2..1024, 1..16384, > 0)");
    }
    GodrayBeamsPush push{};
    push.resolution = inputs.surface_resolution;
    push.grid = inputs.grid;
    push.max_depth = static_cast<float>(std::min(inputs.max_depth, 1e30));
    const VkDeviceSize bytes = VkDeviceSize{inputs.grid} * inputs.grid * kGodrayBeamBytes;

    struct Data {
        fg::BufferHandle surface, beams;
        SunShadowReads shadow;
    };
    const auto& data = graph.add_pass<Data>(
        "godray beams", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.surface = builder.read_storage("Surface", inputs.surface);
            d.beams = builder.write_storage("Beams", builder.create_buffer("godray beams", {bytes}));
            if (graph.blackboard().has(keys::kSunShadow)) {
                d.shadow.declare(builder, &graph.blackboard().get(keys::kSunShadow));
            }
        },
        [push](const Data& d, fg::PassContext& context) {
            const bool shadow = static_cast<bool>(d.shadow);
            ComputePipelineDesc desc;
            desc.shader = ShaderVariant{"godrays/godray_beams.comp"}.define("VKWATER_SUN_SHADOW", shadow).file();
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
            for (const BeamChunk& chunk : beam_chunks(push.resolution, push.grid, limits.maxStorageBufferRange,
                                                      limits.minStorageBufferOffsetAlignment)) {
                GodrayBeamsPush p = push;
                p.first_row = chunk.first_row;
                p.rows = chunk.rows;
                p.vertex_row0 = chunk.vertex_row0;
                p.vertex_base = chunk.vertex_base;
                // The surface rows this chunk reads, in one binding.
                context.bind(pipeline, {context.storage_buffer("Surface", d.surface, chunk.offset, chunk.bytes)});
                context.push_constants(pipeline, p);
                context.dispatch(pipeline, push.grid, chunk.rows);
            }
        });
    return data.beams;
}

}  // namespace vkw::passes
