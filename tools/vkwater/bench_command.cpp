// vkwater bench SCENE --reference REF.exr: renders the scene over a sweep of quality
// settings, times each (median of N frames after a warm-up, interquartile spread, one
// submission per frame), measures its error against the reference, and writes the
// table as CSV and as an SVG plot of error against time with the Pareto front marked.
// The settings: the water grid (which is also the photon grid, `--grids`) times any scene
// fields named with `--sweep key=v1,v2,...` (each a scene override, as `--set`; every
// combination is rendered); without `--sweep`, caustics on and off (the flat-surface stand-in).
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
    std::vector<std::string> sweeps;  // "key=v1,v2,..."
    uint32_t frames = 30;
    std::string out_dir;
    std::vector<std::string> overrides;
    DeviceOptions device;
};

// One swept scene field and its values.
struct SweepAxis {
    std::string key;
    std::vector<std::string> values;
};

SweepAxis parse_sweep(const std::string& text) {
    const size_t equals = text.find('=');
    SweepAxis axis;
    if (equals != std::string::npos) axis.key = text.substr(0, equals);
    for (size_t start = equals + 1; equals != std::string::npos && start <= text.size();) {
        const size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) axis.values.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    if (axis.key.empty() || axis.values.empty()) {
        throw UserError("--sweep '" + text + "': expected key.path=value1,value2,... (a scene field as --set names it, "
                        "and at least one value)");
    }
    return axis;
}

// The setting's short name: the key without the sections every sweep shares.
std::string short_key(const std::string& key) {
    for (const char* prefix : {"effects.", "water."}) {
        if (key.rfind(prefix, 0) == 0) return key.substr(std::string(prefix).size());
    }
    return key;
}

// Every combination of the axes' values, as lists of overrides (the first axis varies slowest).
std::vector<std::vector<std::string>> combinations(const std::vector<SweepAxis>& axes) {
    std::vector<std::vector<std::string>> settings{{}};
    for (const SweepAxis& axis : axes) {
        std::vector<std::vector<std::string>> next;
        for (const std::vector<std::string>& setting : settings) {
            for (const std::string& value : axis.values) {
                next.push_back(setting);
                next.back().push_back(axis.key + "=" + value);
            }
        }
        settings = std::move(next);
    }
    return settings;
}

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
    std::vector<SweepAxis> axes{{"water.grid_resolution", {}}};
    for (const uint32_t grid : args.grids) axes[0].values.push_back(std::to_string(grid));
    if (args.sweeps.empty()) axes.push_back({"effects.caustics.mode", {"on", "off"}});
    for (const std::string& sweep : args.sweeps) axes.push_back(parse_sweep(sweep));
    for (const std::vector<std::string>& setting : combinations(axes)) {
        std::vector<std::string> overrides = args.overrides;
        overrides.insert(overrides.end(), setting.begin(), setting.end());
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
        std::string name;
        for (const std::string& override_text : setting) name += (name.empty() ? "" : " ") + short_key(override_text);
        bench::SweepRow row{name, times[times.size() / 2], times[times.size() * 3 / 4] - times[times.size() / 4],
                            error.rel_mse, error.flip_mean, error.bias};
        std::printf("%-28s %10.2f %9.2f %12.6g %9.4f %9.4f\n", row.setting.c_str(), row.median_ms, row.spread_ms,
                    row.rel_mse, row.flip, row.bias);
        rows.push_back(row);
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
    command->add_option("--sweep", args->sweeps,
                        "Also sweep a scene field: key.path=v1,v2,... (repeatable; every combination is rendered; "
                        "without it, caustics on and off)");
    command->add_option("--frames", args->frames, "Timed frames per setting (after one warm-up frame)")
        ->check(CLI::Range(1u, 100000u))
        ->capture_default_str();
    command->add_option("--out-dir", args->out_dir, "Folder for sweep.csv and sweep.svg (default bench-<scene>)");
    command->add_option("--set", args->overrides, "Override a scene field: key.path=value (repeatable)");
    add_device_options(*command, args->device);
    return [args] { return run_bench(*args); };
}

}  // namespace vkw::cli
