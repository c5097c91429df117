// Kernel times of the GPU water surface at R = 256 (and N = 256 for the ocean), each pass
// submitted alone and timed with fences on the CPU clock, best of several frames. Not a
// correctness test and slow on lavapipe, so disabled; run it with
//   test_water_gpu --gtest_also_run_disabled_tests --gtest_filter='water_gpu_timing.*'
// No validation layer: it would time its own checks.
#include "engine/framegraph/executor.hpp"
#include "engine/vk/context.hpp"
#include "engine/water/fft_ocean.hpp"
#include "passes/water/water_surface.hpp"
#include "passes/water/water_surface_spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace vkw::test {
namespace {

constexpr int kFrames = 7;

// Best time per pass over kFrames executions of one compiled graph.
void print_pass_times(Context& context, const passes::WaterSurfaceInputs& inputs, const std::string& label) {
    fg::PipelineStore pipelines;
    fg::FrameGraph graph;
    graph.request_output(passes::add_water_surface_pass(graph, inputs));
    graph.compile(1, 1);
    fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = false, .timing = fg::TimingMode::Fences});
    std::map<std::string, double> best;
    for (int frame = 0; frame < kFrames; ++frame) {
        const fg::FrameReport report = executor.execute();
        if (frame == 0) continue;  // pipeline creation and first touches of memory
        for (const fg::PassTime& pass : report.passes) {
            auto [it, inserted] = best.try_emplace(pass.pass, pass.ms);
            if (!inserted) it->second = std::min(it->second, pass.ms);
        }
    }
    for (const auto& [pass, ms] : best) std::printf("%-28s %-30s %8.3f ms\n", label.c_str(), pass.c_str(), ms);
}

TEST(water_gpu_timing, DISABLED_KernelTimesAtR256N256) {
    Context context(ContextOptions{});
    std::printf("device: %s\n", context.device_name().c_str());
    passes::WaterSurfaceInputs inputs;
    inputs.half_extent = 32.0;
    inputs.grid_resolution = 256;
    inputs.time = 10.0;

    inputs.waves.model = WaveModel::Flat;
    print_pass_times(context, inputs, "flat");
    inputs.waves.model = WaveModel::Sum;
    for (size_t count : {8u, 64u}) {
        inputs.waves.components.clear();
        for (size_t w = 0; w < count; ++w) {
            inputs.waves.components.push_back(
                {0.02, 1.0 + 0.37 * double(w), 13.0 * double(w), 0.0, 0.5 / double(count), -1.0});
        }
        print_pass_times(context, inputs, "sum, " + std::to_string(count) + " waves");
    }
    inputs.waves.model = WaveModel::FftOcean;
    inputs.waves.ocean.resolution = 256;
    inputs.waves.ocean.patch_size = 64.0;
    inputs.waves.ocean.choppiness = 0.8;
    const passes::OceanSpectrumBuffer buffer(
        context, std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(inputs.waves.ocean, inputs.waves.seed)));
    inputs.ocean = &buffer;
    print_pass_times(context, inputs, "ocean N = 256");
}

}  // namespace
}  // namespace vkw::test
