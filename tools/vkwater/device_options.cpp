// Options several subcommands share: the Vulkan device, the scene's file scope, the image size, the
// samples per pixel; and the loading of the scene they name.
#include "engine/scene/scene_loader.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/console.hpp"

namespace vkw::cli {

void add_device_options(CLI::App& command, DeviceOptions& options) {
    command.add_option("--device", options.device,
                       "Use the Vulkan device whose name contains this text (default: a discrete, then an "
                       "integrated GPU, then the CPU device lavapipe)");
    command.add_flag("--validation", options.validation,
                     "Run with VK_LAYER_KHRONOS_validation and synchronization validation; any error or "
                     "warning fails the run (exit 2)");
}

void add_scene_options(CLI::App& command, std::string& scene, std::vector<std::string>& overrides,
                       bool& allow_outside_paths) {
    command.add_option("scene", scene, "Scene file (JSON, see scenes/README.md)")->required();
    command.add_option("--set", overrides, "Override a scene field: key.path=value (repeatable)");
    command.add_flag("--allow-outside-paths", allow_outside_paths,
                     "Let the scene read files outside its own folder tree (glTF files, their buffers and "
                     "images); by default such a name is refused");
}

Scene load_command_scene(const std::string& scene, const std::vector<std::string>& overrides,
                         bool allow_outside_paths) {
    Scene loaded = load_scene(scene, overrides, {.allow_outside_paths = allow_outside_paths});
    print_warnings(scene_warnings(loaded));
    return loaded;
}

void add_image_size_options(CLI::App& command, uint32_t& width, uint32_t& height) {
    command.add_option("--width", width, "Image width in pixels")->check(CLI::Range(1u, 16384u))->capture_default_str();
    command.add_option("--height", height, "Image height in pixels")
        ->check(CLI::Range(1u, 16384u))
        ->capture_default_str();
}

void add_spp_option(CLI::App& command, int64_t& spp, const std::string& how) {
    command.add_option("--spp", spp, "Samples per pixel, a square k^2 (1: each pixel's centre); " + how)
        ->capture_default_str();
}

void add_render_scale_option(CLI::App& command, double& render_scale) {
    command
        .add_option("--render-scale", render_scale,
                    "Render the scene at this fraction of the image's width and height, then stretch it to the "
                    "image with the bilinear filter (0 < S <= 1; 0.5 costs about a quarter of the per-pixel "
                    "passes)")
        ->check(CLI::Range(1e-3, 1.0))
        ->capture_default_str();
}

}  // namespace vkw::cli
