// vkwater render --frames A:B[:STEP]: a sequence of frames, frame f at water time
// water.time + f / fps, on one device with one renderer (its pipelines and the frame's device
// objects made once), each frame written as soon as it is done and recorded in the folder's
// manifest. A frame's pixels depend on its number alone, never on which frames the same process
// rendered before it, so any split of the range (--shard, a re-run) gives the same files.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/image/pixel_hash.hpp"
#include "engine/image/png_preview.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/range.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tools/reference/scene_hash.hpp"
#include "tools/vkwater/console.hpp"
#include "tools/vkwater/image_provenance.hpp"
#include "tools/vkwater/render_setup.hpp"
#include "tools/vkwater/sequence/frame_pattern.hpp"
#include "tools/vkwater/sequence/frame_selection.hpp"
#include "tools/vkwater/sequence/sequence_manifest.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace vkw::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Whether `path` holds an image whose pixels hash to `hash` (a frame done by an earlier run).
bool file_holds(const std::filesystem::path& path, const std::string& hash) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return false;
    try {
        return pixel_hash(read_exr(path)) == hash;
    } catch (const UserError&) {
        return false;  // truncated or not an EXR: render it again
    }
}

// What every frame of the folder shares: a frame made with other settings is another sequence.
nlohmann::json sequence_identity(const RenderArgs& args, const FramePattern& pattern) {
    return {{"vkwater", VKWATER_VERSION},
            {"sceneHash", ref::scene_file_hash(args.scene)},
            {"settings",
             {{"overrides", applied_overrides(args)},
              {"width", args.width},
              {"height", args.height},
              {"spp", args.spp},
              {"fps", args.fps},
              {"pattern", pattern.name_pattern()},
              {"recording", args.recording},
              {"causticLayer", !args.no_caustic_layer},
              {"inscatterLayer", !args.no_inscatter_layer},
              {"pixelType", args.half ? "half" : "float"},
              {"temporal", args.temporal}}}};
}

std::string seconds_text(double seconds) {
    char text[32];
    if (seconds < 120.0) {
        std::snprintf(text, sizeof text, "%.0f s", seconds);
    } else if (seconds < 7200.0) {
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    } else {
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
    }
    return text;
}

}  // namespace

int run_render_sequence(const RenderArgs& args) {
    const auto start = Clock::now();
    const FrameRange range = parse_frame_range(args.frames);
    const Shard shard = args.shard.empty() ? Shard{} : parse_shard(args.shard);
    if (args.repeat != 1) throw UserError("--repeat: a sequence renders each frame once; leave it out with --frames");
    if (!args.reference.empty()) {
        throw UserError("--reference: a sequence has no one reference; compare a frame with vkwater compare");
    }
    if (args.out.empty()) {
        throw UserError("--frames: give --out with the frame number in the file name, e.g. --out out/pool_%04d.exr");
    }
    // Each accumulated frame holds the ones before it: one process renders them all, in order.
    if (args.temporal && !args.shard.empty()) {
        throw UserError("--shard '" + args.shard +
                        "': a temporal sequence's frames depend on the ones before (accepted: --temporal without "
                        "--shard)");
    }
    if (args.temporal && args.spp != 1) {
        throw UserError("--spp " + std::to_string(args.spp) +
                        ": --temporal jitters its frames within the pixel itself (accepted: --spp 1 with it)");
    }
    const FramePattern pattern(args.out);
    const std::vector<std::string> overrides = applied_overrides(args);
    Scene scene = load_command_scene(args.scene, overrides, args.allow_outside_paths);
    const PixelFilter filter = pixel_filter_from_spp(args.spp);
    // A scene without water has nothing that moves yet: its frames are all the same picture.
    const double water_time_at_frame_0 = scene.water ? scene.water->time : 0.0;

    // Every task of an array creates the folder; create_directories tolerates the others' doing so.
    std::error_code error;
    if (!pattern.folder().empty()) std::filesystem::create_directories(pattern.folder(), error);
    if (error) throw UserError("cannot create the folder " + quoted_path(pattern.folder()) + ": " + error.message());
    const SequenceManifest manifest(pattern.folder(), args.scene, sequence_identity(args, pattern));
    const std::map<int64_t, FrameRecord> recorded = manifest.recorded();  // refuses another sequence's folder

    std::vector<int64_t> to_render;
    size_t kept = 0;
    const std::vector<int64_t> mine = shard.frames_of(range);
    for (int64_t frame : mine) {
        const auto found = recorded.find(frame);
        if (!args.temporal && found != recorded.end() &&
            file_holds(pattern.file_for(frame), found->second.pixel_hash)) {
            ++kept;
        } else {
            to_render.push_back(frame);
        }
    }
    std::printf(
        "sequence: frames %s at %s fps (%zu), %zu in this task%s, %zu kept (their files match %s), %zu to "
        "render\n",
        range.text().c_str(), format_number(args.fps).c_str(), static_cast<size_t>(range.count()), mine.size(),
        args.shard.empty() ? "" : (" (shard " + args.shard + ")").c_str(), kept, manifest.path().c_str(),
        to_render.size());
    if (to_render.empty()) return kExitOk;

    std::unique_ptr<Context> context = open_render_device(args.device);
    const std::shared_ptr<ValidationLog> validation_log = context->shared_validation_log();
    note_slow_cpu_frames(*context, scene, args, static_cast<uint32_t>(to_render.size()) * filter.samples);
    RenderOptions options = render_options(args);
    options.timing = fg::TimingMode::None;  // the whole frame's time is what a sequence reports
    const std::string device_name = context->device_name();

    const auto render_start = Clock::now();
    size_t realize_count = 0;
    {
        Renderer renderer(*context);  // its pipelines must go before the device
        for (size_t done = 0; done < to_render.size(); ++done) {
            const auto frame_start = Clock::now();
            const int64_t frame = to_render[done];
            const double water_time = water_time_at_frame_0 + static_cast<double>(frame) / args.fps;
            if (scene.water) scene.water->time = water_time;
            if (args.temporal)
                scene.camera.image_shift_ndc = renderer.next_temporal_shift(options.width, options.height);
            RenderResult result = render_filtered(renderer, scene, options, filter);
            const std::string what = "frame " + std::to_string(frame);
            require_finite_image(result.image, what + " (--check-finite names the first pass that made one)");
            char time[96];
            std::snprintf(time, sizeof time, "%.2f ms (%s)", result.timing.total_ms,
                          result.timing.method_name().c_str());
            const std::string frame_text = std::to_string(frame) + " of " + range.text() + " at " +
                                           format_number(args.fps) + " fps, water.time " + format_number(water_time) +
                                           " s";
            result.image.attributes = image_attributes({args.scene, overrides, "real-time", filter.describe(),
                                                        device_name, time, frame_text, render_scale_text(options)},
                                                       scene.camera);
            const std::filesystem::path path = pattern.file_for(frame);
            write_exr(path, result.image, args.half ? ExrPixelType::Half : ExrPixelType::Float);
            if (args.png) {
                write_png_preview(std::filesystem::path(path).replace_extension(".png"), result.image,
                                  static_cast<float>(scene.camera.exposure));
            }
            // The hash of the pixels as the file stores them, which is what a re-run reads back: 32-bit
            // floats are stored exactly, so the image in memory serves; half floats are rounded (and
            // clamped) by write_exr, so that file is read back.
            const std::string hash = args.half ? pixel_hash(read_exr(path)) : pixel_hash(result.image);
            const FrameRecord record{frame,      path.filename().string(), water_time,
                                     hash,       result.timing.total_ms,   ms_since(frame_start),
                                     device_name};
            manifest.record(record);
            const double mean_ms = ms_since(render_start) / static_cast<double>(done + 1);
            const size_t left = to_render.size() - done - 1;
            std::printf(
                "frame %lld (%zu of %zu): %.1f ms on the device, %.0f ms in all; %s\n", static_cast<long long>(frame),
                done + 1, to_render.size(), record.frame_ms, record.wall_ms,
                left == 0 ? "done" : ("about " + seconds_text(mean_ms * double(left) / 1000.0) + " left").c_str());
            std::fflush(stdout);
        }
        realize_count = renderer.realize_count();
    }
    const double render_s = ms_since(render_start) / 1000.0;
    std::printf(
        "rendered %zu frame(s) in %.2f s (%.2f frames per second); the frame's device objects made %zu time(s); "
        "recorded in %s\n",
        to_render.size(), render_s, double(to_render.size()) / render_s, realize_count, manifest.path().c_str());
    context.reset();  // tear the device down now: teardown can report validation messages too
    std::printf("total %.1f ms (whole command)\n", ms_since(start));
    const size_t validation_failures = validation_log->failure_count();
    if (validation_failures > 0) {
        throw InternalError(std::to_string(validation_failures) +
                            " validation message(s); see above. Every error or warning fails a --validation run");
    }
    return kExitOk;
}

}  // namespace vkw::cli
