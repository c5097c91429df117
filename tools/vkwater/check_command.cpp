// vkwater check SCENE: reads, overrides and validates a scene as every other command would, with
// no Vulkan device, and says in one line what it holds. Exit 0 for a valid scene, 1 with the
// loader's one-line error for anything else. The malformed-input corpus (tests/corpus) runs
// through it, and so can a user's editor or CI.
#include "engine/core/errors.hpp"
#include "tools/vkwater/commands.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace vkw::cli {
namespace {

struct CheckArgs {
    std::string scene;
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
};

std::string plural(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string describe_water(const Scene& scene) {
    if (!scene.water) return "no water";
    switch (scene.water->waves.model) {
        case WaveModel::Flat: return "flat water";
        case WaveModel::Sum: return "water of " + plural(scene.water->waves.components.size(), "wave");
        case WaveModel::FftOcean: return "an FFT ocean";
    }
    return "water";
}

int run_check(const CheckArgs& args) {
    const Scene scene = load_command_scene(args.scene, args.overrides, args.allow_outside_paths);
    std::printf("%s: a valid scene: %s, %s (vkwater passes %s shows the frame it makes)\n", args.scene.c_str(),
                describe_water(scene).c_str(), plural(scene.receivers.size(), "receiver").c_str(), args.scene.c_str());
    return kExitOk;
}

}  // namespace

Run add_check_command(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App* command =
        app.add_subcommand("check", "Read and validate a scene without a device: exit 0 if valid, else 1 and why");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    command->footer(
        "Examples:\n"
        "  vkwater check scenes/pool.json\n"
        "  vkwater check scenes/pool.json --set water.ior=1.5\n");
    return [args] { return run_check(*args); };
}

}  // namespace vkw::cli
