// vkwater bench SCENE --reference REF.exr: renders the scene over a sweep of quality
// settings, times each (median of N frames after a warm-up, interquartile spread, one
// submission per frame), measures its error against the reference, and writes the
// table as CSV and as an SVG plot of error against time with the Pareto front marked.
// The settings today: the water grid (which is also the photon grid) and caustics
// against the flat-surface stand-in; more join as the effects land.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/render/renderer.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/context.hpp"
#include "tools/benchmarks/sweep_report.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/vkwater/commands.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace vkw::cli {
namespace {

struct BenchArgs {
    std::string scene;
    std::string reference;
    std::vector<uint32_t> grids{128, 256, 512};
    uint32_t frames = 30;
    std::string out_dir;
    std::vector<std::string> overrides;
    DeviceOptions device;
};

int run_bench(const BenchArgs& args) {
    const ImageRGBA32F reference = read_exr(args.reference);
    const uint32_t width = static_cast<uint32_t>(reference.width), height = static_cast<uint32_t>(reference.height);
    const std::filesystem::path out_dir =
        args.out_dir.empty() ? "bench-" + std::filesystem::path(args.scene).stem().string() : args.out_dir;
    std::filesystem::create_directories(out_dir);

    ContextOptions context_options;
    context_options.validation = args.device.validation;
    context_options.device_name = args.device.device;
    auto context = std::make_unique<Context>(context_options);
    const metrics::FlipExposureRange range = metrics::flip_exposure_range(reference);  // once, from the reference
    std::vector<bench::SweepRow> rows;
    std::printf("%-28s %10s %9s %12s %9s %9s\n", "setting", "ms", "spread", "relMSE", "FLIP", "bias");
    for (const uint32_t grid : args.grids) {
        for (const char* caustics : {"on", "off"}) {
            std::vector<std::string> overrides = args.overrides;
            overrides.push_back("water.grid_resolution=" + std::to_string(grid));
            overrides.push_back(std::string("effects.caustics.mode=") + caustics);
            const Scene scene = load_scene(args.scene, overrides);
            Renderer renderer(*context);
            const RenderOptions options{width, height, false, fg::TimingMode::None};
            RenderResult result = renderer.render(scene, options);  // warm-up: compiles shader variants
            std::vector<double> times;
            for (uint32_t frame = 0; frame < args.frames; ++frame) {
                result = renderer.render(scene, options);
                times.push_back(result.timing.total_ms);
            }
            std::sort(times.begin(), times.end());
            const metrics::Metrics error = metrics::compare_images(result.image, reference, nullptr, &range);
            bench::SweepRow row{"grid=" + std::to_string(grid) + " caustics=" + caustics, times[times.size() / 2],
                                times[times.size() * 3 / 4] - times[times.size() / 4], error.rel_mse,
                                error.flip_mean, error.bias};
            std::printf("%-28s %10.2f %9.2f %12.6g %9.4f %9.4f\n", row.setting.c_str(), row.median_ms, row.spread_ms,
                        row.rel_mse, row.flip, row.bias);
            rows.push_back(row);
        }
    }
    bench::write_csv(out_dir / "sweep.csv", rows);
    bench::write_svg(out_dir / "sweep.svg", std::filesystem::path(args.scene).filename().string() + ", " +
                                                std::to_string(width) + "x" + std::to_string(height) + " on " +
                                                context->device_name(),
                     rows);
    std::printf("time: median of %u frames after a warm-up, one submission per frame (whole frame)\n", args.frames);
    std::printf("wrote %s and %s\n", (out_dir / "sweep.csv").c_str(), (out_dir / "sweep.svg").c_str());
    return kExitOk;
}

}  // namespace

Run add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* command = app.add_subcommand("bench", "Time and error of a scene over a sweep of quality settings");
    command->add_option("scene", args->scene, "Scene file (JSON)")->required();
    command->add_option("--reference", args->reference, "Reference EXR (vkwater reference) at the bench's size")
        ->required();
    command->add_option("--grids", args->grids, "Water (and photon) grid resolutions to sweep")
        ->delimiter(',')
        ->capture_default_str();
    command->add_option("--frames", args->frames, "Timed frames per setting (after one warm-up frame)")
        ->check(CLI::Range(1u, 100000u))
        ->capture_default_str();
    command->add_option("--out-dir", args->out_dir, "Folder for sweep.csv and sweep.svg (default bench-<scene>)");
    command->add_option("--set", args->overrides, "Override a scene field: key.path=value (repeatable)");
    add_device_options(*command, args->device);
    return [args] { return run_bench(*args); };
}

}  // namespace vkw::cli
