// The caustic map's blur (passes/caustics/caustics_blur.hpp): it keeps the map's total flux (to fp32
// rounding) while it moves light about, radius 0 is the identity bit for bit, and its width
// follows the photon density the irradiance implies, r = r0 sqrt(E_flat / E).
#include "passes/caustics/caustics_blur.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kE = 4.0, kWavelength = 2.0;

// A sine along x (A k = 0.3: focal lines on the floor, so the irradiance and with it the blur's
// radius vary from texel to texel).
passes::WaterSurfaceInputs sine_surface() {
    passes::WaterSurfaceInputs s;
    s.level = 0.0;
    s.half_extent = kE;
    s.grid_resolution = 128;
    s.waves.model = WaveModel::Sum;
    const double k = 2.0 * std::numbers::pi / kWavelength;
    s.waves.components = {{0.3 / k, kWavelength, 0.0, 0.0, 0.0, -1.0}};
    return s;
}

passes::CausticInputs sine_caustics(const passes::WaterSurfaceInputs& s) {
    passes::CausticInputs c;
    c.grid_resolution = s.grid_resolution;
    c.half_extent = s.half_extent;
    c.sun_direction = sun_at(30.0, {1.0, 0.0, 0.0});
    c.sun_irradiance = {1.0, 2.0, 0.5};
    c.sigma_t = {0.3, 0.1, 0.05};
    c.floor_height = -2.0;
    c.max_amplitude = s.waves.components[0].amplitude;
    c.fit_margin = 1.0;
    c.map_width = c.map_height = s.grid_resolution + 2;
    return c;
}

using caustics_blur = GpuTest;

TEST_F(caustics_blur, KeepsTheMapsFluxAndMovesLight) {
    const passes::WaterSurfaceInputs surface = sine_surface();
    const passes::CausticInputs in = sine_caustics(surface);
    const CausticRun run = run_caustics(context(), surface, in, {}, nullptr, 10.0, /*blur_radius=*/1.0);
    ASSERT_EQ(run.unblurred.size(), run.irradiance.size());
    double largest_change = 0.0, largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        long double before = 0.0, after = 0.0;
        for (size_t t = 0; t < run.irradiance.size() / 4; ++t) {
            const float e = run.irradiance[4 * t + c];
            ASSERT_TRUE(std::isfinite(e) && e >= 0.0f) << "texel " << t;
            before += run.unblurred[4 * t + c];
            after += e;
            largest_change = std::max(largest_change, double(std::abs(e - run.unblurred[4 * t + c])));
            largest = std::max(largest, double(run.unblurred[4 * t + c]));
        }
        // Each blurred value is, per axis, at most 9 products summed, each weight from about 10
        // fp32 operations (the tent and its closed-form sum): about 25 roundings of u = 2^-24 per
        // axis, 50 over both, so the total moves by at most 50 u = 3.0e-6 relative (the map's
        // flux is exactly redistributed in real numbers: every source's weights sum to one).
        const double change = double(after / before - 1.0);
        std::printf("channel %d: map total %.9Lg before, %.9Lg after the blur, relative change %.2e\n", c, before,
                    after, change);
        EXPECT_LE(std::abs(change), 50.0 * kUnit) << "channel " << c;
    }
    // And it did blur: the focal lines lose a good part of their peak.
    EXPECT_GT(largest_change, 0.05 * largest);
}

TEST_F(caustics_blur, RadiusZeroIsTheIdentity) {
    const passes::WaterSurfaceInputs surface = sine_surface();
    const CausticRun run = run_caustics(context(), surface, sine_caustics(surface), {}, nullptr, 10.0, 0.0);
    for (size_t t = 0; t < run.irradiance.size() / 4; ++t) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(run.irradiance[4 * t + c], run.unblurred[4 * t + c]) << "texel " << t;
    }
}

TEST_F(caustics_blur, WidthFollowsThePhotonDensity) {
    // Flat water, n = 1, vertical sun, no extinction, the bilinear kernel, 3 texels per cell:
    // each photon lands on a texel centre, so every third texel (per axis) holds E = 9 E_flat and
    // the others 0. The density rule gives r = r0 sqrt(E_flat / E) = 3 / 3 = 1 texel for r0 = 3,
    // so h = 2 and weights (1/4, 1/2, 1/4) per axis: a lit texel keeps 9/4 E_flat, its edge
    // neighbours get 9/8 (the texel one further, next to the next photon, as much from that one),
    // its corners 9/16. A blur of the fixed width r0 (h = 4, weights 1/4 .. 1/16) would give
    // 9 (1/4)^2 = 9/16 at the centre instead.
    passes::WaterSurfaceInputs surface;
    surface.level = 0.0;
    surface.half_extent = 8.0;
    surface.grid_resolution = 16;
    passes::CausticInputs in;
    in.grid_resolution = surface.grid_resolution;
    in.half_extent = surface.half_extent;
    in.sun_direction = {0.0, -1.0, 0.0};
    in.sun_irradiance = {1.0, 2.0, 0.5};
    in.ior = 1.0;
    in.floor_height = -2.0;
    in.map_width = in.map_height = 50;  // 48 texels over the water: 3 per cell
    in.kernel = CausticKernel::Bilinear;
    const CausticRun run = run_caustics(context(), surface, in, {}, nullptr, 10.0, 3.0);
    const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
    // A lit texel near the middle of the map.
    const size_t middle = size_t(frame.height / 2) * frame.width + frame.width / 2;
    size_t lit = middle;
    for (size_t t = middle - 2 * frame.width - 2; t <= middle + 2 * frame.width + 2; ++t) {
        if (run.unblurred[4 * t] > run.unblurred[4 * lit]) lit = t;
    }
    const int x = int(lit % frame.width), y = int(lit / frame.width);
    auto blurred = [&](int dx, int dy, int c) {
        return double(run.irradiance[4 * (size_t(y + dy) * frame.width + x + dx) + c]);
    };
    for (int c = 0; c < 3; ++c) {
        const double e_flat = in.sun_irradiance[c];
        std::printf(
            "channel %d: lit texel %.6g E_flat; blurred centre %.6g, edge %.6g, two away %.6g, corner %.6g "
            "(x E_flat)\n",
            c, run.unblurred[4 * lit + c] / e_flat, blurred(0, 0, c) / e_flat, blurred(1, 0, c) / e_flat,
            blurred(2, 0, c) / e_flat, blurred(1, 1, c) / e_flat);
        // The lit texels hold 9 E_flat to the fixed point's and fp32's rounding; the weights come
        // out of a sqrt and two divisions of those: 1e-5 relative bounds all of it.
        EXPECT_NEAR(run.unblurred[4 * lit + c] / (9.0 * e_flat), 1.0, 1e-5);
        EXPECT_NEAR(blurred(0, 0, c) / (2.25 * e_flat), 1.0, 1e-5);
        EXPECT_NEAR(blurred(1, 0, c) / (1.125 * e_flat), 1.0, 1e-5);
        EXPECT_NEAR(blurred(0, -1, c) / (1.125 * e_flat), 1.0, 1e-5);
        EXPECT_NEAR(blurred(2, 0, c) / (1.125 * e_flat), 1.0, 1e-5);
        EXPECT_NEAR(blurred(1, 1, c) / (0.5625 * e_flat), 1.0, 1e-5);
    }
}

}  // namespace
}  // namespace vkw::test
