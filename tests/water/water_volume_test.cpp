// The water-volume mesh: closed and outward-wound for every model, with volumes that have
// closed forms (flat; a sine and an FFT heightfield over whole periods; a Gerstner wave,
// whose displaced mean level is lowered by A s / 2), and is_watertight's failure reports.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/errors.hpp"
#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/flat_surface.hpp"
#include "engine/water/water_volume.hpp"
#include "engine/water/wave_sum_surface.hpp"

namespace vkw {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_watertight(const TriangleMesh& mesh) {
    std::string why;
    EXPECT_TRUE(is_watertight(mesh, &why)) << why;
}

WaveSettings one_wave(double amplitude, double wavelength, double steepness) {
    WaveSettings settings;
    settings.model = WaveModel::Sum;
    settings.components.push_back({amplitude, wavelength, 0.0, 33.0, steepness});
    return settings;
}

TEST(water_volume, FlatVolumeIsClosedWithTheBoxVolume) {
    const double e = 3.0, level = 0.25, bottom = -1.5;
    const TriangleMesh mesh = build_water_volume(FlatSurface(level), e, 8, bottom);
    expect_watertight(mesh);
    EXPECT_EQ(mesh.positions.size(), 2u * 9u * 9u);
    EXPECT_EQ(mesh.indices.size(), 3u * (4u * 64u + 2u * 32u));
    const double expected = (2.0 * e) * (2.0 * e) * (level - bottom);
    EXPECT_NEAR(signed_volume(mesh), expected, 1e-9 * expected);
}

TEST(water_volume, SineOverWholePeriodsKeepsTheFlatVolume) {
    // The top integrates the piecewise-linear surface: the trapezoid rule, which sums a sine
    // sampled uniformly over whole periods to zero. 4 periods over 2E = 4 m, 12 cells each.
    const double e = 2.0, level = 0.1, bottom = -2.0;
    const WaveSumSurface surface(one_wave(0.05, 1.0, 0.0), level, 0.6);
    const TriangleMesh mesh = build_water_volume(surface, e, 48, bottom);
    expect_watertight(mesh);
    const double expected = (2.0 * e) * (2.0 * e) * (level - bottom);
    EXPECT_NEAR(signed_volume(mesh), expected, 1e-9 * expected);
}

TEST(water_volume, GerstnerVolumeMatchesItsClosedForms) {
    // One Gerstner wave along x over whole periods: the volume is the integral of
    // (level + A sin - bottom)(1 - s sin) over the parameter square,
    //   (2E)^2 (level - bottom - A s / 2),
    // and the mesh (cells stay rectangles: x depends on x0 only) is the trapezoid rule along
    // the displaced profile, which gives sin(k d) / (k d) times the A s / 2 term, d the cell
    // width in x0: exact but for rounding.
    const double e = 2.0, level = 0.0, bottom = -1.0, a = 0.06, wavelength = 1.0, s = 0.7;
    const uint32_t r = 64;
    const WaveSumSurface surface(one_wave(a, wavelength, s), level, 1.1);
    const TriangleMesh mesh = build_water_volume(surface, e, r, bottom);
    expect_watertight(mesh);
    const double area = (2.0 * e) * (2.0 * e), k = 2.0 * kPi / wavelength, d = 2.0 * e / r;
    const double continuous = area * (level - bottom - a * s / 2.0);
    const double discrete = area * (level - bottom - a * s / 2.0 * std::sin(k * d) / (k * d));
    EXPECT_NEAR(signed_volume(mesh), discrete, 1e-9 * discrete);
    // The discretisation error, a relative (k d)^2 / 6 of the A s / 2 term, here 1.6e-4 of it.
    EXPECT_NEAR(signed_volume(mesh), continuous, area * a * s / 2.0 * (k * d) * (k * d) / 6.0 * 1.01);
}

TEST(water_volume, CrossingGerstnerWavesGiveAClosedMesh) {
    WaveSettings settings;
    settings.components = {{0.08, 3.0, 20.0, 0.0, 0.4}, {0.03, 1.3, 115.0, 40.0, 0.5}};
    const TriangleMesh mesh = build_water_volume(WaveSumSurface(settings, 0.0, 2.0), 5.0, 40, -3.0);
    expect_watertight(mesh);
    const double box = 100.0 * 3.0;
    EXPECT_NEAR(signed_volume(mesh), box, 100.0 * 0.11);  // |h| <= 0.11 everywhere
}

FftOceanSurface small_ocean_surface(double choppiness) {
    FftOceanSettings ocean;
    ocean.resolution = 16;
    ocean.patch_size = 16.0;
    ocean.wind_speed = 5.0;
    return FftOceanSurface(std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(ocean, 77)), choppiness, 0.0,
                           1.5);
}

TEST(water_volume, FftHeightfieldOverOnePatchKeepsTheFlatVolume) {
    // E = patch / 2 and R = n: the vertices are the FFT nodes, and the trapezoid rule over a
    // period returns the mean of the samples, the k = 0 mode, which is zero.
    const FftOceanSurface surface = small_ocean_surface(0.0);
    const double bottom = -(surface.max_amplitude() + 1.0);
    const TriangleMesh mesh = build_water_volume(surface, 8.0, 16, bottom);
    expect_watertight(mesh);
    const double expected = 16.0 * 16.0 * (0.0 - bottom);
    EXPECT_NEAR(signed_volume(mesh), expected, 1e-9 * expected);
}

TEST(water_volume, ChoppyFftOceanGivesAClosedMesh) {
    const FftOceanSurface surface = small_ocean_surface(0.8);
    const double amplitude = surface.max_amplitude();
    const TriangleMesh mesh = build_water_volume(surface, 6.0, 24, -amplitude - 0.5);
    expect_watertight(mesh);
    EXPECT_GT(signed_volume(mesh), 0.0);
}

TEST(water_volume, BottomAboveATroughIsRefused) {
    const WaveSumSurface surface(one_wave(0.5, 2.0, 0.0), 0.0, 0.0);
    EXPECT_THROW(build_water_volume(surface, 2.0, 8, -0.25), UserError);
    EXPECT_THROW(build_water_volume(surface, 0.0, 8, -1.0), InternalError);
    EXPECT_THROW(build_water_volume(surface, 2.0, 0, -1.0), InternalError);
}

TEST(water_volume, WatertightnessCheckReportsHolesAndFlips) {
    const TriangleMesh closed = build_water_volume(FlatSurface(0.0), 1.0, 2, -1.0);
    expect_watertight(closed);

    TriangleMesh holed = closed;
    holed.indices.resize(holed.indices.size() - 3);
    std::string why;
    EXPECT_FALSE(is_watertight(holed, &why));
    EXPECT_NE(why.find("edge"), std::string::npos) << why;

    TriangleMesh flipped = closed;
    std::swap(flipped.indices[1], flipped.indices[2]);
    EXPECT_FALSE(is_watertight(flipped, &why));
    EXPECT_NE(why.find("2 time(s)"), std::string::npos) << why;

    TriangleMesh out_of_range = closed;
    out_of_range.indices[0] = 1000;
    EXPECT_FALSE(is_watertight(out_of_range, &why));
    EXPECT_NE(why.find("vertex 1000"), std::string::npos) << why;
}

}  // namespace
}  // namespace vkw
