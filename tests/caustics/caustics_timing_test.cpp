// Times of the caustic photon pass (trace + int64 fixed-point splat into a 512^2 map) at grids
// 128^2, 512^2 and 1024^2, with GPU timestamps (compute passes: they agree with the wall clock on
// lavapipe, ../shared/LAVAPIPE.md), best of several frames. A benchmark, not a test: run it with
//   test_caustics --gtest_also_run_disabled_tests --gtest_filter='caustics_timing.*'
// No validation layer: it would time its own checks.
#include "engine/framegraph/executor.hpp"
#include "engine/vk/context.hpp"
#include "passes/caustics_photons.hpp"
#include "passes/caustics_resolve.hpp"
#include "passes/water_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

namespace vkw::test {
namespace {

constexpr int kFrames = 8;

TEST(caustics_timing, DISABLED_PhotonPassTimes) {
    Context context(ContextOptions{});
    std::printf("| grid | photons | photon pass ms | photons/s | resolve ms |\n| --- | --- | --- | --- | --- |\n");
    for (const uint32_t r : {128u, 512u, 1024u}) {
        passes::WaterSurfaceInputs surface;
        surface.half_extent = 4.0;
        surface.grid_resolution = r;
        surface.waves.model = WaveModel::Sum;
        surface.waves.components = {{0.3 / std::numbers::pi, 2.0, 20.0, 0.0, 0.0, -1.0}};
        passes::CausticInputs in;
        in.grid_resolution = r;
        in.half_extent = surface.half_extent;
        in.max_amplitude = surface.waves.components[0].amplitude;
        in.sun_direction = glm::normalize(glm::dvec3(0.5, -1.0, 0.2));
        in.sigma_t = {0.3, 0.1, 0.05};
        in.fit_margin = 1.0;
        in.map_width = in.map_height = 512;
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        in.surface = passes::add_water_surface_pass(graph, surface);
        const passes::CausticMap map =
            passes::add_caustic_resolve_pass(graph, passes::add_caustic_photon_pass(graph, in), in);
        graph.request_output(map.irradiance);
        graph.compile(1, 1);
        fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = false, .timing = fg::TimingMode::Timestamps});
        std::map<std::string, double> best;
        for (int frame = 0; frame < kFrames; ++frame) {
            const fg::FrameReport report = executor.execute();
            if (frame == 0) continue;
            for (const fg::PassTime& pass : report.passes) {
                auto [it, inserted] = best.try_emplace(pass.pass, pass.ms);
                if (!inserted) it->second = std::min(it->second, pass.ms);
            }
        }
        const double photons = double(r) * r, ms = best["caustic photons"];
        std::printf("| %u^2 | %.0f | %.2f | %.1f M | %.2f |\n", r, photons, ms, photons / ms / 1e3,
                    best["caustic resolve"]);
    }
}

}  // namespace
}  // namespace vkw::test
