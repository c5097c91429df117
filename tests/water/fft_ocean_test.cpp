// The FFT ocean: reproducible h0, the exact series against the FFT grid, analytic
// derivatives against central differences, periodicity, the choppy displacement's sign and
// Newton's height_at.
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/errors.hpp"
#include "engine/water/fft_ocean.hpp"
#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/ocean_grid.hpp"
#include "tests/water/water_test_support.hpp"

namespace vkw {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

FftOceanSettings small_ocean(uint32_t n = 16) {
    FftOceanSettings ocean;
    ocean.resolution = n;
    ocean.patch_size = 20.0;
    ocean.wind_speed = 6.0;
    ocean.wind_direction_deg = 25.0;
    return ocean;
}

FftOceanSurface ocean_surface(const FftOceanSettings& ocean, uint64_t seed, double choppiness, double level,
                              double time) {
    return FftOceanSurface(std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(ocean, seed)), choppiness,
                           level, time);
}

double sum_abs_modes(const FftOceanSurface& surface) { return surface.max_amplitude(); }

TEST(water_ocean, SameSeedGivesBitIdenticalH0AndAnotherSeedDoesNot) {
    const FftOceanSpectrum a = make_ocean_spectrum(small_ocean(), 11);
    const FftOceanSpectrum b = make_ocean_spectrum(small_ocean(), 11);
    const FftOceanSpectrum c = make_ocean_spectrum(small_ocean(), 12);
    ASSERT_EQ(a.h0.size(), 256u);
    std::size_t nonzero = 0, differing = 0;
    for (std::size_t i = 0; i < a.h0.size(); ++i) {
        EXPECT_EQ(a.h0[i], b.h0[i]) << "mode " << i;
        nonzero += a.h0[i] != 0.0;
        differing += a.h0[i] != c.h0[i];
    }
    EXPECT_EQ(nonzero, 15u * 15u - 1u);  // all but the Nyquist row/column and k = 0
    EXPECT_EQ(differing, nonzero);
}

TEST(water_ocean, ModesKeepTheirNumbersWhenTheResolutionGrows) {
    // The generator is keyed by the signed frequency, so a finer grid over the same patch
    // only adds modes.
    const FftOceanSpectrum coarse = make_ocean_spectrum(small_ocean(16), 5);
    const FftOceanSpectrum fine = make_ocean_spectrum(small_ocean(32), 5);
    for (int fz = -7; fz <= 7; ++fz) {
        for (int fx = -7; fx <= 7; ++fx) {
            const std::size_t ic = std::size_t((fz + 16) % 16) * 16 + (fx + 16) % 16;
            const std::size_t if_ = std::size_t((fz + 32) % 32) * 32 + (fx + 32) % 32;
            EXPECT_EQ(coarse.h0[ic], fine.h0[if_]) << fx << ", " << fz;
        }
    }
}

TEST(water_ocean, SameTimeAndSeedGiveABitIdenticalSurface) {
    WaveSettings settings;
    settings.model = WaveModel::FftOcean;
    settings.ocean = small_ocean();
    settings.ocean.choppiness = 0.5;
    settings.seed = 99;
    const auto s1 = make_surface(settings, 0.1, 4.25);
    const auto s2 = make_surface(settings, 0.1, 4.25);
    for (double x : {-3.3, 0.0, 7.9}) {
        for (double z : {-11.0, 2.2}) {
            const SurfacePoint p = s1->at_parameter(x, z), q = s2->at_parameter(x, z);
            EXPECT_EQ(p.position, q.position);
            EXPECT_EQ(p.normal, q.normal);
            EXPECT_EQ(p.dP_du, q.dP_du);
            EXPECT_EQ(p.dP_dv, q.dP_dv);
        }
    }
    const FftOceanGrid g1 = dynamic_cast<const FftOceanSurface&>(*s1).grid();
    const FftOceanGrid g2 = dynamic_cast<const FftOceanSurface&>(*s2).grid();
    EXPECT_EQ(g1.fields, g2.fields);
}

TEST(water_ocean, ModesAreHermitianSoTheSeriesIsReal) {
    const FftOceanSpectrum spectrum = make_ocean_spectrum(small_ocean(), 3);
    const auto modes = ocean_modes_at(spectrum, 1.9);
    for (std::size_t i = 0; i < modes.size(); ++i) {
        EXPECT_EQ(modes[spectrum.opposite(i)], std::conj(modes[i])) << "mode " << i;
    }
}

TEST(water_ocean, ExactSeriesEqualsTheFftGridAtGridPoints) {
    const double choppiness = 0.8, time = 2.5;
    const FftOceanSettings ocean = small_ocean(32);
    const FftOceanSurface surface = ocean_surface(ocean, 17, choppiness, 0.0, time);
    const FftOceanGrid grid = surface.grid();
    const uint32_t n = grid.n;
    // Both are sums of n^2 terms m_f h~ e^{ik.x}; bounding each partial sum by
    // sum |m_f h~| gives the rounding bound n^2 eps sum |m_f h~| for either.
    OceanFieldValues bound{};
    const auto modes = ocean_modes_at(surface.spectrum(), time);
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const auto m = ocean_field_multipliers(surface.spectrum().wave_vector(a, b), choppiness);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                bound[f] += std::abs(m[f] * modes[std::size_t(b) * n + a]);
            }
        }
    }
    for (uint32_t iz = 0; iz < n; ++iz) {
        for (uint32_t ix = 0; ix < n; ++ix) {
            const OceanFieldValues exact = surface.fields_at(ix * grid.spacing(), iz * grid.spacing());
            const OceanFieldValues fast = grid.values(ix, iz);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                EXPECT_NEAR(exact[f], fast[f], double(n) * n * kEps * bound[f])
                    << "field " << f << " at node " << ix << ", " << iz;
            }
        }
    }
}

void expect_ocean_derivatives(double choppiness) {
    const double level = 0.3, step = 1e-5;
    const FftOceanSurface surface = ocean_surface(small_ocean(), 8, choppiness, level, 1.2);
    const uint32_t n = surface.spectrum().n;
    const auto modes = ocean_modes_at(surface.spectrum(), surface.time());
    // |d^3 P / du^3| <= (1 + choppiness) sum |h~(k)| |k|^3: the height and each displacement
    // are series with coefficients of modulus <= max(1, choppiness) |h~|.
    double third = 0.0;
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const double k = glm::length(surface.spectrum().wave_vector(a, b));
            third += (1.0 + choppiness) * std::abs(modes[std::size_t(b) * n + a]) * k * k * k;
        }
    }
    for (double x0 : {-13.1, -2.0, 0.3, 5.55, 19.0}) {
        for (double z0 : {-4.4, 0.0, 8.8}) {
            // Rounding: the coordinates and level, plus each of the n^2 terms (whose phase
            // 2 pi f u carries about n eps) with the sum's growth of at most n in practice.
            const double scale =
                std::abs(x0) + std::abs(z0) + level + 4.0 * n * (1.0 + choppiness) * sum_abs_modes(surface);
            test::expect_derivatives_match_differences(surface, x0, z0, step,
                                                       test::central_difference_tolerance(step, third, scale));
        }
    }
}

TEST(water_ocean, HeightfieldDerivativesMatchCentralDifferences) { expect_ocean_derivatives(0.0); }

TEST(water_ocean, ChoppyDerivativesMatchCentralDifferences) { expect_ocean_derivatives(0.9); }

TEST(water_ocean, SurfaceIsPeriodicWithThePatch) {
    const FftOceanSurface surface = ocean_surface(small_ocean(), 4, 0.6, 0.0, 0.7);
    const double period = surface.spectrum().patch_size;
    for (double x0 : {-1.7, 3.2}) {
        const SurfacePoint p = surface.at_parameter(x0, 2.0);
        const SurfacePoint q = surface.at_parameter(x0 + 3.0 * period, 2.0 - period);
        // The reduced phase differs by the rounding of x0 / period: a few eps of the terms.
        EXPECT_NEAR(q.position.x - 3.0 * period, p.position.x, 1e-12);
        EXPECT_NEAR(q.position.y, p.position.y, 1e-12);
        EXPECT_NEAR(q.position.z + period, p.position.z, 1e-12);
        EXPECT_NEAR(glm::length(q.normal - p.normal), 0.0, 1e-12);
    }
}

TEST(water_ocean, PositiveChoppinessSqueezesTheCrests) {
    // One mode, fx = 2 on a 16 m patch: h = 0.2 cos(k x0) with k = pi / 4, crest at x0 = 0.
    FftOceanSpectrum spectrum;
    spectrum.n = 16;
    spectrum.patch_size = 16.0;
    spectrum.h0.assign(256, 0.0);
    spectrum.h0[2] = 0.1;
    const double k = std::numbers::pi / 4.0, choppiness = 0.5;
    const FftOceanSurface surface(std::make_shared<const FftOceanSpectrum>(spectrum), choppiness, 0.0, 0.0);
    EXPECT_NEAR(surface.at_parameter(0.0, 0.0).position.y, 0.2, 1e-15);
    // Trochoid: x = x0 - choppiness 0.2 sin(k x0), so dx/dx0 = 1 - 0.1 k at the crest and
    // 1 + 0.1 k in the trough; points beside the crest move toward it.
    EXPECT_NEAR(surface.at_parameter(0.0, 0.0).dP_du.x, 1.0 - 0.1 * k, 1e-15);
    EXPECT_NEAR(surface.at_parameter(4.0, 0.0).dP_du.x, 1.0 + 0.1 * k, 1e-15);
    EXPECT_LT(surface.at_parameter(0.5, 0.0).position.x, 0.5);
    EXPECT_EQ(surface.max_amplitude(), 0.2);
}

TEST(water_ocean, HeightAtByNewtonReproducesTheDisplacedPoint) {
    const FftOceanSurface surface = ocean_surface(small_ocean(), 21, 0.7, -0.2, 5.0);
    for (int i = 0; i < 25; ++i) {
        const double x0 = -10.0 + 20.0 * std::fmod(0.5 + i * 0.6180339887498949, 1.0);
        const double z0 = -10.0 + 20.0 * std::fmod(0.5 + i * 0.7548776662466927, 1.0);
        const SurfacePoint p = surface.at_parameter(x0, z0);
        EXPECT_NEAR(surface.height_at(p.position.x, p.position.z), p.position.y, 1e-9);
    }
}

TEST(water_ocean, MaxAmplitudeBoundsTheHeights) {
    const FftOceanSurface surface = ocean_surface(small_ocean(64), 6, 0.0, 0.0, 8.0);
    const FftOceanGrid grid = surface.grid();
    EXPECT_GE(surface.max_amplitude(), grid.max_abs_height());
    EXPECT_LE(surface.max_amplitude(), surface.spectrum().amplitude_bound());
}

TEST(water_ocean, TheFramesAmplitudeBoundIsTheSpectrumsAllTimeOneAndHoldsAtEveryTime) {
    // The frame reads the bound without building the surface (surface.hpp): the spectrum's
    // 2 sum |h0|, the same value however the time moves, and never below the surface's own.
    WaveSettings waves;
    waves.model = WaveModel::FftOcean;
    waves.ocean = small_ocean(64);
    waves.seed = 6;
    const double all_time = shared_ocean_spectrum(waves.ocean, waves.seed)->amplitude_bound();
    for (const double time : {0.0, 1.3, 8.0, 1000.0}) {
        const double bound = frame_amplitude_bound(waves, -0.5, time);
        EXPECT_EQ(bound, all_time) << "time " << time;
        EXPECT_GE(bound, make_surface(waves, -0.5, time)->max_amplitude()) << "time " << time;
    }
    // Another seed is another spectrum, with its own bound.
    waves.seed = 7;
    EXPECT_EQ(frame_amplitude_bound(waves, 0.0, 0.0), shared_ocean_spectrum(waves.ocean, 7)->amplitude_bound());
    EXPECT_NE(frame_amplitude_bound(waves, 0.0, 0.0), all_time);
    // The other models give their surface's own bound, bit for bit, without building it: sines,
    // sines with a Gerstner term, and flat water (whose components are not read).
    WaveSettings sines;
    sines.model = WaveModel::Sum;
    const WaveComponent sine{.amplitude = 0.05, .wavelength = 2.0};
    const WaveComponent gerstner{.amplitude = 0.0301, .wavelength = 3.1, .steepness = 0.4};
    sines.components = {sine};
    EXPECT_EQ(frame_amplitude_bound(sines, 0.0, 2.0), make_surface(sines, 0.0, 2.0)->max_amplitude());
    sines.components = {sine, gerstner, sine};
    EXPECT_EQ(frame_amplitude_bound(sines, 0.3, 2.0), make_surface(sines, 0.3, 2.0)->max_amplitude());
    WaveSettings flat = sines;
    flat.model = WaveModel::Flat;
    EXPECT_EQ(frame_amplitude_bound(flat, 0.3, 2.0), 0.0);
    EXPECT_EQ(make_surface(flat, 0.3, 2.0)->max_amplitude(), 0.0);
    // Bad waves are refused as make_surface refuses them.
    sines.components[1].steepness = 1.2;  // the steepness sums above 1: the waves fold
    EXPECT_THROW(frame_amplitude_bound(sines, 0.0, 2.0), UserError);
    EXPECT_THROW(make_surface(sines, 0.0, 2.0), UserError);
}

TEST(water_ocean, BadSettingsAreRefusedNamingTheField) {
    FftOceanSettings ocean = small_ocean(12);
    try {
        make_ocean_spectrum(ocean, 1);
        FAIL() << "resolution 12 accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("water.waves.resolution = 12: accepted a power of two in [16, 1024]"),
                  std::string::npos)
            << e.what();
    }
    ocean = small_ocean();
    ocean.wind_speed = 0.0;
    EXPECT_THROW(make_ocean_spectrum(ocean, 1), UserError);
}

}  // namespace
}  // namespace vkw
