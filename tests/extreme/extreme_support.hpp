// Shared parts of the extreme-case suite: one small scene the cases override, the
// real-time renderer (lavapipe, validation, finite check after every pass) and the CPU reference
// on the same scene, the per-image checks every case makes, the continuity measure, and the
// caustic passes' receiver flux against the flux the surface intercepts.
//
// Every suite's name starts with "extreme_", so `ctest -R extreme` selects exactly these tests.
#pragma once

#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/floor_caustics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace vkw::test {

// Images of 64 x 48: every case renders several, on two shared cores.
inline constexpr uint32_t kExtremeWidth = 64;
inline constexpr uint32_t kExtremeHeight = 48;

// The base scene: flat water (n = 1.333) 1 m deep over a grey floor, 6 m square, a 192-cell grid
// (3.1 cm cells: 16 per wavelength of the suite's 0.5 m waves; the caustic map has 194 texels),
// clear-ocean water (g = 0.9), constant sky, the sun 60 degrees from the zenith in the south
// (azimuth 180: its glint lies behind the camera, out of the frame, so moving the sun moves no
// delta-like highlight through the pixels; the sun travels in the y-z plane, where the caustic
// map's photon lattice falls on its texels and flat water's map is exact,
// tests/caustics/caustics_flat_test.cpp). The camera, 1.5 m up at z = 1 m, looks north and 59
// degrees down with a 60 degree field of view: it sees the water (sky reflection, floor, in-
// scatter) between z = -1.7 and 1 m and the floor through it up to z = -2.6 m (-3.5 m at n = 1),
// away from the pool's southern rim: the floor there (z > 3 - d tan(theta_t), 1.27 m at n = 1 and
// the sun 60 degrees from the zenith, 1.86 m for a grazing sun at n = 1.333) would receive sunlight
// entering beyond the water's square, which the two renderers do not model alike (the photons
// start on the surface, the reference's flat beam anywhere).
// Godrays are off: under waves in a scattering medium they would replace the analytic in-scatter,
// and their passes (in progress as this suite was written) took 30 s per 64 x 48 frame on
// lavapipe; their extreme cases come with them.
inline constexpr const char* kExtremeBaseScene = R"({
  "description": "extreme-case suite base: small flat pool, clear-ocean water, sun in the south",
  "camera": {"position": [0, 1.5, 1], "target": [0, -1, -0.5], "fov_y_deg": 60, "near": 0.05, "far": 100},
  "sun": {"elevation_deg": 30, "azimuth_deg": 180, "irradiance": [2, 2, 2]},
  "sky": {"radiance": [0.4, 0.5, 0.6]},
  "floor": {"height": -1, "albedo": [0.5, 0.5, 0.5], "half_extent": 3},
  "water": {"level": 0, "ior": 1.333, "half_extent": 3, "grid_resolution": 192, "waves": {"model": "flat"}},
  "medium": {"preset": "clear-ocean"},
  "effects": {"godrays": {"mode": "off"}}
})";

// The base scene with `overrides` ("key.path=value", as the CLI's --set).
inline Scene extreme_scene(const std::vector<std::string>& overrides = {}) {
    return parse_scene(kExtremeBaseScene, "extreme-base.json", overrides);
}

// A pool 12 m square, for the closed-form cases whose rays reach further than the base's 6 m
// floor: straight rays at n = 1, rays reflected down by the surface's underside. Flat water only
// (its 64-cell grid resolves nothing but a plane; the reference's beams would cost 4 times more).
inline const std::vector<std::string> kWidePool = {"water.half_extent=6", "floor.half_extent=6",
                                                   "water.grid_resolution=64"};

// Two lists of overrides, one after the other.
inline std::vector<std::string> joined(std::vector<std::string> first, const std::vector<std::string>& second) {
    first.insert(first.end(), second.begin(), second.end());
    return first;
}

// A sine along x (h = A sin(2 pi x / lambda)) of slope A k, as a waves override.
inline std::string sine_waves(double slope, double wavelength = 0.5) {
    const double amplitude = slope * wavelength / (2.0 * 3.14159265358979323846);
    char text[256];
    std::snprintf(text, sizeof text,
                  R"(water.waves={"model":"sum","components":[{"amplitude":%.17g,"wavelength":%.17g}]})", amplitude,
                  wavelength);
    return text;
}

// The sun `zenith_deg` from the zenith in the south, as an override of its elevation (the loader's
// elevation form: exactly overhead at 90 degrees, below the horizon past 0).
inline std::string sun_at_zenith(double zenith_deg) {
    char text[96];
    std::snprintf(text, sizeof text, "sun.elevation_deg=%.17g", 90.0 - zenith_deg);
    return text;
}

inline RenderOptions extreme_options() {
    RenderOptions options;
    options.width = kExtremeWidth;
    options.height = kExtremeHeight;
    options.check_finite = true;  // every pass's float targets are scanned: a NaN names its pass
    options.timing = fg::TimingMode::None;
    return options;
}

inline ImageRGBA32F render_real_time(Renderer& renderer, const Scene& scene) {
    return renderer.render(scene, extreme_options()).image;
}

// Wavy water's floor caustics in the reference: 256 texels a side (2.3 cm over the 6 m floor,
// finer than the 5 to 10 cm a pixel covers there) and 16 cells per wavelength before refinement
// (32 after): the default 2048 texels would cost seconds per image. Folding surfaces cost far
// more (their footprints are long slivers, clipped against every texel of their bounding box):
// their cases take a coarser map, the images' stability being what they check.
inline constexpr ref::WaterTransport::Quality kSuiteQuality{256, 16.0};
inline constexpr ref::WaterTransport::Quality kFoldingQuality{64, 8.0};

inline ImageRGBA32F render_reference(const Scene& scene, const ref::WaterTransport::Quality& quality = kSuiteQuality) {
    ref::ReferenceOptions options{kExtremeWidth, kExtremeHeight, 0, {}};
    options.quality = quality;
    return ref::render_reference(scene, options);
}

// Assertions (1) and (2) of every case: every R, G, B value finite and >= 0.
inline void expect_finite_non_negative(const ImageRGBA32F& image, const std::string& what) {
    size_t non_finite = 0, negative = 0;
    for (size_t p = 0; p < image.pixel_count(); ++p) {
        for (int c = 0; c < 3; ++c) {
            const float v = image.rgba[4 * p + c];
            non_finite += !std::isfinite(v);
            negative += v < 0.0f;
        }
    }
    EXPECT_EQ(non_finite, 0u) << what << ": non-finite values";
    EXPECT_EQ(negative, 0u) << what << ": negative radiance";
}

inline double rel_mse(const ImageRGBA32F& test, const ImageRGBA32F& reference) {
    return metrics::rel_mse(metrics::rgb_view(test), metrics::rgb_view(reference),
                            metrics::counted_pixels(reference.width, reference.height, nullptr));
}

inline double mean_radiance(const ImageRGBA32F& image) {
    double sum = 0.0;
    for (size_t p = 0; p < image.pixel_count(); ++p)
        sum += image.rgba[4 * p] + image.rgba[4 * p + 1] + image.rgba[4 * p + 2];
    return sum / (3.0 * image.pixel_count());
}

// Flat water has no approximation left in the real-time shading: it equals the reference to
// fp32 rounding, relMSE < 1e-10 (tests/render/water_vs_reference_test.cpp derives the bound: a
// few hundred fp32 roundings, 1e-5 relative per value).
inline constexpr double kFlatWaterRelMse = 1e-10;

// Continuity (item 4): RMS(delta) = sqrt(relMSE(image(p + delta), image(p))).
struct Continuity {
    double rms_delta = 0.0, rms_half = 0.0;
    double ratio() const { return rms_delta / rms_half; }
};

inline Continuity continuity(const std::function<ImageRGBA32F(double)>& image_at, double p, double delta) {
    const ImageRGBA32F base = image_at(p);
    return {std::sqrt(rel_mse(image_at(p + delta), base)), std::sqrt(rel_mse(image_at(p + 0.5 * delta), base))};
}

// A smooth response halves its difference with the step: RMS(delta) / RMS(delta / 2) = 2 up to
// the curvature's share. [1.6, 2.5] is the band the suite accepts:
// a ratio near 1 would mean a jump (a discontinuity), near 4 a hidden second-order error.
inline constexpr double kContinuityRatioLow = 1.6, kContinuityRatioHigh = 2.5;

// The real-time renderer's continuity at p, delta against the reference's, on the scenes
// `scene_at(p)`: both ratios in the band, and RMS_rt(delta) <= C |delta| with
// C = RMS_ref(delta) / |delta| times `factor`.
inline void expect_continuous(const std::string& what, Renderer& renderer, const std::function<Scene(double)>& scene_at,
                              double p, double delta, double factor) {
    const Continuity rt = continuity([&](double x) { return render_real_time(renderer, scene_at(x)); }, p, delta);
    const Continuity ref = continuity([&](double x) { return render_reference(scene_at(x)); }, p, delta);
    const double c = ref.rms_delta / std::abs(delta);
    std::printf(
        "%s at %g, delta %g: real time RMS %.4e / %.4e (ratio %.3f), reference %.4e / %.4e (ratio %.3f), "
        "C = %.4e, RMS_rt / (C |delta|) = %.4f (limit %.2f)\n",
        what.c_str(), p, delta, rt.rms_delta, rt.rms_half, rt.ratio(), ref.rms_delta, ref.rms_half, ref.ratio(), c,
        rt.rms_delta / (c * std::abs(delta)), factor);
    EXPECT_GE(rt.ratio(), kContinuityRatioLow) << what;
    EXPECT_LE(rt.ratio(), kContinuityRatioHigh) << what;
    EXPECT_GE(ref.ratio(), kContinuityRatioLow) << what << " (reference)";
    EXPECT_LE(ref.ratio(), kContinuityRatioHigh) << what << " (reference)";
    EXPECT_LE(rt.rms_delta, factor * c * std::abs(delta)) << what;
}

// The caustic passes' inputs for `scene`, as the renderer fills them (passes/frame/renderer.cpp).
inline passes::CausticInputs scene_caustic_inputs(const Scene& scene) {
    const Water& water = *scene.water;
    passes::CausticInputs in;
    in.grid_resolution = water.grid_resolution;
    in.water_level = water.level;
    in.half_extent = water.half_extent;
    in.max_amplitude = make_surface(water.waves, water.level, water.time)->max_amplitude();
    in.sun_direction = scene.sun.direction;
    in.sun_irradiance = scene.sun.irradiance;
    in.ior = water.ior;
    in.sigma_t = scene.medium.sigma_t();
    in.floor_height = scene.floor.height;
    in.map_width = in.map_height = std::clamp(water.grid_resolution + 2, 16u, 16384u);
    return in;
}

// The caustic passes of `scene` alone, with the flux buffer and the resolved map read back.
inline CausticRun run_scene_caustics(Context& context, const Scene& scene) {
    const Water& water = *scene.water;
    const passes::WaterSurfaceInputs surface{water.level, water.half_extent, water.grid_resolution,
                                             water.time,  water.waves,       nullptr};
    return run_caustics(context, surface, scene_caustic_inputs(scene));
}

// W per channel: the flux the photon pass deposited on the floor plus what fell off the map.
inline glm::dvec3 receiver_flux(const CausticRun& run, const Scene& scene) {
    const passes::CausticMapFrame frame = passes::fit_caustic_map(scene_caustic_inputs(scene));
    glm::dvec3 total(0.0);
    const size_t texels = size_t(frame.width) * frame.height;
    for (int c = 0; c < 3; ++c) {
        long double sum = run.lost(c);
        for (size_t t = 0; t < texels; ++t) sum += run.texel(t, c);
        total[c] = double(sum) * frame.lsb[c];
    }
    return total;
}

// The flux the water surface intercepts, W per channel: E_s times the sum over the grid's cells
// of max(0, -s . a), a the cell's vector area from its diagonals (what a photon intercepts,
// caustic_photon.glsl), in double from the CPU surface at the same vertices. No photon carries
// more than its cell intercepts (T <= 1, exp(-sigma_t l) <= 1).
inline glm::dvec3 intercepted_flux(const Scene& scene) {
    const Water& water = *scene.water;
    const auto surface = make_surface(water.waves, water.level, water.time);
    const uint32_t r = water.grid_resolution;
    auto vertex = [&](uint32_t i, uint32_t j) {
        return surface->at_parameter(water.half_extent * (2.0 * i - r) / r, water.half_extent * (2.0 * j - r) / r)
            .position;
    };
    double sum = 0.0;
    if (scene.sun.direction.y >= 0.0) return glm::dvec3(0.0);
    for (uint32_t j = 0; j < r; ++j) {
        for (uint32_t i = 0; i < r; ++i) {
            const glm::dvec3 area =
                0.5 * glm::cross(vertex(i, j + 1) - vertex(i + 1, j), vertex(i + 1, j + 1) - vertex(i, j));
            sum += std::max(0.0, -glm::dot(scene.sun.direction, area));
        }
    }
    return scene.sun.irradiance * sum;
}

// Assertion (3): 0 <= receiver flux <= intercepted flux, and the resolved map finite and >= 0.
// Slack of the upper bound, relative: the GPU's fp32 vertices and area products (a few units of
// 2^-24 of each cell's area, summed: below 1e-5 of the total) and the fixed point's rounding (at
// most 4 LSB per photon, LSB <= 1e-9 of a flat texel's flux: 4e-9 per photon).
inline void expect_receiver_flux_bounded(const CausticRun& run, const Scene& scene, const std::string& what) {
    size_t bad = 0;
    for (const float e : run.irradiance) bad += !(std::isfinite(e) && e >= 0.0f);
    EXPECT_EQ(bad, 0u) << what << ": non-finite or negative caustic irradiance";
    const glm::dvec3 got = receiver_flux(run, scene), incoming = intercepted_flux(scene);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(got[c], 0.0) << what;
        EXPECT_LE(got[c], incoming[c] * (1.0 + 1e-5) + 1e-12) << what << " channel " << c;
    }
    std::printf("%s: receiver flux %.6g W of %.6g W intercepted (green)\n", what.c_str(), got.y, incoming.y);
}

// All the sunlight that enters the slab holding the water's surface (|x|, |z| <= E + A, |y - level|
// <= A, A the amplitude bound, which also bounds the sideways motion of Gerstner points), W per
// channel: E_s times the slab's cross-section seen from the sun. Light that reaches the floor
// through the surface crossed this slab first, folds or not: a bound for either renderer.
inline glm::dvec3 slab_flux(const Scene& scene) {
    const Water& water = *scene.water;
    if (scene.sun.direction.y >= 0.0) return glm::dvec3(0.0);
    const double a = make_surface(water.waves, water.level, water.time)->max_amplitude();
    const double w = 2.0 * (water.half_extent + a), h = 2.0 * a;
    const glm::dvec3 s = glm::abs(scene.sun.direction);
    return scene.sun.irradiance * (s.y * w * w + (s.x + s.z) * w * h);
}

// The reference's floor irradiance map as its renderer builds it for `quality` (the finer of the
// two maps: 2 cells_per_wavelength cells per shortest wavelength), and its receiver flux against
// slab_flux, assertion (3).
inline void expect_reference_flux_bounded(const Scene& scene, const ref::WaterTransport::Quality& quality,
                                          const std::string& what) {
    const auto surface = make_surface(scene.water->waves, scene.water->level, scene.water->time);
    double shortest = std::numeric_limits<double>::infinity();
    for (const WaveComponent& wave : scene.water->waves.components) shortest = std::min(shortest, wave.wavelength);
    const auto cells = static_cast<uint32_t>(
        std::ceil(2.0 * scene.water->half_extent / shortest * 2.0 * quality.cells_per_wavelength));
    const ref::FloorCausticMap map(scene, *surface, quality.floor_texels, cells);
    size_t bad = 0;
    for (const glm::dvec3& e : map.texels())
        bad += !(std::isfinite(e.x + e.y + e.z) && e.x >= 0 && e.y >= 0 && e.z >= 0);
    EXPECT_EQ(bad, 0u) << what << ": non-finite or negative reference floor irradiance";
    const glm::dvec3 got = map.total_flux(), bound = slab_flux(scene);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(got[c], 0.0) << what << " (reference)";
        // Double precision sums of at most 2 cells^2 deposits: 1e-12 relative covers them.
        EXPECT_LE(got[c], bound[c] * (1.0 + 1e-12)) << what << " (reference) channel " << c;
    }
    std::printf("%s: reference receiver flux %.6g W of %.6g W entering the surface's slab (green)\n", what.c_str(),
                got.y, bound.y);
}

// Both renderers' images of one case.
struct CaseImages {
    ImageRGBA32F real_time, reference;
};

// What every case asserts (item 2): (1) and (2) on both renderers' images, and (3) on
// both renderers' receiver flux (the real-time caustic passes run on their own too when the frame
// culls them, the sun on or below the horizon, as a forced-on frame would: they must deposit
// nothing then; the reference's beams only exist under wavy water, flat water's floor irradiance
// being the closed form). Returns the images for the case's own checks.
inline CaseImages expect_stable(Context& context, Renderer& renderer, const Scene& scene, const std::string& what,
                                const ref::WaterTransport::Quality& quality = kSuiteQuality) {
    CaseImages images{render_real_time(renderer, scene), render_reference(scene, quality)};
    expect_finite_non_negative(images.real_time, what + " (real time)");
    expect_finite_non_negative(images.reference, what + " (reference)");
    if (scene.water && scene.effects[Effect::SurfaceCaustics].mode != EffectMode::Off) {
        expect_receiver_flux_bounded(run_scene_caustics(context, scene), scene, what);
    }
    if (scene.water && scene.water->waves.model != WaveModel::Flat) expect_reference_flux_bounded(scene, quality, what);
    return images;
}

// Assertion (5) where flat water makes both renderers closed form: relMSE < kFlatWaterRelMse.
inline void expect_closed_form(const CaseImages& images, const std::string& what) {
    const double error = rel_mse(images.real_time, images.reference);
    std::printf("%s: relMSE against the reference %.3e\n", what.c_str(), error);
    EXPECT_LT(error, kFlatWaterRelMse) << what;
}

}  // namespace vkw::test
