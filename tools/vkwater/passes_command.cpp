// vkwater passes SCENE: prints the compiled frame graph without rendering: the needs
// decisions and their reasons, the living passes in order with their reads and
// writes, the culled passes and why, and transient memory before/after aliasing.
#include "engine/core/errors.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/vk/context.hpp"
#include "engine/water/fft_ocean.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/receivers/receiver_meshes.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/cpu_frame_estimate.hpp"

#include <cstdio>
#include <memory>

namespace vkw::cli {
namespace {

struct PassesArgs {
    std::string scene;
    uint32_t width = 800;
    uint32_t height = 600;
    std::string dot;
    bool barriers = false;
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
};

int run_passes(const PassesArgs& args) {
    const Scene scene = load_command_scene(args.scene, args.overrides, args.allow_outside_paths);
    fg::FrameGraph graph(decide_frame_needs(scene, double(args.width) / double(args.height)));
    const FrameConstants constants = make_frame_constants(scene, args.width, args.height);
    // An FFT ocean's passes import its spectrum buffer, which only a device can hold:
    // for such scenes alone this command makes one.
    std::unique_ptr<Context> context;
    std::unique_ptr<passes::OceanSpectrumBuffer> ocean;
    if (scene.water && scene.water->waves.model == WaveModel::FftOcean) {
        context = std::make_unique<Context>(ContextOptions{});
        ocean = std::make_unique<passes::OceanSpectrumBuffer>(
            *context, std::make_shared<const FftOceanSpectrum>(
                          make_ocean_spectrum(scene.water->waves.ocean, scene.water->waves.seed)));
    }
    // Receiver meshes, like the ocean's spectrum, live on a device: made only when present.
    std::unique_ptr<passes::ReceiverMeshes> receivers;
    if (!scene.receivers.empty()) {
        if (!context) context = std::make_unique<Context>(ContextOptions{});
        receivers = std::make_unique<passes::ReceiverMeshes>(*context, scene.receivers);
    }
    build_frame_graph(graph, scene, &constants, args.width, args.height, VK_NULL_HANDLE, ocean.get(), receivers.get());
    graph.compile(args.width, args.height);
    std::printf("%s", graph.describe().c_str());
    std::printf("on a CPU device (lavapipe, 2 cores): %s\n",
                estimate_cpu_frame(scene, graph.needs(), args.width, args.height).describe().c_str());
    if (args.barriers) std::printf("barriers:\n%s", graph.dump_barriers().c_str());
    if (!args.dot.empty()) {
        require_writable_file_path(args.dot);
        write_file_checked(args.dot, graph.to_dot());
        std::printf("wrote %s\n", args.dot.c_str());
    }
    return kExitOk;
}

}  // namespace

Run add_passes_command(CLI::App& app) {
    auto args = std::make_shared<PassesArgs>();
    CLI::App* command = app.add_subcommand("passes", "Print the frame graph a scene compiles to, and why");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    add_image_size_options(*command, args->width, args->height);
    command->add_option("--dot", args->dot, "Also write the graph as Graphviz to this file");
    command->add_flag("--barriers", args->barriers, "Also print every derived barrier");
    command->footer(
        "Examples:\n"
        "  vkwater passes scenes/pool.json\n"
        "  vkwater passes scenes/lake.json --dot build/lake.dot\n");
    return [args] { return run_passes(*args); };
}

}  // namespace vkw::cli
