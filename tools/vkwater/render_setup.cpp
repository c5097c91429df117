// The shared part of vkwater render (render_setup.hpp).
#include "tools/vkwater/render_setup.hpp"

#include "engine/scene/range.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/upscale.hpp"
#include "tools/vkwater/cpu_frame_estimate.hpp"

#include <chrono>
#include <cstdio>

namespace vkw::cli {

std::vector<std::string> applied_overrides(const RenderArgs& args) {
    std::vector<std::string> overrides = args.overrides;
    if (args.exposure) overrides.push_back("camera.exposure=" + format_number(*args.exposure));
    return overrides;
}

RenderOptions render_options(const RenderArgs& args) {
    RenderOptions options;
    options.width = args.width;
    options.height = args.height;
    options.check_finite = args.check_finite;
    options.caustic_layer = !args.no_caustic_layer;
    options.inscatter_layer = !args.no_inscatter_layer;
    options.render_scale = args.render_scale;
    options.temporal.enabled = args.temporal;
    options.recording =
        args.recording == "renderpass" ? fg::RecordingKind::RenderPassObject : fg::RecordingKind::DynamicRendering;
    return options;
}

std::string render_scale_text(const RenderOptions& options) {
    if (options.render_scale == 1.0) return "";
    return format_number(options.render_scale) + ": the scene rendered at " +
           std::to_string(passes::scaled_size(options.width, options.render_scale)) + "x" +
           std::to_string(passes::scaled_size(options.height, options.render_scale)) +
           ", stretched to the image bilinearly";
}

std::unique_ptr<Context> open_render_device(const DeviceOptions& device) {
    ContextOptions options;
    options.validation = device.validation;
    options.device_name = device.device;
    const auto start = std::chrono::steady_clock::now();
    auto context = std::make_unique<Context>(options);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("device: %s (instance + device created in %.1f ms%s)\n", context->device_name().c_str(), ms,
                device.validation ? ", with validation" : "");
    return context;
}

void note_slow_cpu_frames(const Context& context, const Scene& scene, const RenderArgs& args, uint32_t frames) {
    if (!context.is_cpu_device()) return;
    const CpuFrameEstimate estimate =
        estimate_cpu_frame(scene, decide_frame_needs(scene, double(args.width) / args.height), args.width, args.height);
    if (estimate.seconds * frames > kSlowCpuFrameSeconds) {
        std::printf("note: %s on this CPU device, %u frame(s)\n", estimate.describe().c_str(), frames);
    }
}

}  // namespace vkw::cli
