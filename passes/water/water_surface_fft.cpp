// Rows pass and columns pass of the GPU inverse FFT (water_surface_fft.hpp).
#include "passes/water/water_surface_fft.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"

#include <shader_structs/water/ocean_fft.comp.hpp>

#include <bit>
#include <string>

namespace vkw::passes {

namespace {

constexpr uint32_t kMinPoints = 16, kMaxPoints = 1024;  // kMaxPoints: the points of one work group
constexpr uint32_t kMaxGroups = 65535;                  // per dispatch dimension

// The push-constant block of shaders/water/ocean_fft.comp, generated from its SPIR-V (tools/shader_structs).
using FftPush = glsl::ocean_fft_comp::Params;

// Work groups of one direction: 1024 points each, n * n * grid_count points in all.
uint32_t fft_groups(uint32_t n, uint32_t grid_count) {
    return static_cast<uint32_t>((uint64_t{n} * n * grid_count + kMaxPoints - 1) / kMaxPoints);
}

// One pass transforming every line of one direction, 1024 / n lines per work group.
fg::BufferHandle add_fft_direction(fg::FrameGraph& graph, fg::BufferHandle grids, const std::string& name,
                                   const FftPush& push) {
    struct Data {
        fg::BufferHandle grids;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) { d.grids = builder.read_write_storage("Grids", grids); },
        [push](const Data&, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline("ocean fft", ComputePipelineDesc{"water/ocean_fft.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            vkCmdDispatch(context.cmd(), fft_groups(push.n, push.line_count / push.n), 1, 1);
        });
    return data.grids;
}

}  // namespace

fg::BufferHandle add_inverse_fft_passes(fg::FrameGraph& graph, fg::BufferHandle grids, uint32_t n,
                                        uint32_t grid_count) {
    if (!std::has_single_bit(n) || n < kMinPoints || n > kMaxPoints || grid_count == 0 ||
        fft_groups(n, grid_count) > kMaxGroups) {
        throw InternalError("add_inverse_fft_passes: n = " + std::to_string(n) +
                            ", grid_count = " + std::to_string(grid_count) +
                            ": accepted n a power of two in [16, 1024], " + "1 <= grid_count <= 65535 * 1024 / n^2");
    }
    const uint32_t log2n = static_cast<uint32_t>(std::countr_zero(n));
    const uint32_t lines = n * grid_count;
    const fg::BufferHandle rows = add_fft_direction(graph, grids, "ocean fft rows", {n, log2n, 1, n, lines});
    return add_fft_direction(graph, rows, "ocean fft columns", {n, log2n, n, 1, lines});
}

}  // namespace vkw::passes
