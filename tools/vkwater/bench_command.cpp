// vkwater bench SCENE --reference REF.exr: renders the scene over a sweep of quality
// settings, times each (median of N frames after a warm-up, interquartile spread, one
// submission per frame), measures its error against the reference (at full resolution, at
// 4x box-downsampled resolution, and of the caustic and in-scatter layers when both images carry them) and the
// frame's memory, and writes the table as CSV and as an SVG plot of error against time with
// the Pareto front marked.
// The settings: the water grid (which is also the photon grid, `--grids`) times any scene
// fields named with `--sweep key=v1,v2,...` (each a scene override, as `--set`) times any sets
// of overrides given with `--alternatives 'k=v k=v|k=v'` (every combination is rendered);
// without either, caustics on and off (the flat-surface stand-in).
// --shard I/N times only the settings whose index is I modulo N (a batch array's task); `vkwater
// bench merge DIR...` joins the shards' tables (tools/benchmarks/sweep_merge.hpp).
// Every frame of a setting renders the same Scene: the water stays at the scene file's
// `water.time` (the renderer keeps no clock), so the timed frames and the measured one agree.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/context.hpp"
#include "passes/common/calibration.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tools/benchmarks/frame_memory.hpp"
#include "tools/benchmarks/sweep_merge.hpp"
#include "tools/benchmarks/sweep_report.hpp"
#include "tools/metrics/downsample.hpp"
#include "tools/metrics/reference_errors.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/image_provenance.hpp"
#include "tools/vkwater/sequence/frame_selection.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace vkw::cli {
namespace {

// The fewest frames whose median has a meaningful spread; fewer are for smoke tests.
constexpr uint32_t kRecommendedFrames = 30;

struct BenchArgs {
    std::string scene;
    std::string reference;
    std::vector<uint32_t> grids{128, 256, 512};
    std::vector<std::string> sweeps;        // "key=v1,v2,..."
    std::vector<std::string> alternatives;  // "key=v key=v|key=v|..."
    uint32_t frames = kRecommendedFrames;
    int64_t spp = 1;
    std::string out_dir;
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
    DeviceOptions device;
    std::string shard;  // "I/N"; empty: every setting
};

// Frames per setting timed pass by pass for the calibration pass's median (the timed frames are
// one submission each, which has no per-pass times): enough for a median, few enough to add
// about a sixth to a default bench.
constexpr uint32_t kCalibrationFrames = 5;

// The calibration pass's median time over frames timed pass by pass (passes/common/calibration.hpp).
double calibration_pass_ms(Renderer& renderer, const Scene& scene, RenderOptions options, const PixelFilter& filter,
                           uint32_t frames) {
    options.timing = fg::TimingMode::Auto;
    std::vector<double> times;
    for (uint32_t frame = 0; frame < frames; ++frame) {
        const RenderResult result = render_filtered(renderer, scene, options, filter);
        for (const fg::PassTime& pass : result.timing.passes) {
            if (pass.pass == passes::kCalibrationPassName) times.push_back(pass.ms);
        }
    }
    if (times.empty()) throw InternalError("bench: the timed frames carry no calibration pass");
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

// One axis of the sweep: its values, each a list of scene overrides ("key.path=value").
struct SweepAxis {
    std::vector<std::vector<std::string>> values;
};

// --sweep key.path=v1,v2,...: one field, one override per value.
SweepAxis parse_sweep(const std::string& text) {
    const size_t equals = text.find('=');
    const std::string key = equals != std::string::npos ? text.substr(0, equals) : "";
    SweepAxis axis;
    for (size_t start = equals + 1; equals != std::string::npos && start <= text.size();) {
        const size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) axis.values.push_back({key + "=" + text.substr(start, comma - start)});
        start = comma + 1;
    }
    if (key.empty() || axis.values.empty()) {
        throw UserError("--sweep '" + text +
                        "': expected key.path=value1,value2,... (a scene field as --set names it, "
                        "and at least one value)");
    }
    return axis;
}

// --alternatives 'a.b=1 c.d=2|a.b=3': values that set several fields at once (or none, where an
// alternative sets a field that makes the others moot, as godrays off and a godray grid).
SweepAxis parse_alternatives(const std::string& text) {
    SweepAxis axis;
    for (size_t start = 0; start <= text.size();) {
        const size_t bar = std::min(text.find('|', start), text.size());
        std::vector<std::string> overrides;
        for (size_t word = start; word < bar;) {
            const size_t space = std::min(text.find(' ', word), bar);
            if (space > word) overrides.push_back(text.substr(word, space - word));
            word = space + 1;
        }
        auto is_override = [](const std::string& o) { return o.find('=') != std::string::npos && o.front() != '='; };
        const bool valid = !overrides.empty() && std::all_of(overrides.begin(), overrides.end(), is_override);
        if (!valid) {
            throw UserError("--alternatives '" + text +
                            "': expected alternatives separated by '|', each one or more "
                            "key.path=value overrides separated by spaces");
        }
        axis.values.push_back(std::move(overrides));
        start = bar + 1;
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
            for (const std::vector<std::string>& value : axis.values) {
                next.push_back(setting);
                next.back().insert(next.back().end(), value.begin(), value.end());
            }
        }
        settings = std::move(next);
    }
    return settings;
}

// --out-dir, made if it is missing; vkw::UserError when it cannot be a folder.
void make_output_folder(const std::filesystem::path& out_dir) {
    std::error_code folder_error;
    std::filesystem::create_directories(out_dir, folder_error);
    if (folder_error || !std::filesystem::is_directory(out_dir)) {
        throw UserError("--out-dir " + quoted_path(out_dir) + ": cannot make it a folder (" +
                        (folder_error ? folder_error.message() : std::string("it is a file")) + ")");
    }
}

// The reference, with the bench's downsampling factor checked against its size (naming the file).
metrics::ReferenceErrors load_reference(const std::string& path) {
    ImageRGBA32F image = read_exr(path);
    const int factor = metrics::kBenchDownsampleFactor;
    if (image.width < factor || image.height < factor) {
        throw UserError("--reference " + path + ": the image is " + metrics::size_text(image.width, image.height) +
                        ", but the errors at " + std::to_string(factor) +
                        "x box-downsampled resolution need at least " + std::to_string(factor) + "x" +
                        std::to_string(factor) + " pixels");
    }
    return metrics::ReferenceErrors(std::move(image), factor);
}

int run_bench(const BenchArgs& args) {
    if (args.scene.empty() || args.reference.empty()) {
        throw UserError(
            "bench: give the SCENE and --reference REF.exr (or: vkwater bench merge DIR..., to join "
            "shards' tables)");
    }
    const Shard shard = args.shard.empty() ? Shard{} : parse_shard(args.shard);
    const PixelFilter filter = pixel_filter_from_spp(args.spp);
    // The sweep's settings before anything is made: a mistyped axis leaves no empty --out-dir behind.
    std::vector<SweepAxis> axes(1);
    for (const uint32_t grid : args.grids) axes[0].values.push_back({"water.grid_resolution=" + std::to_string(grid)});
    if (args.sweeps.empty() && args.alternatives.empty()) axes.push_back(parse_sweep("effects.caustics.mode=on,off"));
    for (const std::string& sweep : args.sweeps) axes.push_back(parse_sweep(sweep));
    for (const std::string& alternatives : args.alternatives) axes.push_back(parse_alternatives(alternatives));
    const std::vector<std::vector<std::string>> settings = combinations(axes);
    const metrics::ReferenceErrors reference = load_reference(args.reference);
    require_comparable_filters(filter, reference.reference(), args.reference);
    const uint32_t width = static_cast<uint32_t>(reference.reference().width);
    const uint32_t height = static_cast<uint32_t>(reference.reference().height);
    const std::filesystem::path out_dir =
        args.out_dir.empty() ? "bench-" + std::filesystem::path(args.scene).stem().string() : args.out_dir;
    make_output_folder(out_dir);

    ContextOptions context_options;
    context_options.validation = args.device.validation;
    context_options.device_name = args.device.device;
    auto context = std::make_unique<Context>(context_options);
    std::vector<bench::SweepRow> rows;
    const std::string factor = std::to_string(metrics::kBenchDownsampleFactor) + "x";
    std::printf("%-28s %10s %9s %8s %12s %12s %9s %9s %12s %12s %9s\n", "setting", "ms", "spread", "cal", "relMSE",
                ("relMSE " + factor).c_str(), "FLIP", "bias", "caustic", "in-scatter", "MiB");
    if (!args.shard.empty()) {
        std::printf("shard %s: the settings at positions %u, %u + %u, ... of %zu\n", args.shard.c_str(), shard.index,
                    shard.index, shard.count, settings.size());
    }
    for (size_t index = shard.index; index < settings.size(); index += shard.count) {
        const std::vector<std::string>& setting = settings[index];
        std::vector<std::string> overrides = args.overrides;
        overrides.insert(overrides.end(), setting.begin(), setting.end());
        // Its warnings once: the same files in every setting.
        const Scene scene = rows.empty()
                                ? load_command_scene(args.scene, overrides, args.allow_outside_paths)
                                : load_scene(args.scene, overrides, {.allow_outside_paths = args.allow_outside_paths});
        Renderer renderer(*context);
        const RenderOptions options{width, height, false, fg::TimingMode::None};
        RenderResult result = render_filtered(renderer, scene, options, filter);  // warm-up: compiles shader variants
        std::vector<double> times;
        for (uint32_t frame = 0; frame < args.frames; ++frame) {
            result = render_filtered(renderer, scene, options, filter);
            times.push_back(result.timing.total_ms);
        }
        std::sort(times.begin(), times.end());
        // The errors from one more frame with the caustic and in-scatter layers, which the timed
        // frames leave out (their second colour targets are not part of the setting's cost).
        RenderOptions with_layer = options;
        with_layer.caustic_layer = true;
        with_layer.inscatter_layer = true;
        result = render_filtered(renderer, scene, with_layer, filter);
        const metrics::FrameErrors error = reference.measure(result.image);
        const bench::FrameMemory memory = bench::measure_frame_memory(renderer, scene, options);
        std::string name;
        for (const std::string& override_text : setting) name += (name.empty() ? "" : " ") + short_key(override_text);
        bench::SweepRow row{name,
                            times[times.size() / 2],
                            times[times.size() * 3 / 4] - times[times.size() / 4],
                            error.full.rel_mse,
                            error.full.flip_mean,
                            error.full.bias,
                            error.downsampled.rel_mse,
                            error.downsampled.flip_mean,
                            error.caustic.value,
                            error.inscatter.value,
                            memory.total(),
                            calibration_pass_ms(renderer, scene, options, filter, kCalibrationFrames),
                            context->device_name(),
                            index,
                            settings.size()};
        std::printf("%-28s %10.2f %9.2f %8.1f %12.6g %12.6g %9.4f %9.4f %12s %12s %9.2f\n", row.setting.c_str(),
                    row.median_ms, row.spread_ms, row.median_ms / row.calibration_ms, row.rel_mse,
                    row.rel_mse_downsampled, row.flip, row.bias, error.caustic.text().c_str(),
                    error.inscatter.text().c_str(), static_cast<double>(row.memory_bytes) / (1024.0 * 1024.0));
        std::fflush(stdout);  // a long sweep shows its progress, also when its output goes to a file
        rows.push_back(row);
    }
    bench::write_csv(out_dir / "sweep.csv", rows, metrics::kBenchDownsampleFactor);
    bench::write_svg(out_dir / "sweep.svg",
                     std::filesystem::path(args.scene).filename().string() + ", " + std::to_string(width) + "x" +
                         std::to_string(height) + ", " + std::to_string(args.frames) + " frames, on " +
                         context->device_name(),
                     rows, metrics::kBenchDownsampleFactor);
    std::printf(
        "time: median of %u frames after a warm-up (spread: interquartile range), one submission per "
        "frame (whole frame), scene time frozen at water.time; cal: the same in calibration passes (the median of "
        "%u frames timed pass by pass)\n",
        args.frames, kCalibrationFrames);
    if (args.frames < kRecommendedFrames) {
        std::printf("note: fewer than %u frames per setting: the medians and spreads are rough\n", kRecommendedFrames);
    }
    std::printf("memory: the frame graph's transient heap plus the imported buffers and images\n");
    std::printf("wrote %s and %s\n", (out_dir / "sweep.csv").c_str(), (out_dir / "sweep.svg").c_str());
    return kExitOk;
}

struct MergeArgs {
    std::vector<std::string> folders;
    std::string out_dir = "bench-merged";
};

int run_bench_merge(const MergeArgs& args) {
    std::vector<std::pair<std::filesystem::path, bench::SweepTable>> shards;
    for (const std::string& folder : args.folders) {
        const std::filesystem::path file = std::filesystem::path(folder) / "sweep.csv";
        shards.emplace_back(file, bench::read_csv(file));
    }
    const bench::MergedSweep merged = bench::merge_sweeps(shards);
    const std::filesystem::path out_dir = args.out_dir;
    make_output_folder(out_dir);
    bench::write_csv(out_dir / "sweep.csv", merged.rows, merged.downsample_factor);
    char title[256];
    std::snprintf(title, sizeof title,
                  "%zu settings merged from %zu shard(s), on %s; times at the median calibration pass, %.3g ms",
                  merged.rows.size(), shards.size(), merged.device.c_str(), merged.calibration_ms);
    bench::write_svg(out_dir / "sweep.svg", title, merged.rows, merged.downsample_factor);
    std::printf(
        "merged %zu settings from %zu shard(s) on %s; each time scaled by the median calibration pass "
        "(%.3f ms) over its own\n",
        merged.rows.size(), shards.size(), merged.device.c_str(), merged.calibration_ms);
    std::printf("wrote %s and %s\n", (out_dir / "sweep.csv").c_str(), (out_dir / "sweep.svg").c_str());
    return kExitOk;
}

}  // namespace

Run add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* command = app.add_subcommand("bench", "Time and error of a scene over a sweep of quality settings");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    // Required unless the command is `bench merge` (run_bench checks them).
    command->get_option("scene")->required(false);
    command->add_option("--reference", args->reference, "Reference EXR (vkwater reference) at the bench's size");
    command->add_option("--grids", args->grids, "Water (and photon) grid resolutions to sweep")
        ->delimiter(',')
        ->capture_default_str();
    command->add_option("--sweep", args->sweeps,
                        "Also sweep a scene field: key.path=v1,v2,... (repeatable; every combination is rendered; "
                        "without it and --alternatives, caustics on and off)");
    command->add_option("--alternatives", args->alternatives,
                        "Also sweep over whole sets of overrides: 'key.path=v key.path=v|key.path=v|...' (repeatable; "
                        "one axis each, combined with every other axis), e.g. "
                        "'effects.godrays.mode=off|effects.godrays.grid=32'");
    add_spp_option(*command, args->spp,
                   "more box-filter every setting's frames as render --spp does (each frame's time the sum of its k^2 "
                   "sub-frames)");
    command
        ->add_option("--frames", args->frames,
                     "Timed frames per setting (after one warm-up frame); 30 or more for a meaningful median "
                     "and spread")
        ->check(CLI::Range(1u, 100000u))
        ->capture_default_str();
    command->add_option("--out-dir", args->out_dir, "Folder for sweep.csv and sweep.svg (default bench-<scene>)");
    command->add_option("--shard", args->shard,
                        "Time only task I of N of the sweep (I/N): the settings at positions I, I + N, ...; join the "
                        "tasks' folders with vkwater bench merge");
    add_device_options(*command, args->device);
    command->footer(
        "Examples:\n"
        "  vkwater bench scenes/pool.json --reference build/pool-ref.exr --grids 64,128,256\n"
        "  vkwater bench scenes/pool.json --reference build/pool-ref.exr --shard 0/2 --out-dir build/bench-0\n"
        "  vkwater bench merge build/bench-0 build/bench-1 --out-dir build/bench\n");

    auto merge_args = std::make_shared<MergeArgs>();
    CLI::App* merge = command->add_subcommand(
        "merge", "Join the sweep.csv of a sweep's shards (bench --shard I/N) into one sweep.csv and sweep.svg");
    merge->add_option("folders", merge_args->folders, "The shards' --out-dir folders")->required();
    merge->add_option("--out-dir", merge_args->out_dir, "Folder for the merged sweep.csv and sweep.svg")
        ->capture_default_str();
    return [args, merge, merge_args] { return merge->parsed() ? run_bench_merge(*merge_args) : run_bench(*args); };
}

}  // namespace vkw::cli
