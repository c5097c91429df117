// Steep waves in deep water: sines of slope A k = 0.5, 1 and 2 (lambda 0.5 m) over a
// floor 1 m and 1 km down, the sun overhead and 60 degrees from the zenith, with no extinction
// (so the light reaches the floor 1 km down: the waves then send most photons kilometres off the
// map, some along nearly horizontal refracted rays, through the far-coordinate path of
// caustic_photons.comp) and with clear-ocean extinction (optical depths up to 1200: exp
// underflows to 0). The caustic map must stay finite and non-negative, and the flux the photon pass
// deposits plus what fell off the map never exceeds what the surface intercepts.
// tests/extreme/ covers slopes 0.5 to 2 with the floor 1 m down under a 60-degree sun in
// clear-ocean water and 1 km of water under a slope of 0.3; this adds the steep waves in deep
// water, the overhead sun over steep waves and the extinction-free kilometre.
#include "engine/water/wave_sum_surface.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <numbers>
#include <string>

namespace vkw::test {
namespace {

constexpr double kWavelength = 0.5, kHalfExtent = 1.0;
constexpr uint32_t kGrid = 128;

struct Case {
    double depth, zenith_deg;
    glm::dvec3 sigma_t;
};

class caustics_steep_deep : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(caustics_steep_deep, FiniteNonNegativeAndBoundedByTheInterceptedFlux) {
    const double slope = GetParam(), k = 2.0 * std::numbers::pi / kWavelength;
    passes::WaterSurfaceInputs surface;
    surface.half_extent = kHalfExtent;
    surface.grid_resolution = kGrid;
    surface.waves.model = WaveModel::Sum;
    surface.waves.components = {{slope / k, kWavelength, 0.0, 0.0, 0.0, -1.0}};
    const WaveSumSurface cpu(surface.waves, surface.level, surface.time);
    const glm::dvec3 clear_ocean{1.169 + 0.028, 0.0638 + 0.035, 0.0150 + 0.039}, none(0.0);

    for (const Case& c : {Case{1.0, 0.0, none}, Case{1.0, 60.0, none}, Case{1000.0, 0.0, none},
                          Case{1000.0, 60.0, none}, Case{1000.0, 0.0, clear_ocean}, Case{1000.0, 60.0, clear_ocean}}) {
        passes::CausticInputs in;
        in.sun_direction = sun_at(c.zenith_deg, {1.0, 0.0, 0.0});
        in.sun_irradiance = {1.0, 2.0, 0.5};
        in.sigma_t = c.sigma_t;
        in.floor_height = -c.depth;
        in.half_extent = kHalfExtent;
        in.max_amplitude = slope / k;
        in.map_width = in.map_height = kGrid + 2;
        char what_text[128];
        std::snprintf(what_text, sizeof what_text, "slope %g, floor %g m down, sun %g deg from the zenith, %s", slope,
                      c.depth, c.zenith_deg, c.sigma_t.y > 0.0 ? "clear ocean" : "no extinction");
        const std::string what = what_text;
        const CausticRun run = run_caustics(context(), surface, in);
        const passes::CausticMapFrame frame = passes::fit_caustic_map(in);

        size_t bad = 0;
        for (const float e : run.irradiance) bad += !(std::isfinite(e) && e >= 0.0f);
        EXPECT_EQ(bad, 0u) << what << ": non-finite or negative caustic irradiance";

        // Intercepted: docs/model.md section 4's E_s integral of max(0, -s.N) dA over the smooth surface
        // (CPU quadrature). Each photon carries at most its cell's max(0, -s.a), a the vector area of
        // the chord patch through the cell's vertices; for a sine along x that is the integral of
        // (cos theta_s - u_h . grad h) over the cell, and max(0, integral) <= integral of max(0, .),
        // so the chords never intercept more than the smooth surface. Slack, relative: the GPU's
        // fp32 vertices and area products (a few 2^-24 per cell, summed: below 1e-5) and the fixed
        // point's rounding: at most 4 LSB per photon, LSB = max(1e-9 Phi_flat, Phi_in / 2^62) with
        // Phi_flat = E_s T cos(theta_s) texel^2 exp(...) at most the mean flux a cell intercepts
        // (E_s cos(theta_s) texel^2 over whole wavelengths, texel = cell), so at most 4e-9 of the
        // intercepted flux plus 4 N / 2^62 of the bound Phi_in.
        const glm::dvec3 incoming = section4_flux(cpu, in, 200000, true);
        for (int ch = 0; ch < 3; ++ch) {
            long double sum = run.lost(ch), on_map = 0;
            for (size_t t = 0; t < size_t(frame.width) * frame.height; ++t) on_map += run.texel(t, ch);
            sum += on_map;
            const double received = double(sum) * frame.lsb[ch];
            EXPECT_GE(received, 0.0) << what;
            EXPECT_LE(received, incoming[ch] * (1.0 + 1e-5)) << what << ", channel " << ch;
            if (ch == 1) {
                std::printf("%s: on the map %.5g W, off it %.5g W, intercepted %.5g W\n", what.c_str(),
                            double(on_map) * frame.lsb[ch], double(run.lost(ch)) * frame.lsb[ch], incoming[ch]);
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Slope, caustics_steep_deep, ::testing::Values(0.5, 1.0, 2.0), [](const auto& param_info) {
    return "slope_" + std::to_string(int(param_info.param * 10)) + "_tenths";
});

}  // namespace
}  // namespace vkw::test
