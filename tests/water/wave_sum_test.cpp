// Sum of sine and Gerstner waves: analytic derivatives against central differences, the
// phase and dispersion conventions, Newton's height_at, and the steepness check.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/errors.hpp"
#include "engine/water/surface.hpp"
#include "engine/water/validate_waves.hpp"
#include "engine/water/wave_sum_surface.hpp"
#include "tests/water/water_test_support.hpp"

namespace vkw {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStep = 1e-5;  // m, central-difference step

WaveSettings sum_of(std::vector<WaveComponent> components) {
    WaveSettings settings;
    settings.model = WaveModel::Sum;
    settings.components = std::move(components);
    return settings;
}

// sum over waves of (A + s / k) k^3 bounds |d^3 P / du^3| (and along v): the height term is
// A sin(theta) and the displacement (s / k) cos(theta), each differentiated three times.
double third_derivative_bound(const WaveSettings& settings) {
    double bound = 0.0;
    for (const WaveComponent& w : settings.components) {
        const double k = 2.0 * kPi / w.wavelength;
        bound += (w.amplitude + w.steepness / k) * k * k * k;
    }
    return bound;
}

// The magnitude of the sums in P near (x0, z0), for the rounding part of the tolerance:
// the coordinate, the level, and each wave term including sin()'s eps * phase error.
double rounding_scale(const WaveSettings& settings, double x0, double z0, double level) {
    double scale = std::abs(x0) + std::abs(z0) + std::abs(level);
    for (const WaveComponent& w : settings.components) {
        const double k = 2.0 * kPi / w.wavelength;
        scale += (w.amplitude + w.steepness / k) * (1.0 + k * (std::abs(x0) + std::abs(z0)));
    }
    return scale;
}

void expect_derivatives_everywhere(const WaveSettings& settings, double level, double time) {
    const WaveSumSurface surface(settings, level, time);
    for (double x0 : {-7.3, -1.1, 0.0, 0.37, 2.9, 8.6}) {
        for (double z0 : {-5.2, -0.4, 0.81, 4.4}) {
            const double tolerance = test::central_difference_tolerance(kStep, third_derivative_bound(settings),
                                                                        rounding_scale(settings, x0, z0, level));
            test::expect_derivatives_match_differences(surface, x0, z0, kStep, tolerance);
        }
    }
}

const std::vector<WaveComponent> kGerstnerWaves = {
    // amplitude, wavelength, direction, phase, steepness, speed
    {0.08, 3.0, 20.0, 0.0, 0.4, -1.0},
    {0.03, 1.3, 115.0, 40.0, 0.3, -1.0},
    {0.012, 0.55, -70.0, 200.0, 0.2, 0.5},
};

TEST(water_wave_sum, SineDerivativesMatchCentralDifferences) {
    expect_derivatives_everywhere(sum_of({{0.05, 0.7, 30.0, 10.0, 0.0, -1.0}}), 0.2, 1.3);
}

TEST(water_wave_sum, GerstnerDerivativesMatchCentralDifferences) {
    expect_derivatives_everywhere(sum_of(kGerstnerWaves), -0.1, 2.7);
}

TEST(water_wave_sum, MixedSineAndGerstnerDerivativesMatchCentralDifferences) {
    auto waves = kGerstnerWaves;
    waves.push_back({0.02, 0.9, 170.0, 0.0, 0.0, -1.0});
    waves.push_back({0.01, 5.0, 45.0, 0.0, 0.0, 3.0});
    expect_derivatives_everywhere(sum_of(waves), 0.0, 0.4);
}

TEST(water_wave_sum, SineFollowsThePhaseAndDispersionConventions) {
    // h = A sin(k (d . x) - w t + p), w = sqrt(g k), d = (cos a, sin a) in xz.
    const double a = 0.05, wavelength = 2.0, direction = 30.0, phase = 10.0, level = 0.3;
    const WaveSettings settings = sum_of({{a, wavelength, direction, phase, 0.0, -1.0}});
    const double k = 2.0 * kPi / wavelength, omega = std::sqrt(kGravity * k);
    const double d = direction * kPi / 180.0;
    const double t = 1.7, x = 0.6, z = -2.2;
    const WaveSumSurface surface(settings, level, t);
    const double expected =
        level + a * std::sin(k * (std::cos(d) * x + std::sin(d) * z) - omega * t + phase * kPi / 180.0);
    EXPECT_NEAR(surface.height_at(x, z), expected, 1e-15);
    // The wave travels along d at the phase speed w / k = sqrt(g / k).
    const double dt = 0.25, shift = omega / k * dt;
    const WaveSumSurface later(settings, level, t + dt);
    EXPECT_NEAR(later.height_at(x + shift * std::cos(d), z + shift * std::sin(d)), expected, 1e-14);
}

TEST(water_wave_sum, GivenSpeedOverridesTheDispersion) {
    const WaveSettings settings = sum_of({{0.05, 2.0, 0.0, 0.0, 0.0, 0.8}});
    const WaveSumSurface now(settings, 0.0, 0.0), later(settings, 0.0, 0.5);
    EXPECT_NEAR(later.height_at(1.3 + 0.8 * 0.5, 0.0), now.height_at(1.3, 0.0), 1e-15);
}

TEST(water_wave_sum, MaxAmplitudeOfOneSineIsItsAmplitude) {
    EXPECT_EQ(WaveSumSurface(sum_of({{0.07, 1.0}}), 0.0, 0.0).max_amplitude(), 0.07);
    EXPECT_NEAR(WaveSumSurface(sum_of(kGerstnerWaves), 0.0, 0.0).max_amplitude(), 0.122, 1e-15);
}

// The slope bound (WaveSumSurface::max_slope): never below the slope |grad h| = tan(tilt) found
// over a dense sample of the surface, and for perpendicular equal sines (pool's pair) the exact
// sqrt(2) A k to within the bound's direction sampling (pi / 720 of sum A k), not 2 A k.
double sampled_max_slope(const WaveSumSurface& surface) {
    double steepest = 0.0;
    for (int j = 0; j < 400; ++j) {
        for (int i = 0; i < 400; ++i) {
            const SurfacePoint p = surface.at_parameter(-3.0 + 6.0 * i / 400.0, -3.0 + 6.0 * j / 400.0);
            steepest = std::max(steepest, std::sqrt(1.0 - p.normal.y * p.normal.y) / p.normal.y);
        }
    }
    return steepest;
}

TEST(water_wave_sum, SlopeBoundHoldsAndIsTightForPerpendicularSines) {
    const double a = 0.017, k = 2.0 * kPi / 0.5;
    const WaveSumSurface pool(sum_of({{a, 0.5, 0.0, 0.0}, {a, 0.5, 90.0, 90.0}}), 0.0, 0.0);
    EXPECT_GE(pool.max_slope(), sampled_max_slope(pool));
    const double exact = std::sqrt(2.0) * a * k, margin = kPi / 720.0 * 2.0 * a * k;
    EXPECT_GE(pool.max_slope(), exact);
    EXPECT_LE(pool.max_slope(), exact + margin * (1.0 + 1e-12));
    const WaveSumSurface gerstner(sum_of(kGerstnerWaves), 0.0, 0.0);
    EXPECT_GE(gerstner.max_slope(), sampled_max_slope(gerstner));
    EXPECT_TRUE(std::isfinite(gerstner.max_slope()));
}

TEST(water_wave_sum, HeightfieldOnlyWithoutSteepness) {
    EXPECT_TRUE(WaveSumSurface(sum_of({{0.07, 1.0}}), 0.0, 0.0).is_heightfield());
    EXPECT_FALSE(WaveSumSurface(sum_of(kGerstnerWaves), 0.0, 0.0).is_heightfield());
}

TEST(water_wave_sum, GerstnerCrestIsSqueezedByItsSteepness) {
    // Crest at theta = pi / 2 (x0 = 0, phase 90): dx/dx0 = 1 - s there, 1 + s in the trough.
    const WaveSumSurface surface(sum_of({{0.1, 2.0, 0.0, 90.0, 0.6}}), 0.0, 0.0);
    EXPECT_NEAR(surface.at_parameter(0.0, 0.0).dP_du.x, 0.4, 1e-15);
    EXPECT_NEAR(surface.at_parameter(1.0, 0.0).dP_du.x, 1.6, 1e-15);
}

TEST(water_wave_sum, GerstnerHeightAtByNewtonReproducesTheDisplacedPoint) {
    const WaveSumSurface surface(sum_of(kGerstnerWaves), 0.15, 3.1);
    for (int i = 0; i < 60; ++i) {
        // Parameters spread over [-10, 10]^2 by a fixed low-discrepancy sequence.
        const double x0 = -10.0 + 20.0 * std::fmod(0.5 + i * 0.6180339887498949, 1.0);
        const double z0 = -10.0 + 20.0 * std::fmod(0.5 + i * 0.7548776662466927, 1.0);
        const SurfacePoint p = surface.at_parameter(x0, z0);
        EXPECT_NEAR(surface.height_at(p.position.x, p.position.z), p.position.y, 1e-9);
        // No folding (steepness sum 0.9): the parameter is unique and found again.
        const glm::dvec2 found = surface.parameter_at(p.position.x, p.position.z);
        EXPECT_NEAR(found.x, x0, 1e-9);
        EXPECT_NEAR(found.y, z0, 1e-9);
    }
}

std::string refusal(const WaveSettings& settings) {
    try {
        validate_waves(settings);
    } catch (const UserError& e) {
        return e.what();
    }
    return "";
}

TEST(water_wave_sum, SteepnessSumAboveOneIsRefusedNamingTheField) {
    const WaveSettings settings = sum_of({{0.1, 2.0, 0.0, 0.0, 0.6}, {0.1, 1.0, 90.0, 0.0, 0.5}});
    const std::string message = refusal(settings);
    EXPECT_NE(message.find("water.waves.components[1].steepness"), std::string::npos) << message;
    EXPECT_NE(message.find("sum over all waves <= 1"), std::string::npos) << message;
    EXPECT_THROW(WaveSumSurface(settings, 0.0, 0.0), UserError);
    EXPECT_THROW(make_surface(settings, 0.0, 0.0), UserError);
}

// frame_shape_bounds (surface.hpp) are the surface's own max_slope() and max_curvature(), kept per
// thread while the waves stay: each setting, asked after a different one and again after itself,
// gives its surface's bounds bit for bit, whatever the clock.
TEST(water_wave_sum, TheFramesShapeBoundsAreTheSurfacesOwnAndFollowTheWaves) {
    const WaveComponent sine{.amplitude = 0.05, .wavelength = 2.0};
    const WaveComponent gerstner{.amplitude = 0.03, .wavelength = 3.1, .direction_deg = 40.0, .steepness = 0.4};
    std::vector<WaveSettings> settings(5);
    for (WaveSettings& s : settings) s.model = WaveModel::Sum;
    settings[0].components = {sine};
    settings[1].components = {sine, gerstner};
    settings[2].components = {sine, gerstner};
    settings[2].components[1].direction_deg = 70.0;  // only a direction differs from [1]
    settings[3].components = {sine};
    settings[3].components[0].wavelength = 2.5;  // only a wavelength differs from [0]
    settings[4].model = WaveModel::Flat;
    for (int round = 0; round < 2; ++round) {
        for (const WaveSettings& s : settings) {
            for (const double time : {0.0, 3.7}) {
                const ShapeBounds bounds = frame_shape_bounds(s, 0.0, time);
                const auto surface = make_surface(s, 0.0, time);
                EXPECT_EQ(bounds.slope, surface->max_slope())
                    << "components " << s.components.size() << ", time " << time;
                EXPECT_EQ(bounds.curvature, surface->max_curvature())
                    << "components " << s.components.size() << ", time " << time;
            }
        }
    }
    EXPECT_NE(frame_shape_bounds(settings[1], 0.0, 0.0).slope, frame_shape_bounds(settings[2], 0.0, 0.0).slope);
    EXPECT_NE(frame_shape_bounds(settings[0], 0.0, 0.0).slope, frame_shape_bounds(settings[3], 0.0, 0.0).slope);
    WaveSettings ocean;
    ocean.model = WaveModel::FftOcean;
    EXPECT_EQ(frame_shape_bounds(ocean, 0.0, 0.0).slope, std::numeric_limits<double>::infinity());
    EXPECT_EQ(frame_shape_bounds(ocean, 0.0, 0.0).curvature, std::numeric_limits<double>::infinity());
}

TEST(water_wave_sum, FoldingIsAcceptedWhenAllowed) {
    WaveSettings settings = sum_of({{0.1, 2.0, 0.0, 0.0, 0.6}, {0.1, 1.0, 90.0, 0.0, 0.5}});
    settings.allow_folding = true;
    EXPECT_EQ(refusal(settings), "");
}

TEST(water_wave_sum, StepsThatSumToOneExactlyAreAccepted) {
    std::vector<WaveComponent> waves(10, WaveComponent{0.01, 1.0, 0.0, 0.0, 0.1});
    EXPECT_EQ(refusal(sum_of(waves)), "");
}

TEST(water_wave_sum, BadComponentsAreRefusedNamingTheField) {
    EXPECT_NE(refusal(sum_of({{0.1, 1.0}, {0.1, -2.0}})).find("water.waves.components[1].wavelength"),
              std::string::npos);
    EXPECT_NE(refusal(sum_of({{-0.1, 1.0}})).find("water.waves.components[0].amplitude"), std::string::npos);
    EXPECT_NE(refusal(sum_of({{0.1, 1.0, 0.0, 0.0, -0.2}})).find("water.waves.components[0].steepness"),
              std::string::npos);
    EXPECT_NE(refusal(sum_of({{0.1, 1.0, NAN}})).find("water.waves.components[0].direction_deg"), std::string::npos);
}

}  // namespace
}  // namespace vkw
