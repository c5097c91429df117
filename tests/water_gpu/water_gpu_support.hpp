// Shared parts of the GPU water tests: run the water surface passes through a frame graph
// and read the vertices back, the CPU's vertex parameters, and the comparison of one vertex
// with a CPU surface point under a tolerance (surface_tolerance.hpp derives them).
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/surface.hpp"
#include "passes/present/readback.hpp"
#include "passes/water/water_surface.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace vkw::test {

// One vertex as passes/water/water_surface.hpp lays it out.
struct GpuVertex {
    float position[4];
    float normal[4];
    glm::dvec3 p() const { return {position[0], position[1], position[2]}; }
    glm::dvec3 n() const { return {normal[0], normal[1], normal[2]}; }
};
static_assert(sizeof(GpuVertex) == passes::kWaterVertexBytes);

// Builds a graph with the water surface and a readback, executes it once (one submission,
// so synchronization validation sees the whole frame) and returns the (R + 1)^2 vertices.
inline std::vector<GpuVertex> read_water_surface(Context& context, const passes::WaterSurfaceInputs& inputs) {
    const VkDeviceSize bytes = passes::water_surface_bytes(inputs.grid_resolution);
    Buffer readback(context, {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "water surface readback");
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        passes::add_readback_pass(graph, passes::add_water_surface_pass(graph, inputs), readback.handle(), bytes);
        graph.compile(1, 1);
        fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    std::vector<GpuVertex> vertices(bytes / sizeof(GpuVertex));
    std::memcpy(vertices.data(), readback.mapped(), bytes);
    return vertices;
}

// The parameter of vertex i along an axis, as the CPU computes it: E (2 i - R) / R.
inline double vertex_parameter(uint32_t i, const passes::WaterSurfaceInputs& inputs) {
    const double r = inputs.grid_resolution;
    return inputs.half_extent * (2.0 * i - r) / r;
}

struct VertexTolerance {
    glm::dvec3 position;  // per coordinate, m
    double normal;        // per component of the unit normal
};

// The largest error seen, as a fraction of its tolerance, and the largest tolerance, to
// report how tight the bounds are and how small against the waves.
struct WorstRatio {
    double position = 0.0, normal = 0.0;
    double position_tolerance = 0.0, normal_tolerance = 0.0;

    void print() const {
        std::printf(
            "worst error / tolerance: position %.4f, normal %.4f; largest tolerance: position %.2e m, "
            "normal %.2e\n",
            position, normal, position_tolerance, normal_tolerance);
    }
};

// Expects the GPU vertex to match the CPU point within `tolerance`; updates `worst`.
inline void expect_vertex_near(const GpuVertex& gpu, const SurfacePoint& cpu, const VertexTolerance& tolerance,
                               const std::string& where, WorstRatio& worst) {
    EXPECT_EQ(gpu.position[3], 1.0f) << where;
    EXPECT_EQ(gpu.normal[3], 0.0f) << where;
    for (int c = 0; c < 3; ++c) {
        const double position_error = std::abs(gpu.p()[c] - cpu.position[c]);
        const double normal_error = std::abs(gpu.n()[c] - cpu.normal[c]);
        EXPECT_LE(position_error, tolerance.position[c]) << "position[" << c << "] at " << where;
        EXPECT_LE(normal_error, tolerance.normal) << "normal[" << c << "] at " << where;
        worst.position = std::max(worst.position, position_error / tolerance.position[c]);
        worst.normal = std::max(worst.normal, normal_error / tolerance.normal);
        worst.position_tolerance = std::max(worst.position_tolerance, tolerance.position[c]);
    }
    worst.normal_tolerance = std::max(worst.normal_tolerance, tolerance.normal);
}

}  // namespace vkw::test
