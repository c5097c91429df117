// (c) Energy: the flux the photon pass deposits equals docs/model.md section 4's integral over the
// same surface, computed independently on the CPU (double-precision quadrature over engine/water's
// analytic WaveSumSurface, not by summing photons). (d) Two runs are bit-identical. (e) A grazing
// sun gives finite, non-negative maps and never more flux than the surface intercepts.
#include "engine/scene/scene_loader.hpp"
#include "engine/water/wave_sum_surface.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kE = 4.0, kWavelength = 2.0;

passes::WaterSurfaceInputs sine_surface(double slope, uint32_t resolution) {
    passes::WaterSurfaceInputs s;
    s.level = 0.0;
    s.half_extent = kE;
    s.grid_resolution = resolution;
    s.waves.model = WaveModel::Sum;
    const double k = 2.0 * std::numbers::pi / kWavelength;
    s.waves.components = {{slope / k, kWavelength, 0.0, 0.0, 0.0, -1.0}};  // h = A sin(k x), A k = slope
    return s;
}

passes::CausticInputs sine_caustics(const passes::WaterSurfaceInputs& s, double zenith_deg) {
    passes::CausticInputs c;
    c.sun_direction = sun_at(zenith_deg, {1.0, 0.0, 0.0});
    c.sun_irradiance = {1.0, 2.0, 0.5};
    c.sigma_t = {0.3, 0.1, 0.05};
    c.floor_height = -2.0;
    c.half_extent = s.half_extent;
    c.max_amplitude = s.waves.components[0].amplitude;
    c.fit_margin = 1.5;  // the waves deflect photons sideways by at most ~0.5 m here
    c.map_width = c.map_height = 128;
    return c;
}

glm::dvec3 deposited(const CausticRun& run, const passes::CausticMapFrame& frame, bool with_lost) {
    glm::dvec3 total(0.0);
    const size_t texels = size_t(frame.width) * frame.height;
    for (int c = 0; c < 3; ++c) {
        long double sum = with_lost ? run.lost(c) : 0;
        for (size_t t = 0; t < texels; ++t) sum += run.texel(t, c);
        total[c] = double(sum) * frame.lsb[c];
    }
    return total;
}

using caustics_energy = GpuTest;

TEST_F(caustics_energy, DepositedFluxEqualsSection4Integral) {
    double worst = 0.0;
    // Every splat kernel: the adaptive and footprint ones' taps are split by cumulative rounding,
    // so they must deposit exactly what the bilinear one does.
    for (const CausticKernel kernel : {CausticKernel::Bilinear, CausticKernel::Adaptive, CausticKernel::Footprint}) {
        for (const double zenith : {0.0, 60.0}) {
            for (const double slope : {0.1, 0.3}) {
                const passes::WaterSurfaceInputs surface = sine_surface(slope, 512);
                passes::CausticInputs in = sine_caustics(surface, zenith);
                in.kernel = kernel;
                const CausticRun run = run_caustics(context(), surface, in);
                const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
                const WaveSumSurface cpu(surface.waves, surface.level, surface.time);
                const glm::dvec3 expected = section4_flux(cpu, in, 200000);
                const glm::dvec3 got = deposited(run, frame, false);
                EXPECT_EQ(run.lost(0) + run.lost(1) + run.lost(2), 0u) << "photons fell off the map";
                for (int c = 0; c < 3; ++c) {
                    const double error = std::abs(got[c] / expected[c] - 1.0);
                    worst = std::max(worst, error / 0.005);
                    EXPECT_LE(error, 0.005)
                        << "kernel " << int(kernel) << " zenith " << zenith << " slope " << slope << " channel " << c;
                }
                std::printf(
                    "%s zenith %4.1f slope %.1f: deposited %.7g %.7g %.7g W, section 4 %.7g %.7g %.7g W, "
                    "relative error %.2e %.2e %.2e\n",
                    kernel == CausticKernel::Adaptive    ? "adaptive"
                    : kernel == CausticKernel::Footprint ? "footprint"
                                                         : "bilinear",
                    zenith, slope, got.x, got.y, got.z, expected.x, expected.y, expected.z, got.x / expected.x - 1.0,
                    got.y / expected.y - 1.0, got.z / expected.z - 1.0);
            }
        }
    }
    std::printf("worst error / 0.5%%: %.4f\n", worst);
}

TEST_F(caustics_energy, TwoRunsAreBitIdentical) {
    const passes::WaterSurfaceInputs surface = sine_surface(0.3, 256);
    passes::CausticInputs in = sine_caustics(surface, 60.0);
    in.sub_photons = 2;
    const CausticRun a = run_caustics(context(), surface, in);
    const CausticRun b = run_caustics(context(), surface, in);
    EXPECT_EQ(std::memcmp(a.flux.data(), b.flux.data(), a.flux.size() * 8), 0);
    EXPECT_EQ(std::memcmp(a.irradiance.data(), b.irradiance.data(), a.irradiance.size() * 4), 0);
}

// The adaptive kernel's lanes take their neighbours' rays from each other by subgroup shuffles
// (shaders/caustics/caustic_photons.comp). Each ray is the same function of the same inputs
// whichever lane traces it, so the map must be the same bit for bit as when every lane traces its
// own: on waves along both axes, with sub-cells and jitter, a grid of 203 photons a side (no
// multiple of the 64-invocation rows nor of the 8 rows each walks), and with a receiver mesh (the
// sun shadow variant, whose neighbours land on each photon's own plane).
TEST_F(caustics_energy, AdaptiveLanesSharingRaysGiveTheSameMapAsLanesTracingTheirOwn) {
    // Every device the suite runs on (lavapipe, the GPUs it was run on) has them; without them only
    // one variant would exist and the comparison could not fail.
    ASSERT_TRUE(context().features().compute_subgroup_shuffle_relative)
        << "no subgroup shuffles in compute shaders (or subgroups wider than 64 lanes) on this device";
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 5, 6], "target": [0, -1, 0]},
      "sun": {"elevation_deg": 50, "azimuth_deg": 30, "irradiance": [1, 2, 0.5]},
      "sky": {"radiance": [0.2, 0.3, 0.4]},
      "floor": {"height": -2, "half_extent": 4},
      "receivers": [{"type": "sphere", "radius": 0.6, "translation": [0.3, -1.2, -0.5]}]
    })",
                                    "lanes.json");
    const passes::ReceiverMeshes meshes(context(), scene.receivers);
    for (const uint32_t sub : {1u, 2u}) {
        for (const bool with_mesh : {false, true}) {
            passes::WaterSurfaceInputs surface = sine_surface(0.3, sub == 1 ? 203 : 101);
            surface.waves.components.push_back({0.02, 1.3, 70.0, 40.0, 0.0, -1.0});
            passes::CausticInputs in = sine_caustics(surface, 40.0);
            in.sun_direction = scene.sun.direction;
            in.kernel = CausticKernel::Adaptive;
            in.sub_photons = sub;
            in.jitter = sub > 1;
            in.max_amplitude += 0.02;
            CausticRun runs[2];
            for (const bool share : {true, false}) {
                in.share_rays_between_lanes = share;
                runs[share ? 0 : 1] = run_caustics(context(), surface, in, {}, with_mesh ? &meshes : nullptr, 4.0);
            }
            uint64_t total = 0;
            for (const uint64_t q : runs[0].flux) total += q;
            EXPECT_GT(total, 0u) << "an empty map would pass";
            ASSERT_EQ(runs[0].flux.size(), runs[1].flux.size());
            EXPECT_EQ(std::memcmp(runs[0].flux.data(), runs[1].flux.data(), runs[0].flux.size() * 8), 0)
                << "sub-photons " << sub << (with_mesh ? ", with the receiver mesh" : "");
        }
    }
}

TEST_F(caustics_energy, GrazingSunStaysFiniteAndBounded) {
    for (const double slope : {0.3, 1.0}) {
        for (const double zenith : {89.0, 90.0, 91.0}) {
            const passes::WaterSurfaceInputs surface = sine_surface(slope, 256);
            const passes::CausticInputs in = sine_caustics(surface, zenith);
            const CausticRun run = run_caustics(context(), surface, in);
            const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
            size_t bad = 0;
            for (const float e : run.irradiance) bad += !(std::isfinite(e) && e >= 0.0f);
            EXPECT_EQ(bad, 0u) << "zenith " << zenith << " slope " << slope;
            const WaveSumSurface cpu(surface.waves, surface.level, surface.time);
            const glm::dvec3 incoming = section4_flux(cpu, in, 200000, true);
            const glm::dvec3 got = deposited(run, frame, true);
            for (int c = 0; c < 3; ++c) {
                // The cells' chords may intercept slightly more than the smooth surface (second
                // order in the cell size): 0.1% slack, far below the Fresnel loss at grazing.
                EXPECT_LE(got[c], incoming[c] * 1.001) << "zenith " << zenith << " slope " << slope;
            }
            if (!frame.sun_up) {
                EXPECT_EQ(got.x + got.y + got.z, 0.0) << "the sun is not up";
            }
            std::printf("zenith %4.1f slope %.1f: deposited %.5g W of %.5g W intercepted (ratio %.4f)\n", zenith, slope,
                        got.x, incoming.x, incoming.x > 0.0 ? got.x / incoming.x : 0.0);
        }
    }
}

}  // namespace
}  // namespace vkw::test
