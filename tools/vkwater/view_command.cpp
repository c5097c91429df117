// vkwater view SCENE: the interactive window (tools/vkwater/view/viewer.hpp): orbit and fly
// camera, the parameter panel, the statistics overlay; --frames and --script make a
// repeatable run that exits with a summary (tests, benchmarks).
#include "engine/core/errors.hpp"
#include "passes/frame/frame_needs.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/cpu_frame_estimate.hpp"
#include "tools/vkwater/view/stats_overlay.hpp"
#include "tools/vkwater/view/viewer.hpp"

#include <map>
#include <memory>

namespace vkw::cli {
namespace {

struct ViewArgs {
    window::ViewerOptions viewer;
    std::string scene;
    std::string script;
    std::string present = "fifo";
    DeviceOptions device;
};

int run_view(ViewArgs& args) {
    static const std::map<std::string, window::PresentMode> kModes = {{"fifo", window::PresentMode::Fifo},
                                                                      {"mailbox", window::PresentMode::Mailbox},
                                                                      {"immediate", window::PresentMode::Immediate}};
    args.viewer.scene = args.scene;
    args.viewer.script = args.script;
    args.viewer.present = kModes.at(args.present);
    args.viewer.device = args.device.device;
    args.viewer.validation = args.device.validation;
    args.viewer.cpu_frame_note = [](const Scene& scene, uint32_t width, uint32_t height) {
        const CpuFrameEstimate estimate =
            estimate_cpu_frame(scene, decide_frame_needs(scene, double(width) / height), width, height);
        if (estimate.seconds <= kSlowViewFrameSeconds) return std::string();
        return estimate.describe() +
               " a frame on this CPU device (a smaller window, water.grid_resolution or "
               "effects.godrays.grid makes it faster)";
    };
    window::run_viewer(args.viewer);
    return kExitOk;
}

}  // namespace

Run add_view_command(CLI::App& app) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* command = app.add_subcommand(
        "view", std::string("Show a scene in a window, with camera controls, a parameter panel and per-pass times\n") +
                    window::kViewerKeys);
    add_scene_options(*command, args->scene, args->viewer.overrides, args->viewer.allow_outside_paths);
    command->add_option("--width", args->viewer.width, "Initial window width in pixels")
        ->check(CLI::Range(1u, 16384u))
        ->capture_default_str();
    command->add_option("--height", args->viewer.height, "Initial window height in pixels")
        ->check(CLI::Range(1u, 16384u))
        ->capture_default_str();
    add_render_scale_option(*command, args->viewer.render_scale);
    add_spp_option(*command, args->viewer.spp,
                   "more each frame shown averages k^2 sub-frames shifted to the centres of the pixel's k x k strata "
                   "(the box filter of render --spp, the same image; the caustic photons traced once for all of them)");
    command->add_flag("--temporal", args->viewer.temporal,
                      "Temporal accumulation: each frame jittered within its pixel and blended into the frames "
                      "before it, reprojected to the moved camera and clamped to its neighbourhood, so that still "
                      "views sharpen to the 16-sample box filter and moving ones do not ghost");
    command
        ->add_option("--budget-ms", args->viewer.budget_ms,
                     "Keep the frame time within this many milliseconds by choosing the settings (resolution "
                     "scale, photon grid, water mesh, godrays, scene lookup steps, caustic kernel and map scale, and "
                     "with --spp N up to N samples per pixel) with the lowest expected error that fit; 0 turns it "
                     "off (default: the display's refresh interval on a GPU, 66 on a CPU device; none by default with "
                     "--frames, --script, --render-scale or --spp)")
        ->check(finite_number() & CLI::NonNegativeNumber);
    command->add_option("--present", args->present, "Present mode: fifo, mailbox or immediate")
        ->check(CLI::IsMember({"fifo", "mailbox", "immediate"}))
        ->capture_default_str();
    command
        ->add_option("--frames", args->viewer.frames,
                     "Show this many frames, print the summary and exit (0: until the window closes)")
        ->capture_default_str();
    command->add_option("--script", args->script,
                        "Run the commands of this file by frame (FRAME: camera|move|resize|set|screenshot|pause|"
                        "resume|time|mode|reload-shaders|wait-file|heap ...; tools/vkwater/view/view_script.hpp)");
    command
        ->add_option("--pass-timing-every", args->viewer.timing_every,
                     "Run the scene graph alone every N frames for per-pass times (fence-timed on CPU "
                     "devices); 0: never")
        ->capture_default_str();
    command
        ->add_option("--screenshot-prefix", args->viewer.screenshot_prefix,
                     "F12 writes PREFIX-<n>.exr (linear HDR) and PREFIX-<n>.png")
        ->capture_default_str();
    command->add_flag("--paused", args->viewer.paused, "Start with the water's clock stopped");
    add_device_options(*command, args->device);
    command->footer(
        "Examples:\n"
        "  vkwater view scenes/pool.json\n"
        "  xvfb-run -a vkwater view scenes/pool.json --frames 600 --script scenes/scripts/pool_tour.txt\n");
    return [args] { return run_view(*args); };
}

}  // namespace vkw::cli
