// vkwater render SCENE --out FILE.exr: renders offscreen, writes linear HDR OpenEXR,
// prints the device, the output path and the time of each pass.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/image/png_preview.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/range.hpp"
#include "engine/vk/context.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/metrics/reference_errors.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/console.hpp"
#include "tools/vkwater/image_provenance.hpp"
#include "tools/vkwater/render_budget.hpp"
#include "tools/vkwater/render_setup.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace vkw::cli {
namespace {

// What --out names, by its extension: the linear HDR OpenEXR (.exr), or the tone-mapped preview
// alone (.png). A device or a pipe (/dev/stdout, a FIFO) has no extension to go by and gets the EXR.
enum class OutputKind { Exr, Png };

OutputKind output_kind(const std::filesystem::path& out) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(out, error);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_directory(status)) {
        return OutputKind::Exr;
    }
    std::string extension = out.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".exr") return OutputKind::Exr;
    if (extension == ".png") return OutputKind::Png;
    throw UserError("--out " + quoted_path(out) + ": " +
                    (extension.empty() ? std::string("no extension") : "unknown extension '" + extension + "'") +
                    " (accepted: .exr for the linear HDR image, .png for a tone-mapped preview alone)");
}

// The in-scatter layer's relMSE, or why there is none; a frame without godrays names their decision.
std::string inscatter_text(const Scene& scene, const RenderOptions& options, const metrics::LayerRelMse& error) {
    if (error.value || !options.inscatter_layer) return error.text(true);
    const fg::FrameNeeds needs = decide_frame_needs(scene, double(options.width) / double(options.height));
    const fg::EffectDecision* godrays = needs.find(Effect::VolumeCaustics);
    if (godrays && !godrays->needed) return "n/a (the godrays do not run: " + godrays->reason + ")";
    return error.text(true);
}

// The budget chooses the resolution scale (and at most --spp's samples) for one image.
void require_budget_alone(const RenderArgs& args) {
    if (args.render_scale != 1.0) {
        throw UserError("--render-scale " + format_number(args.render_scale) +
                        ": --budget-ms chooses the resolution scale itself (accepted: one of the two)");
    }
}

int run_render(const RenderArgs& args) {
    if (!args.frames.empty()) {
        if (args.budget_ms > 0.0) {
            throw UserError(
                "--budget-ms: a sequence renders every frame at the same settings (accepted: "
                "--budget-ms on one frame, then its printed settings with --frames)");
        }
        return run_render_sequence(args);
    }
    if (!args.shard.empty())
        throw UserError("--shard '" + args.shard + "': a shard is a share of a sequence's frames; give --frames too");
    if (args.temporal) {
        throw UserError("--temporal: accumulates over a sequence's frames (accepted: with --frames A:B)");
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::string> overrides = applied_overrides(args);
    Scene scene = load_command_scene(args.scene, overrides, args.allow_outside_paths);
    if (args.budget_ms > 0.0) require_budget_alone(args);
    PixelFilter filter = pixel_filter_from_spp(args.spp);  // with --budget-ms, at most this many samples
    // Fail on an unwritable output before spending time on the render. Without --out, the scene's
    // name with .exr, in the current folder.
    const std::filesystem::path out = args.out.empty()
                                          ? std::filesystem::path(args.scene).filename().replace_extension(".exr")
                                          : std::filesystem::path(args.out);
    const OutputKind kind = output_kind(out);
    if (kind == OutputKind::Png && args.half) {
        throw UserError("--half: --out " + quoted_path(out) + " is a PNG preview; --half applies to an .exr output");
    }
    require_writable_file_path(out);
    const std::filesystem::path png_path =
        kind == OutputKind::Png ? out : std::filesystem::path(out).replace_extension(".png");
    const bool write_png = args.png || kind == OutputKind::Png;
    if (write_png) require_writable_file_path(png_path);
    std::optional<ImageRGBA32F> reference;
    if (!args.reference.empty()) {
        require_readable_file_path(args.reference);
        reference = read_exr(args.reference);
        require_comparable_filters(filter, *reference, args.reference);
    }

    std::unique_ptr<Context> context = open_render_device(args.device);
    const std::shared_ptr<ValidationLog> validation_log = context->shared_validation_log();
    note_slow_cpu_frames(*context, scene, args, args.repeat * filter.samples);

    // -v: the frame's decisions, as the renderer takes them (vkwater passes prints the whole graph).
    if (verbose()) std::printf("%s", decide_frame_needs(scene, double(args.width) / args.height).describe().c_str());

    RenderOptions options = render_options(args);
    RenderResult result;
    double declare_ms = 0.0;
    std::string budget_record;
    {
        Renderer renderer(*context);  // its pipelines must go before the device
        if (args.budget_ms > 0.0) {
            // The budget's choice leaves the scene and the resolution scale at its settings.
            const BudgetedSettings chosen =
                choose_budgeted_settings(renderer, scene, options, args.budget_ms, filter.samples);
            filter = pixel_filter_from_spp(chosen.quality.samples);
            std::printf("%s\n", chosen.describe(args.budget_ms).c_str());
            budget_record = chosen.describe(args.budget_ms) + " on " + context->device_name();
        }
        // After the first second only: most renders take less (console.hpp).
        Progress progress("render", 1.0);
        const double sub_frames = double(args.repeat) * filter.samples;
        for (uint32_t frame = 0; frame < args.repeat; ++frame) {
            result = render_filtered(renderer, scene, options, filter, [&](uint32_t done) {
                progress.report((double(frame) * filter.samples + done) / sub_frames);
            });
        }
        declare_ms = renderer.last_declare_ms();
    }

    std::printf(
        "pass times of frame %u of %u (%s%s):\n", args.repeat, args.repeat, result.timing.method_name().c_str(),
        filter.is_box() ? (", the sum over its " + std::to_string(filter.samples) + " sub-frames").c_str() : "");
    // Each pass's time and the memory of what it creates (the targets and buffers of its method).
    for (const fg::PassTime& pass : result.timing.passes) {
        if (pass.created_bytes == 0) {
            std::printf("  %-24s %8.2f ms\n", pass.pass.c_str(), pass.ms);
        } else {
            const double kib = static_cast<double>(pass.created_bytes) / 1024.0;
            if (kib < 1.0) {
                std::printf("  %-24s %8.2f ms  creates %llu B\n", pass.pass.c_str(), pass.ms,
                            static_cast<unsigned long long>(pass.created_bytes));
            } else if (kib < 1024.0) {
                std::printf("  %-24s %8.2f ms  creates %.1f KiB\n", pass.pass.c_str(), pass.ms, kib);
            } else {
                std::printf("  %-24s %8.2f ms  creates %.2f MiB\n", pass.pass.c_str(), pass.ms, kib / 1024.0);
            }
        }
    }
    std::printf("  %-24s %8.2f ms\n", "frame", result.timing.total_ms);
    // The CPU's share before the device runs: the graph is declared and compiled every frame.
    std::printf("  %-24s %8.3f ms (CPU)\n", "declare + compile graph", declare_ms);

    const std::string device_name = context->device_name();
    context.reset();  // tear the device down now: teardown can report validation messages too
    require_finite_image(result.image, "the rendered image (--check-finite names the first pass that made one)");
    char time[96];
    std::snprintf(time, sizeof time, "%.2f ms, frame %u of %u (%s)", result.timing.total_ms, args.repeat, args.repeat,
                  result.timing.method_name().c_str());
    result.image.attributes = image_attributes({args.scene, overrides, "real-time", filter.describe(), device_name,
                                                time, "", render_scale_text(options), budget_record},
                                               scene.camera);
    if (kind == OutputKind::Exr) {
        const ExrWriteReport report =
            write_exr(out, result.image, args.half ? ExrPixelType::Half : ExrPixelType::Float);
        std::printf("wrote %s (%dx%d, %s)\n", out.c_str(), result.image.width, result.image.height,
                    args.half ? "half float" : "32-bit float");
        if (args.half && report.clamped_values > 0) {
            std::printf("clamped %zu values to the half-float maximum 65504\n", report.clamped_values);
        }
    }
    if (write_png) {
        write_png_preview(png_path, result.image, static_cast<float>(scene.camera.exposure));
        std::printf("wrote %s (preview: ACES filmic, sRGB)\n", png_path.c_str());
    }
    if (reference) {
        // The project's two numbers for every image: its time and its error, one line each.
        const metrics::Metrics error = metrics::compare_images(result.image, *reference);
        std::printf("time: %.2f ms per frame (%s)\n", result.timing.total_ms, result.timing.method_name().c_str());
        const metrics::LayerRelMse caustic = metrics::layer_rel_mse(result.image, *reference, metrics::kCausticLayer);
        const metrics::LayerRelMse inscatter =
            metrics::layer_rel_mse(result.image, *reference, metrics::kInScatterLayer);
        std::printf(
            "error against %s: relMSE %.6g, FLIP %.6g, bias %.6g, L*u*v* %.6g, caustic relMSE %s, "
            "in-scatter relMSE %s\n",
            args.reference.c_str(), error.rel_mse, error.flip_mean, error.bias, error.luv_mean, caustic.text().c_str(),
            inscatter_text(scene, options, inscatter).c_str());
    }
    const double total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("total %.1f ms (whole command)\n", total);
    const size_t validation_failures = validation_log->failure_count();
    if (validation_failures > 0) {
        throw InternalError(std::to_string(validation_failures) +
                            " validation message(s); see above. Every error or warning fails a --validation run");
    }
    return kExitOk;
}

}  // namespace

Run add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* command = app.add_subcommand("render", "Render a scene offscreen to a linear HDR OpenEXR file");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    command->add_option("--out,-o", args->out,
                        "Output file, by its extension: .exr the linear HDR image (32-bit float), .png a tone-mapped "
                        "preview alone (default: the scene's name with .exr, in the current folder; an existing file "
                        "is replaced)");
    command->add_option("--width", args->width, "Image width in pixels")->capture_default_str();
    command->add_option("--height", args->height, "Image height in pixels")->capture_default_str();
    command->add_flag("--half", args->half, "Write half floats (values beyond 65504 are clamped and counted)");
    command->add_flag("--png", args->png, "Also write a tone-mapped PNG preview next to the EXR (its name with .png)");
    command
        ->add_option("--exposure", args->exposure,
                     "The preview's exposure: a multiplier of the linear radiance before the tone curve (default: "
                     "the scene's camera.exposure; the EXR's pixels do not change)")
        ->check(finite_number() & positive_number());
    command
        ->add_option("--repeat", args->repeat,
                     "Render this many frames and report the last: the first frame includes llvmpipe's "
                     "compilation of shader variants on first use")
        ->check(CLI::Range(1u, 10000u))
        ->capture_default_str();
    add_spp_option(*command, args->spp,
                   "more average k^2 sub-frames shifted to the centres of the pixel's k x k strata (a box filter; the "
                   "caustic photons are traced once for all of them; the time is their sum)");
    add_render_scale_option(*command, args->render_scale);
    command
        ->add_option("--budget-ms", args->budget_ms,
                     "Choose the settings (resolution scale, photon grid, water mesh, godrays, scene lookup steps, "
                     "caustic kernel and map scale, and with --spp N up to N samples per pixel) with the lowest "
                     "expected error whose measured frame time fits this many milliseconds; prints them and "
                     "records them in the EXR (given explicitly they give the same image)")
        ->check(finite_number() & positive_number());
    command->add_flag("--no-caustic-layer", args->no_caustic_layer,
                      "Leave out the EXR layer caustic.R/G/B (the sun's irradiance on the receiver each pixel sees "
                      "under the water), and the second colour target its passes write");
    command->add_flag("--no-inscatter-layer", args->no_inscatter_layer,
                      "Leave out the EXR layer inscatter.R/G/B (the godrays' single-scattered radiance alone, "
                      "written where they run), and the second colour target of their composite");
    command->add_flag("--check-finite", args->check_finite,
                      "After each pass, scan every float target it wrote for NaN/Inf and name the first");
    command->add_option("--recording", args->recording, "Graphics pass recording: dynamic or renderpass")
        ->check(CLI::IsMember({"dynamic", "renderpass"}))
        ->capture_default_str();
    command->add_option("--reference", args->reference,
                        "Also print the frame's error against this reference EXR (vkwater reference), next to "
                        "its time");
    command->add_option(
        "--frames", args->frames,
        "Render a sequence: frames A to B inclusive (A:B, or A:B:STEP), frame f at water time "
        "water.time + f / fps, each to --out's pattern (e.g. out/pool_%04d.exr), with out/manifest.json; "
        "frames whose file still holds the pixels the manifest records are kept");
    command->add_option("--fps", args->fps, "A sequence's frames per second")
        ->check(finite_number() & positive_number())
        ->capture_default_str();
    command->add_option("--shard", args->shard,
                        "Render only task I of N of a sequence (I/N): the frames at positions I, I + N, ... of the "
                        "range, for a batch scheduler's array (tools/slurm/)");
    command->add_flag("--temporal", args->temporal,
                      "With --frames: temporal accumulation, each frame jittered within its pixel and blended into "
                      "the frames before it, reprojected and clamped to its neighbourhood (every frame is rendered "
                      "in order, none kept; as vkwater view --temporal)");
    add_device_options(*command, args->device);
    command->footer(
        "Examples:\n"
        "  vkwater render scenes/pool.json --out build/pool.exr --png\n"
        "  vkwater render scenes/lake.json --out build/lake.png --exposure 2\n"
        "  vkwater render scenes/pool.json --width 1920 --height 1080 --set sun.elevation_deg=30\n"
        "  vkwater render scenes/calm.json --width 400 --height 300 --reference build/calm-ref.exr\n"
        "  vkwater render scenes/pool.json --frames 0:239 --fps 24 --out build/pool/pool_%04d.exr\n");
    return [args] { return run_render(*args); };
}

}  // namespace vkw::cli
