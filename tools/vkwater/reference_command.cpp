// vkwater reference SCENE --out ref.exr: the CPU reference renderer of the model
// (docs/model.md section 1), for measuring the real-time renderer's error.
#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/reference_renderer.hpp"
#include "tools/reference/scene_hash.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/console.hpp"
#include "tools/vkwater/image_provenance.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

namespace vkw::cli {
namespace {

struct ReferenceArgs {
    std::string scene;
    std::string out;
    uint32_t width = 400;
    uint32_t height = 300;
    unsigned threads = 0;
    double cells_per_wavelength = ref::WaterTransport::Quality{}.cells_per_wavelength;
    uint32_t in_scatter_planes = ref::WaterTransport::Quality{}.in_scatter_levels;
    uint32_t in_scatter_texels = ref::WaterTransport::Quality{}.in_scatter_texels;
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
    std::string manifest;
    int64_t spp = 1;
    uint32_t floor_texels = ref::WaterTransport::Quality{}.floor_texels;
    bool measure_texels = false;
    bool footprint_caustics = false;
};

// The remaining error of the reference itself, as relMSE: the flat-water transport is
// closed form in double precision, and its one numerical integral (T_hemi) is exact to
// ~1e-9 relative, so relMSE ~ (1e-9)^2. Wavy water adds the floor caustics' change on
// refinement (squared: a relative RMS change r is a relMSE of about r^2).
constexpr double kClosedFormRelMse = 1e-18;

// The relMSE of `test` against `reference`'s caustic layer; 0 where that layer is dark (the
// flat scenes seen from above the water's reach), which relMSE, scaled by its mean, refuses.
double caustic_layer_rel_mse(const metrics::RgbView& test, const ImageRGBA32F& reference) {
    const metrics::RgbView caustic = metrics::layer_view(reference, "caustic");
    double lit = 0.0;
    for (size_t p = 0; p < caustic.pixel_count(); ++p) lit += caustic.channel(p, 0);
    if (!(lit > 0.0)) return 0.0;
    return metrics::rel_mse(test, caustic, metrics::counted_pixels(reference.width, reference.height, nullptr));
}

// How far the caustic layer moves one level coarser (its texel doubled, or half the beam cells),
// as the caustic layer's relMSE (tools/metrics): the estimate of that resolution's share of the
// reference's error, once the resolution is in its converging range (the change to twice the
// texel then exceeds the error at the texel; a texel wider than the caustics' features changes
// little on doubling, and the estimate says nothing there).
double coarser_change_rel_mse(const ImageRGBA32F& image, const ref::ReferenceReport& report) {
    metrics::RgbView coarser = metrics::layer_view(image, "caustic");
    coarser.values = report.caustic_coarser.data();
    return caustic_layer_rel_mse(coarser, image);
}

// The caustics' texel against the pixels that read it (ReferenceOptions::measure_texels).
nlohmann::ordered_json texel_record(const ImageRGBA32F& image, const ref::ReferenceReport& report) {
    const ref::PixelFootprints& footprints = report.footprints;
    return {{"caustic_texel_m", report.caustic_texel},  // 0: closed form, or averaged over footprints
            {"pixels_under_water_measured", footprints.widths.size()},
            {"pixel_footprint_width_m",
             {{"quantile_0.01", footprints.quantile(0.01)},
              {"quantile_0.1", footprints.quantile(0.1)},
              {"median", footprints.quantile(0.5)}}},
            // The fraction of those pixels whose footprint is at least 4 texels wide (the
            // texel at most a quarter of the pixel); over footprints every sample averages over
            // its stratum's own, 1/k of its pixel's.
            {"pixels_at_least_4_texels_wide",
             report.caustic_texel > 0.0 ? footprints.fraction_at_least(4.0 * report.caustic_texel) : 1.0},
            {"coarser", report.coarser_caustics},
            {"caustic_coarser_change_rel_mse", coarser_change_rel_mse(image, report)}};
}

// The image and caustic layer's relMSE against the same reference at half the strata per side:
// the box filter's own share of the error (the integration over the pixel converging).
struct FilterChange {
    uint32_t samples = 0;
    double rel_mse = 0.0, caustic_rel_mse = 0.0, seconds = 0.0;
};

FilterChange measure_filter_change(const Scene& scene, const ref::ReferenceOptions& options,
                                   const ImageRGBA32F& image) {
    ref::ReferenceOptions coarser = options;
    coarser.filter = pixel_filter_from_spp(int64_t{options.filter.samples} / 4);
    coarser.measure_texels = false;
    const auto start = std::chrono::steady_clock::now();
    const ImageRGBA32F other = ref::render_reference(scene, coarser);
    FilterChange change;
    change.samples = coarser.filter.samples;
    change.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::vector<size_t> pixels = metrics::counted_pixels(image.width, image.height, nullptr);
    change.rel_mse = metrics::rel_mse(metrics::rgb_view(other), metrics::rgb_view(image), pixels);
    change.caustic_rel_mse = caustic_layer_rel_mse(metrics::layer_view(other, "caustic"), image);
    return change;
}

// Adds or replaces this reference's entry in the manifest (tests/references/manifest.json):
// the scene file's hash, the settings, the seed, the estimated error and the time taken.
void record_in_manifest(const ReferenceArgs& args, double seconds, const ImageRGBA32F& image,
                        const ref::ReferenceReport& report, const std::optional<FilterChange>& filter_change) {
    nlohmann::ordered_json manifest = nlohmann::ordered_json::object();
    if (std::filesystem::exists(args.manifest)) {
        std::ifstream in(args.manifest);
        manifest = nlohmann::ordered_json::parse(in, nullptr, /*allow_exceptions=*/false);
        if (manifest.is_discarded()) throw UserError(args.manifest + ": not valid JSON");
    }
    const std::filesystem::path scene = args.scene;
    // With the texels measured, the caustics' change one level coarser joins the estimate (the
    // caustic layer's, an upper bound for the image's, whose caustic is one term of its
    // radiance), and so does the image's change at a quarter of the samples per pixel.
    const std::optional<nlohmann::ordered_json> texels =
        args.measure_texels ? std::optional(texel_record(image, report)) : std::nullopt;
    const double estimated_rel_mse = kClosedFormRelMse +
                                     report.caustic_refinement_change * report.caustic_refinement_change +
                                     (texels ? (*texels)["caustic_coarser_change_rel_mse"].get<double>() : 0.0) +
                                     (filter_change ? filter_change->rel_mse : 0.0);
    const std::filesystem::path base = std::filesystem::path(args.manifest).parent_path();
    nlohmann::ordered_json entry = {{"scene", std::filesystem::relative(scene, base).generic_string()},
                                    {"scene_hash", ref::scene_file_hash(scene)},
                                    {"reference", std::filesystem::relative(args.out, base).generic_string()},
                                    {"width", args.width},
                                    {"height", args.height},
                                    {"overrides", args.overrides},
                                    {"seed", 0},
                                    {"samples_per_pixel", args.spp},
                                    {"cells_per_wavelength", args.cells_per_wavelength},
                                    {"in_scatter_planes", args.in_scatter_planes},
                                    {"in_scatter_texels", args.in_scatter_texels},
                                    {"floor_texels", args.floor_texels},
                                    {"footprint_caustics", args.footprint_caustics},
                                    {"estimated_rel_mse", estimated_rel_mse},
                                    {"caustic_refinement_change", report.caustic_refinement_change},
                                    {"approximations", report.approximations},
                                    {"seconds", seconds}};
    if (report.surface_height_error_bound > 0.0) {
        // The FFT ocean's sampled surface: its error bound (the surface is not exact).
        entry["surface_height_error_bound_m"] = report.surface_height_error_bound;
        entry["surface_slope_error_bound"] = report.surface_slope_error_bound;
    }
    if (texels) entry["texels"] = *texels;
    if (filter_change) {
        entry["filter_change"] = {{"samples_per_pixel", filter_change->samples},
                                  {"rel_mse", filter_change->rel_mse},
                                  {"caustic_rel_mse", filter_change->caustic_rel_mse},
                                  {"seconds", filter_change->seconds}};
    }
    manifest[scene.filename().string()] = std::move(entry);
    write_file_checked(args.manifest, manifest.dump(2) + "\n");
}

int run_reference(const ReferenceArgs& args) {
    const Scene scene = load_command_scene(args.scene, args.overrides, args.allow_outside_paths);
    require_writable_file_path(args.out);
    if (!args.manifest.empty()) require_writable_file_path(args.manifest);
    ref::ReferenceOptions options;
    options.width = args.width;
    options.height = args.height;
    // More threads than the hardware runs only cost memory and start-up (100000 made the thread
    // creation fail).
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    options.threads = args.threads;
    if (args.threads > hardware) {
        std::printf("note: --threads %u: using %u, the hardware threads of this machine\n", args.threads, hardware);
        options.threads = hardware;
    }
    options.filter = pixel_filter_from_spp(args.spp);
    if (args.footprint_caustics && !options.filter.is_box()) {
        // Over one sample the footprint would be the whole pixel's: a box-filtered caustic in a
        // point-sampled image, which no comparison could name.
        throw UserError(
            "--footprint-caustics: integrates over each stratum of a box filter (accepted: with --spp 4 "
            "or more, not --spp " +
            std::to_string(args.spp) + ")");
    }
    options.quality.caustic_in_scatter = true;  // the model's godrays under waves
    options.quality.cells_per_wavelength = args.cells_per_wavelength;
    options.quality.in_scatter_levels = args.in_scatter_planes;
    options.quality.in_scatter_texels = args.in_scatter_texels;
    options.quality.floor_texels = args.floor_texels;
    options.quality.ocean_floor_texels = args.floor_texels;
    options.measure_texels = args.measure_texels;
    options.quality.caustics_over_footprints = args.footprint_caustics;
    // From the start: a reference is never quick enough to leave silent (console.hpp).
    auto progress = std::make_shared<Progress>("reference");
    options.progress = [progress](double fraction) { progress->report(fraction); };
    const auto start = std::chrono::steady_clock::now();
    ref::ReferenceReport report;
    ImageRGBA32F image = ref::render_reference(scene, options, &report);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    require_finite_image(image, "the reference image");
    std::optional<FilterChange> filter_change;
    if (args.measure_texels && options.filter.side() % 2 == 0) {
        filter_change = measure_filter_change(scene, options, image);
        std::printf("the box filter's change from %u to %u samples per pixel: relMSE %.3g (caustic layer %.3g)\n",
                    filter_change->samples, options.filter.samples, filter_change->rel_mse,
                    filter_change->caustic_rel_mse);
    }
    char time[64], device[64];
    std::snprintf(time, sizeof time, "%.2f s, the whole image", seconds);
    std::snprintf(device, sizeof device, "CPU, %u threads", options.threads == 0 ? hardware : options.threads);
    image.attributes = image_attributes(
        {args.scene, args.overrides, "reference", options.filter.describe(), device, time}, scene.camera);
    write_exr(args.out, image);
    std::printf("wrote %s (%ux%u, reference, layers RGBA, caustic, inscatter) in %.2f s\n", args.out.c_str(),
                args.width, args.height, seconds);
    if (!args.manifest.empty()) {
        record_in_manifest(args, seconds, image, report, filter_change);
        std::printf("recorded in %s\n", args.manifest.c_str());
    }
    return kExitOk;
}

}  // namespace

Run add_reference_command(CLI::App& app) {
    auto args = std::make_shared<ReferenceArgs>();
    CLI::App* command =
        app.add_subcommand("reference", "Render a scene with the CPU reference renderer (ground truth)");
    add_scene_options(*command, args->scene, args->overrides, args->allow_outside_paths);
    command->add_option("--out,-o", args->out, "Output OpenEXR file (RGBA and the layers caustic and inscatter)")
        ->required();
    add_image_size_options(*command, args->width, args->height);
    command
        ->add_option("--threads", args->threads,
                     "Worker threads (0: every hardware thread; more than the hardware has are clamped to it, with a "
                     "note)")
        ->capture_default_str();
    add_spp_option(*command, args->spp, "more a box filter of k x k rays jittered within their strata");
    command
        ->add_option("--cells-per-wavelength", args->cells_per_wavelength,
                     "Wavy water: surface cells per shortest wavelength of the beam-mapped caustics (the "
                     "estimate compares against half as many); more lowers the reference's error and costs "
                     "about its square in time")
        ->check(finite_number() & CLI::Range(4.0, 256.0))
        ->capture_default_str();
    command
        ->add_option("--in-scatter-planes", args->in_scatter_planes,
                     "Wavy water: depths at which the in-scatter's caustic modulation is mapped (linear between "
                     "them); the time grows about linearly with it")
        ->check(CLI::Range(2u, 1024u))
        ->capture_default_str();
    command
        ->add_option("--in-scatter-texels", args->in_scatter_texels,
                     "Wavy water: texels per side of each in-scatter plane's map over the floor")
        ->check(CLI::Range(16u, 8192u))
        ->capture_default_str();
    command
        ->add_option("--floor-texels", args->floor_texels,
                     "Wavy water: texels per side of the floor's caustic map (the FFT ocean's: per period) and the "
                     "side of the beams' averaging patch under meshes (the floor's side over it); even, since "
                     "--measure-texels compares against 2 x 2 blocks; memory 48 bytes per texel while it is built")
        ->check(CLI::Range(16u, 16384u) &
                CLI::Validator(
                    [](std::string& value) {
                        return std::stoul(value) % 2 == 0
                                   ? std::string()
                                   : value + " is odd (accepted: an even number from 16 to 16384)";
                    },
                    "EVEN"))
        ->capture_default_str();
    command->add_flag("--footprint-caustics", args->footprint_caustics,
                      "Wavy water (not the FFT ocean): average the caustics each sample sees over its share of its "
                      "pixel's footprint on the receiver (the exact beams, --cells-per-wavelength of them), not over "
                      "a texel of the floor's map; the box-filtered references use it");
    command->add_flag("--measure-texels", args->measure_texels,
                      "Measure the caustics' texel against the pixels that read it (their footprints under the "
                      "water; the caustic layer at twice the texel) and record it with --manifest");
    command->add_option("--manifest", args->manifest,
                        "Record this reference (scene hash, settings, estimated error, time) in a JSON manifest");
    command->footer(
        "Examples:\n"
        "  vkwater reference scenes/calm.json --out build/calm-ref.exr\n"
        "  vkwater reference scenes/pool.json --out build/pool-ref.exr --spp 4 --threads 2\n");
    return [args] { return run_reference(*args); };
}

}  // namespace vkw::cli
