// An independent cross-check of the reference renderer's floor caustics: POV-Ray 3.7's
// photon map renders the sun's irradiance on a window of the floor (tools/povray) for the `calm`
// scene and for calm with a sine surface; the reference's beam-mapped floor map
// (tools/reference/floor_caustics.hpp) computes the same irradiance. Compared: the wavy-to-flat
// ratio per bin of the window, the ratio of the total fluxes, and calm's absolute irradiance.
//
// POV-Ray traits and how they are handled here:
// - it stores each photon's colour as RGBE (8-bit mantissas sharing the exponent of the largest
//   channel) and truncates: a channel loses up to 2^-8 (max channel / channel) of each photon.
//   calm's clear-ocean red is 12x weaker than its blue at the floor, so red loses up to 9% (4%
//   measured): red is left out; green and blue (ratio 0.91) lose at most 2^-7 / 0.91 = 0.86%;
// - its gather radius adapts to the photon density, which biases focal lines (the smoothing
//   spreads a peak); bins crossed by a focal line are left out of the per-bin check (below);
// - it omits the n^2 of radiance across the surface: irrelevant here, no camera ray crosses it;
// - left-handed axes: the writer negates z, so the window is not mirrored (a mirrored sine at
//   30 degrees would fail the per-bin check).
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "tools/povray/povray_scene.hpp"
#include "tools/reference/floor_caustics.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>

namespace vkw::test {
namespace {

// The reference's floor map: the floor square [-2, 2]^2 m in 512 texels of 1/128 m; the window
// is 1 m (128 texels) square on texel edges, rendered by POV-Ray at 64 x 64 pixels and compared
// in 8 x 8 bins of 12.5 cm (16 x 16 texels, 8 x 8 pixels).
constexpr double kFloorHalfExtent = 2.0;
constexpr int kTexels = 512;
constexpr double kTexel = 2.0 * kFloorHalfExtent / kTexels;
constexpr double kWindow = 1.0;
constexpr int kPixels = 64;
constexpr int kBins = 8;
// Water surface cells per side, for POV-Ray's mesh and the reference's beams alike: 2.4 m of
// water holds 2.4 wavelengths of 1 m, about 107 cells each.
constexpr uint32_t kCells = 256;

const std::filesystem::path kOut = std::filesystem::path(VKWATER_BINARY_DIR) / "tests/povray/out";

// calm, with the water cut to 2.4 m square (the window needs 1 m plus the 0.81 m shift of the
// refracted beam plus the waves' deflection; POV-Ray shoots photons at the whole water body).
std::vector<std::string> calm_overrides() { return {"water.half_extent=1.2", "floor.half_extent=2"}; }

Scene calm() { return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json", calm_overrides()); }

// The same with h = A sin(k (x cos 30 + z sin 30)), A = 0.03 m, lambda = 1 m (slope 0.19): the
// first focus of a vertical sun would lie at f - A = 3.35 m, so the 2 m floor sees bands from 0.5x to
// 4x the flat irradiance but no cusp. The 30 degrees make the pattern asymmetric in x and in z.
Scene sine() {
    std::vector<std::string> overrides = calm_overrides();
    overrides.push_back(
        R"(water.waves={"model":"sum","components":[{"amplitude":0.03,"wavelength":1,"direction_deg":30}]})");
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json", overrides);
}

pov::PovrayOptions options_for(const Scene& scene) {
    pov::PovrayOptions options;
    pov::FloorWindow w = pov::lit_floor_window(scene, kWindow);
    w.x0 = std::round(w.x0 / kTexel) * kTexel, w.z0 = std::round(w.z0 / kTexel) * kTexel;  // on texel edges
    w.x1 = w.x0 + kWindow, w.z1 = w.z0 + kWindow;
    options.window = w;
    options.mesh_cells = kCells;
    // 4 mm between photons: about 8 photons per pixel on flat water, so the automatic gather
    // (20 to 100 photons) smooths over about 2 pixels.
    options.photon_spacing = 0.004;
    return options;
}

ImageRGBA32F render_with_povray(const Scene& scene, const pov::PovrayOptions& options, const std::string& name) {
    std::filesystem::create_directories(kOut);
    const std::filesystem::path pov = kOut / (name + ".pov"), exr = kOut / (name + ".exr"),
                                log = kOut / (name + ".log");
    std::ofstream(pov) << pov::povray_floor_scene(scene, options);
    std::filesystem::remove(exr);
    const std::string command = "povray +I" + pov.string() + " +O" + exr.string() + " +FE +W" +
                                std::to_string(kPixels) + " +H" + std::to_string(kPixels) + " -D -V > " + log.string() +
                                " 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    std::printf("%s: POV-Ray took %.2f s\n", name.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (status != 0) {
        std::ostringstream text;
        text << std::ifstream(log).rdbuf();
        throw InternalError("'" + command + "' failed (status " + std::to_string(status) +
                            "; is POV-Ray installed? tools/install-deps.sh installs it):\n" + text.str());
    }
    return read_exr(exr);
}

// Per bin and channel: the window's irradiance averaged over the bin.
struct Bins {
    std::vector<glm::dvec3> mean = std::vector<glm::dvec3>(kBins * kBins, glm::dvec3(0.0));
    std::vector<double> spread = std::vector<double>(kBins * kBins, 1.0);  // max / min texel (green)
    glm::dvec3 total() const {
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& m : mean) sum += m;
        return sum;
    }
};

Bins bin_povray(const ImageRGBA32F& image, const glm::dvec3& camera_transmittance) {
    Bins bins;
    constexpr int per_bin = kPixels / kBins;
    for (int y = 0; y < kPixels; ++y) {
        for (int x = 0; x < kPixels; ++x) {
            const float* p = image.pixel(x, y);
            bins.mean[(y / per_bin) * kBins + x / per_bin] +=
                glm::dvec3(p[0], p[1], p[2]) / camera_transmittance / double(per_bin * per_bin);
        }
    }
    return bins;
}

Bins bin_reference(const ref::FloorCausticMap& map, const pov::FloorWindow& window) {
    Bins bins;
    constexpr int per_bin = kTexels / 4 / kBins;  // the window is a quarter of the floor's side
    const int i0 = int(std::lround((window.x0 + kFloorHalfExtent) / kTexel));
    const int j0 = int(std::lround((window.z0 + kFloorHalfExtent) / kTexel));
    std::vector<double> lo(kBins * kBins, 1e300), hi(kBins * kBins, 0.0);
    for (int j = 0; j < kBins * per_bin; ++j) {
        for (int i = 0; i < kBins * per_bin; ++i) {
            const int b = (j / per_bin) * kBins + i / per_bin;
            const glm::dvec3& e = map.texels()[size_t(j0 + j) * kTexels + (i0 + i)];
            bins.mean[b] += e / double(per_bin * per_bin);
            lo[b] = std::min(lo[b], e.y);
            hi[b] = std::max(hi[b], e.y);
        }
    }
    for (int b = 0; b < kBins * kBins; ++b) bins.spread[b] = hi[b] / lo[b];
    return bins;
}

ref::FloorCausticMap reference_map(const Scene& scene) {
    const std::unique_ptr<WaterSurface> surface =
        make_surface(scene.water->waves, scene.water->level, scene.water->time);
    return ref::FloorCausticMap(scene, *surface, kTexels, kCells);
}

TEST(povray_cross_check, SineOverFlatFloorIrradianceMatchesTheReference) {
    const Scene flat = calm(), wavy = sine();
    const pov::PovrayOptions options = options_for(flat);
    const glm::dvec3 camera = pov::camera_transmittance(flat);
    const Bins pov_flat = bin_povray(render_with_povray(flat, options, "calm"), camera);
    const Bins pov_wavy = bin_povray(render_with_povray(wavy, options, "sine"), camera);
    const Bins ref_flat = bin_reference(reference_map(flat), options.window);
    const Bins ref_wavy = bin_reference(reference_map(wavy), options.window);

    // Error budget of a bin's POV-Ray value, relative: RGBE truncation in [-0.86%, 0] (see the top);
    // photon noise: 3% per pixel measured on flat water, over the 64 pixels of a bin whose gathers
    // (radius ~2 pixels) overlap, about 16 independent estimates: 0.75%; the gather's smoothing over
    // ~1.6 cm where the irradiance bends (bins crossed by a focal line are left out). A ratio of two
    // bins doubles the noise: about 2 x 0.75% + 0.86% = 2.4% < 5%, the limit this cross-check sets.
    // Totals: RGBE as above, 0.86%, the noise averaged over 64 bins (0.2%), and the gather's reach
    // over the window's rim (flux in and out cancel to first order): within the 1% limit.
    constexpr double kBinLimit = 0.05, kTotalLimit = 0.01;
    // A focal line crosses a bin where its texels differ by more than 2x (flat water's map is
    // uniform; the sine's smooth bands vary by up to 1.7x within a bin).
    constexpr double kFocalSpread = 2.0;
    int compared = 0, focal = 0;
    double worst = 0.0;
    for (int b = 0; b < kBins * kBins; ++b) {
        if (ref_wavy.spread[b] > kFocalSpread) {
            ++focal;
            continue;
        }
        ++compared;
        for (int c = 1; c < 3; ++c) {  // green and blue (red: RGBE, see the top)
            const double pov_ratio = pov_wavy.mean[b][c] / pov_flat.mean[b][c];
            const double ref_ratio = ref_wavy.mean[b][c] / ref_flat.mean[b][c];
            const double error = pov_ratio / ref_ratio - 1.0;
            worst = std::max(worst, std::abs(error));
            EXPECT_LE(std::abs(error), kBinLimit) << "bin (" << b % kBins << ", " << b / kBins << ") channel " << c
                                                  << ": POV-Ray wavy/flat " << pov_ratio << ", reference " << ref_ratio;
        }
    }
    std::printf(
        "per-bin wavy/flat ratio: %d bins compared, %d crossed by a focal line; worst |error| %.4f (limit %.2f)\n",
        compared, focal, worst, kBinLimit);
    EXPECT_GE(compared, kBins * kBins / 2) << "too few bins away from focal lines to compare";

    for (int c = 1; c < 3; ++c) {
        const double pov_ratio = pov_wavy.total()[c] / pov_flat.total()[c];
        const double ref_ratio = ref_wavy.total()[c] / ref_flat.total()[c];
        std::printf("channel %d: total flux wavy/flat POV-Ray %.5f, reference %.5f: error %+.4f (limit %.2f)\n", c,
                    pov_ratio, ref_ratio, pov_ratio / ref_ratio - 1.0, kTotalLimit);
        EXPECT_LE(std::abs(pov_ratio / ref_ratio - 1.0), kTotalLimit) << "channel " << c;
        // calm alone, absolute: Fresnel, media absorption and geometry against the reference. The
        // budget above without the focal lines and with one image: 0.86% + 0.2% noise < 1.1%.
        const double absolute = pov_flat.total()[c] / ref_flat.total()[c] - 1.0;
        std::printf("channel %d: calm's floor irradiance POV-Ray / reference - 1 = %+.4f (limit 0.011)\n", c, absolute);
        EXPECT_LE(std::abs(absolute), 0.011) << "channel " << c;
    }
}

// The tool's command line: a scene it cannot export is one message naming the file and the
// field, exit 1; a good one writes the file.
TEST(povray_tool, RefusesASceneWithoutWaterAndWritesCalm) {
    std::filesystem::create_directories(kOut);
    const std::filesystem::path dry = kOut / "dry.json", log = kOut / "tool.log", out = kOut / "tool_calm.pov";
    std::ofstream(dry) << R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]}, "sun": {"elevation_deg": 60},
                             "sky": {"radiance": [1, 1, 1]}})";
    const std::string tool = std::string(VKWATER_TOOL) + " povray";
    const int refused =
        std::system((tool + " " + dry.string() + " --out " + out.string() + " > " + log.string() + " 2>&1").c_str());
    std::ostringstream message;
    message << std::ifstream(log).rdbuf();
    EXPECT_TRUE(WIFEXITED(refused) && WEXITSTATUS(refused) == 1) << message.str();
    EXPECT_NE(message.str().find(dry.string() + ": water: the scene has no water"), std::string::npos) << message.str();

    const std::string calm = (std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json").string();
    const int written =
        std::system((tool + " " + calm + " --out " + out.string() + " > " + log.string() + " 2>&1").c_str());
    EXPECT_EQ(written, 0);
    std::string first_line;
    std::getline(std::ifstream(out) >> std::ws, first_line);
    EXPECT_EQ(first_line.rfind("// vkwater povray: the sun's irradiance on the floor of", 0), 0u) << first_line;
}

}  // namespace
}  // namespace vkw::test
