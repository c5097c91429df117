// vkwater povray SCENE --out FILE.pov: a scene as POV-Ray 3.7 input that renders the sun's
// irradiance on a window of the floor (tools/povray/povray_scene.hpp), for checking the
// reference renderer's floor caustics against an independent photon tracer (tests/povray).
#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/file_paths.hpp"
#include "tools/povray/povray_scene.hpp"
#include "tools/vkwater/commands.hpp"

#include <cstdio>
#include <memory>

namespace vkw::cli {
namespace {

struct PovrayArgs {
    std::string scene;
    std::string out;
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
    std::vector<double> window;
    double side = 1.0;
    pov::PovrayOptions options;
};

int run_povray(const PovrayArgs& args) {
    const Scene scene = load_command_scene(args.scene, args.overrides, args.allow_outside_paths);
    require_writable_file_path(args.out);
    pov::PovrayOptions options = args.options;
    options.window = args.window.empty()
                         ? pov::lit_floor_window(scene, args.side)
                         : pov::FloorWindow{args.window[0], args.window[1], args.window[2], args.window[3]};
    const std::string text = pov::povray_floor_scene(scene, options);
    write_file_checked(args.out, text);
    const pov::FloorWindow& w = options.window;
    std::printf("wrote %s: the floor's sun irradiance over x %g..%g m, z %g..%g m (W m^-2 per pixel)\n",
                args.out.c_str(), w.x0, w.x1, w.z0, w.z1);
    std::printf("render it with: povray +I%s +Oout.exr +FE +W<w> +H<h> -D (w : h = %g : %g)\n", args.out.c_str(),
                w.x1 - w.x0, w.z1 - w.z0);
    return kExitOk;
}

}  // namespace

Run add_povray_command(CLI::App& app) {
    auto args = std::make_shared<PovrayArgs>();
    CLI::App* command = app.add_subcommand(
        "povray", "Write the scene's floor irradiance as POV-Ray 3.7 input (photons, media absorption)");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    command->add_option("--out,-o", args->out, "Output POV-Ray file")->required();
    command
        ->add_option("--window", args->window,
                     "Floor window x0 z0 x1 z1 in metres (default: a square of --side around the middle of "
                     "the floor lit through the surface)")
        ->expected(4);
    command->add_option("--side", args->side, "Side of the default window, m")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command
        ->add_option("--mesh-cells", args->options.mesh_cells,
                     "Water surface cells per side (default: the scene's water.grid_resolution)")
        ->check(CLI::Range(1u, 4096u));
    command->add_option("--photon-spacing", args->options.photon_spacing, "Metres between photons across the beam")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command
        ->add_option("--gather-radius", args->options.gather_radius,
                     "Fixed photon gather radius in metres (default 0: POV-Ray's adaptive radius)")
        ->check(CLI::NonNegativeNumber);
    command->footer(
        "Examples:\n"
        "  vkwater povray scenes/calm.json --out build/calm.pov\n");
    return [args] { return run_povray(*args); };
}

}  // namespace vkw::cli
