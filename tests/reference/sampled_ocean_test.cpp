// The FFT ocean as the reference renderer evaluates it (engine/water/sampled_ocean_surface.hpp:
// zero-padded FFT samples and Hermite patches) against the exact Fourier series
// (FftOceanSurface), and its periodic floor caustic map (tools/reference/floor_caustics.hpp)
// against docs/model.md section 4's flux computed independently over the exact series.
// The ocean is scenes/ocean.json's (JONSWAP, 10 m/s wind, choppiness 0.8) on a 64-mode grid
// over 32 m, which keeps ocean.json's 0.5 m mode spacing and shortest wave (0.71 m) while the
// exact series (4096 modes per point) stays fast enough for 10^4 points.
#include "engine/scene/scene_loader.hpp"
#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/sampled_ocean_surface.hpp"
#include "tests/reference/section4_flux.hpp"
#include "tools/reference/floor_caustics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

namespace vkw::ref {
namespace {

constexpr uint32_t kPadding = 4;  // the reference renderer's default (WaterTransport::Quality)

Scene small_ocean_scene() {
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/ocean.json",
                      {"water.waves.resolution=64", "water.waves.patch_size=32"});
}

struct Oceans {
    std::shared_ptr<const FftOceanSpectrum> spectrum;
    std::unique_ptr<FftOceanSurface> exact;
    std::unique_ptr<SampledOceanSurface> sampled;
};

Oceans make_oceans(const Scene& scene) {
    const WaveSettings& waves = scene.water->waves;
    Oceans oceans;
    oceans.spectrum = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(waves.ocean, waves.seed));
    oceans.exact = std::make_unique<FftOceanSurface>(oceans.spectrum, waves.ocean.choppiness, scene.water->level,
                                                     scene.water->time);
    oceans.sampled = std::make_unique<SampledOceanSurface>(*oceans.spectrum, waves.ocean.choppiness, scene.water->level,
                                                           scene.water->time, kPadding);
    return oceans;
}

TEST(reference_sampled_ocean, EveryFieldIsWithinItsDerivedBoundOfTheExactSeries) {
    const Scene scene = small_ocean_scene();
    const Oceans oceans = make_oceans(scene);
    const FftOceanSpectrum& spectrum = *oceans.spectrum;
    // The exact series' own rounding: sum_k |m_f h~| summed naively over n^2 terms errs by
    // at most n^2 eps sum |m_f h~| (the standard bound for recursive summation).
    const std::vector<std::complex<double>> modes = ocean_modes_at(spectrum, scene.water->time);
    OceanFieldValues series_rounding{};
    for (uint32_t b = 0; b < spectrum.n; ++b) {
        for (uint32_t a = 0; a < spectrum.n; ++a) {
            const OceanFieldMultipliers m =
                ocean_field_multipliers(spectrum.wave_vector(a, b), scene.water->waves.ocean.choppiness);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                series_rounding[f] += std::abs(m[f] * modes[size_t(b) * spectrum.n + a]);
            }
        }
    }
    for (double& r : series_rounding) r *= double(spectrum.n) * spectrum.n * std::numeric_limits<double>::epsilon();

    // The same ocean sampled half as finely, to check the order of convergence.
    const SampledOceanSurface coarser(spectrum, scene.water->waves.ocean.choppiness, scene.water->level,
                                      scene.water->time, kPadding / 2);

    // 10^4 points over four periods each way around the origin (the grid must wrap).
    std::mt19937_64 random(10);
    std::uniform_real_distribution<double> coordinate(-2.0 * spectrum.patch_size, 2.0 * spectrum.patch_size);
    OceanFieldValues worst{}, worst_coarser{};
    for (int i = 0; i < 10000; ++i) {
        const double x0 = coordinate(random), z0 = coordinate(random);
        const OceanFieldValues exact = oceans.exact->fields_at(x0, z0);
        const OceanFieldValues sampled = oceans.sampled->fields_at(x0, z0);
        const OceanFieldValues sampled_coarser = coarser.fields_at(x0, z0);
        for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
            worst[f] = std::max(worst[f], std::abs(sampled[f] - exact[f]));
            worst_coarser[f] = std::max(worst_coarser[f], std::abs(sampled_coarser[f] - exact[f]));
        }
    }
    for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
        SCOPED_TRACE("field " + std::to_string(f));
        // The bound of sampled_ocean_surface.hpp: h^4/384 (max|f_xxxx| + max|f_zzzz| + h/4 max|f_xzzzz|)
        // with each maximum bounded by sum |m_f h~| |kx|^a |kz|^b, plus the padded FFT's rounding,
        // plus the exact series' rounding above. (Measured: about 1/100 of it; phases rarely align.)
        EXPECT_LE(worst[f], oceans.sampled->error_bound()[f] + series_rounding[f]);
        EXPECT_LE(worst_coarser[f], coarser.error_bound()[f] + series_rounding[f]);
        // The interpolant is of fourth order: halving h divides the error by 2^4 = 16 once h is
        // small against the shortest wave (here h k_max = 1.1 at P = 2, 0.55 at P = 4, so the
        // ratio is a little below 16). More than 8 = 2^3 rules out any lower order, e.g. a
        // Hermite patch that loses its cross-derivative term (second order, ratio 4).
        EXPECT_GT(worst_coarser[f], 8.0 * worst[f]);
    }
    // The bound is useful: the height to a few mm, the slopes to a few thousandths (h = 0.125 m).
    EXPECT_LT(oceans.sampled->error_bound()[kOceanHeight], 2e-3);
    EXPECT_LT(oceans.sampled->error_bound()[kOceanSlopeX], 1e-2);
}

TEST(reference_sampled_ocean, AmplitudeBoundHoldsAndIsTighterThanTheSeriesBound) {
    const Scene scene = small_ocean_scene();
    const Oceans oceans = make_oceans(scene);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> coordinate(0.0, oceans.spectrum->patch_size);
    double highest = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const double h = oceans.sampled->at_parameter(coordinate(random), coordinate(random)).position.y;
        highest = std::max(highest, std::abs(h - scene.water->level));
    }
    // max_amplitude() bounds the interpolant everywhere (its node-data bound), so no sample exceeds it.
    EXPECT_LE(highest, oceans.sampled->max_amplitude());
    // ... and it is far tighter than sum |h~| (which bounds the series): the crossing's slab is thinner.
    EXPECT_LT(oceans.sampled->max_amplitude(), 0.5 * oceans.exact->max_amplitude());
}

TEST(reference_sampled_ocean, PeriodicFloorMapCarriesTheSection4FluxOfOnePeriod) {
    // The floor 5 m down instead of 30: each beam triangle is attenuated along its vertices'
    // mean path, which is exact to second order in sigma_t times the path's spread over the
    // triangle; at 30 m that spread (about 1 m) makes coastal red's exp(-1.34 l) err by 6%.
    // At 5 m it is 1/6 of that (sigma_t dl ~ 0.2, second-order error about (0.2)^2 / 24 < 0.2%).
    Scene scene = small_ocean_scene();
    scene.floor.height = -5.0;
    const Oceans oceans = make_oceans(scene);
    const double period = oceans.spectrum->patch_size;
    // 256 cells and texels over 32 m: 12.5 cm, the sample spacing.
    const FloorCausticMap map(scene, *oceans.sampled, 256, 256, period);
    // Independent: midpoint quadrature over the exact series, 128 x 128 points per period.
    const glm::dvec3 expected = section4_flux(scene, *oceans.exact, 0.0, period, 128);
    for (int c = 0; c < 3; ++c) {
        // docs/model.md section 4: within 0.5%. The beams' flat triangles (chord normals, cells 1/6
        // of the shortest wave) and the midpoint rule (spectrally accurate for the periodic
        // smooth part, O(h^2) at the kinks where facets turn from the sun) both stay inside it.
        EXPECT_NEAR(map.total_flux()[c], expected[c], 0.005 * expected[c]) << "channel " << c;
    }
    // Periodic: the map reads the same one period away.
    EXPECT_EQ(map.irradiance(3.3, 7.1), map.irradiance(3.3 + period, 7.1 - 2.0 * period));
}

}  // namespace
}  // namespace vkw::ref
