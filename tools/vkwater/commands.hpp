// The vkwater subcommands. Each registers its options on the CLI11 app and returns
// the function that runs it; main() maps exceptions to exit codes
// (0 ok, 1 user error, 2 internal or Vulkan failure).
#pragma once

#include <CLI/CLI.hpp>

#include "engine/scene/scene.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace vkw::cli {

using Run = std::function<int()>;

// Options every GPU subcommand shares.
struct DeviceOptions {
    std::string device;
    bool validation = false;
};
void add_device_options(CLI::App& command, DeviceOptions& options);

// What every command that loads a scene takes: the SCENE argument, --set overrides (repeatable),
// and --allow-outside-paths (the scene may read files outside its own folder tree,
// engine/scene/file_scope.hpp).
void add_scene_options(CLI::App& command, std::string& scene, std::vector<std::string>& overrides,
                       bool& allow_outside_paths);

// The scene those options name, loaded (vkw::UserError for a bad one), its warnings printed on
// stderr (what its files ask for that is left out; console.hpp).
Scene load_command_scene(const std::string& scene, const std::vector<std::string>& overrides, bool allow_outside_paths);

// --width and --height in pixels, each 1 to 16384 (the largest image side any command takes).
void add_image_size_options(CLI::App& command, uint32_t& width, uint32_t& height);

// --spp N, samples per pixel (engine/scene/pixel_filter.hpp checks it): `how` says what this
// command does with them.
void add_spp_option(CLI::App& command, int64_t& spp, const std::string& how);

// --render-scale S: the scene's passes render at S times the image's size per side, stretched to it
// at the frame's end (passes/frame/upscale.hpp).
void add_render_scale_option(CLI::App& command, double& render_scale);

// A check for number options that must be above 0, with a message that says so (CLI::PositiveNumber
// prints the whole double range). Put finite_number() before it.
inline CLI::Validator positive_number() {
    return CLI::Validator(
        [](std::string& text) {
            return std::strtod(text.c_str(), nullptr) > 0.0 ? std::string()
                                                            : "'" + text + "' is not above 0 (accepted: > 0)";
        },
        "POSITIVE");
}

// A check for number options that refuses NaN and infinities: CLI::Range lets NaN through, since
// every comparison with it is false.
inline CLI::Validator finite_number() {
    return CLI::Validator(
        [](std::string& text) {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            return std::isfinite(value) ? std::string() : "'" + text + "' is not a finite number";
        },
        "FINITE");
}

Run add_render_command(CLI::App& app);
Run add_passes_command(CLI::App& app);
Run add_reference_command(CLI::App& app);
Run add_compare_command(CLI::App& app);
Run add_bench_command(CLI::App& app);
Run add_povray_command(CLI::App& app);
Run add_view_command(CLI::App& app);
Run add_check_command(CLI::App& app);

}  // namespace vkw::cli
