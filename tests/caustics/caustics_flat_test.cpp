// Flat water (docs/model.md section 3): the floor irradiance read through caustic_lookup.glsl equals
// E_s cos(theta_s) T exp(-sigma_t d / cos(theta_t)), and with n = 1 the map is uniform to its
// rounding. W - 2 = H - 2 = R: a point's map position is where its line along the refracted sun
// crosses the mean level, so under flat water every photon lands on a texel centre (texel = cell)
// and each texel holds one photon's flux; uniformity is exact up to rounding.
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <utility>

namespace vkw::test {
namespace {

constexpr double kE = 8.0, kFloor = -2.0;
constexpr uint32_t kR = 64;

passes::WaterSurfaceInputs flat_surface() {
    passes::WaterSurfaceInputs s;
    s.level = 0.0;
    s.half_extent = kE;
    s.grid_resolution = kR;
    return s;
}

passes::CausticInputs flat_caustics(double zenith_deg, double ior) {
    passes::CausticInputs c;
    c.sun_direction = sun_at(zenith_deg, {0.0, 0.0, 1.0});
    c.sun_irradiance = {1.0, 2.0, 0.5};
    c.ior = ior;
    c.sigma_t = {0.3, 0.1, 0.05};
    c.floor_height = kFloor;
    c.map_width = c.map_height = kR + 2;
    return c;
}

using caustics_flat = GpuTest;

// The smallest and largest E of channel c over the texels whose centres lie within `reach` m of
// the map's middle on both axes (away from the water's edge, whatever border the kernel adds).
std::pair<double, double> interior_range(const CausticRun& run, const passes::CausticMapFrame& frame, int c,
                                         double reach) {
    auto inside = [&](uint32_t i, double corner, double texel) {
        return std::abs(corner + (i + 0.5) * texel) <= reach;
    };
    double lo = 1e300, hi = 0.0;
    for (uint32_t y = 0; y < frame.height; ++y) {
        if (!inside(y, frame.corner.y, frame.texel.y)) continue;
        for (uint32_t x = 0; x < frame.width; ++x) {
            if (!inside(x, frame.corner.x, frame.texel.x)) continue;
            const double e = run.irradiance[4 * (size_t(y) * frame.width + x) + c];
            lo = std::min(lo, e);
            hi = std::max(hi, e);
        }
    }
    return {lo, hi};
}

// (a) Elevations 90, 60 and 30 degrees (zenith 0, 30, 60), n = 1.333.
TEST_F(caustics_flat, FloorIrradianceMatchesSection3) {
    double worst = 0.0;
    for (const double zenith : {0.0, 30.0, 60.0}) {
        passes::CausticInputs in = flat_caustics(zenith, 1.333);
        const double cos_s = -in.sun_direction.y, d = -kFloor;
        double cos_t = 0.0;
        const double t = fresnel_t(cos_s, in.ior, &cos_t);
        const glm::dvec3 expected = in.sun_irradiance * cos_s * t * glm::exp(-in.sigma_t * (d / cos_t));
        // The lit floor: the water's extent shifted along the refracted ray; probes 3 cells inside it,
        // where every texel the lookup reads has all its photon neighbours.
        const double shift = d * (in.sun_direction.z / in.ior) / cos_t;
        const double h = 2.0 * kE / kR, inner = kE - 3.0 * h;
        ProbeGrid probes;
        probes.count_x = probes.count_z = 41;
        probes.corner = {-inner, kFloor, shift - inner};
        probes.step_x = {2.0 * inner / 40, 0.0, 0.0};
        probes.step_z = {0.0, 0.0, 2.0 * inner / 40};
        const CausticRun run = run_caustics(context(), flat_surface(), in, probes);
        const passes::CausticMapFrame frame = passes::fit_caustic_map(in);

        // Tolerance, relative, first order in u = 2^-24:
        // - a photon's flux: the vector area (3 differences, 2 products and a sum: 6 u), -s.a
        //   (s rounded, one product: 2 u), T (fresnel_exact's ~16 operations, each at most u, on
        //   R <= 0.06: 16 u), the path length (refracted t.y ~8 u, the quotient: 10 u relative)
        //   entering exp through the optical depth x = sigma_t l (10 u x), exp itself (2 u), the
        //   three products (3 u) and the uint64 rounding of the total (u): (30 + 10 x) u;
        // - a photon's light-space coordinate: the patch centre (|P| 3 u), P + l t (l's 18 u
        //   times l, and |hit| u), the difference with the origin and the dot with the axis
        //   (|P - o| 3 u, the axis's own rounding u): delta = u (4 |hit| + 18 l + 4 |P - o|) /
        //   texel, in texels; a texel gathers at most 4 photons whose weights each move by at
        //   most 2 delta: 8 delta;
        // - the resolve and the lookup: float(uint64) (u), the factor (u), four bilinear weights
        //   and their sum (4 u), |s.N| (u): 7 u;
        // - the fixed point: at most 4 taps per texel, each rounded by at most 1 LSB, and
        //   LSB <= 1e-9 of the flat texel flux: 4e-9.
        const double l = d / cos_t;
        const double x = std::max({in.sigma_t.x, in.sigma_t.y, in.sigma_t.z}) * l;
        const double coord = 2.0 * kE + 2.0 * d + 2.0 * frame.texel.x;  // bound on |hit|, |P - o|
        const double delta = kUnit * (8.0 * coord + 18.0 * l) / std::min(frame.texel.x, frame.texel.y);
        const double tolerance = (30.0 + 10.0 * x) * kUnit + 8.0 * delta + 7.0 * kUnit + 4e-9;

        EXPECT_EQ(run.lost(0) + run.lost(1) + run.lost(2), 0u);
        double ratio = 0.0;
        for (size_t k = 0; k < run.probes.size() / 4; ++k) {
            for (int c = 0; c < 3; ++c) {
                const double error = std::abs(run.probes[4 * k + c] / expected[c] - 1.0);
                ratio = std::max(ratio, error / tolerance);
                if (error > tolerance) {
                    ADD_FAILURE() << "zenith " << zenith << " probe " << k << " channel " << c << ": "
                                  << run.probes[4 * k + c] << " vs " << expected[c];
                    break;
                }
            }
        }
        std::printf("zenith %4.1f: E expected %.6f %.6f %.6f, tolerance %.2e relative, worst error/tolerance %.4f\n",
                    zenith, expected.x, expected.y, expected.z, tolerance, ratio);
        worst = std::max(worst, ratio);
    }
    std::printf("worst error / tolerance over all suns: %.4f\n", worst);
}

// (b) n = 1, no jitter, vertical sun, one and four photons per cell, photon lattice aligned with
// the texels: every interior texel equal.
// Every kernel: under flat water the adaptive kernel's hats have their nodes one photon spacing
// apart and sum to one, and a photon's footprint is its sub-cell, inside its texel, so both must
// be exactly as uniform as the bilinear one.
TEST_F(caustics_flat, RefractionFreeMapIsUniform) {
    for (const CausticKernel kernel : {CausticKernel::Bilinear, CausticKernel::Adaptive, CausticKernel::Footprint})
        for (const uint32_t sub : {1u, 2u}) {
            passes::CausticInputs in = flat_caustics(0.0, 1.0);
            in.sigma_t = glm::dvec3(0.0);
            in.sub_photons = sub;
            in.kernel = kernel;
            const CausticRun run = run_caustics(context(), flat_surface(), in);
            const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
            // Interior: texel centres within E - 1.5 texels (the bilinear map's texels 2 .. W - 3),
            // away from the border and the partly covered edge.
            for (int c = 0; c < 3; ++c) {
                const auto [lo, hi] = interior_range(run, frame, c, kE - 1.5 * frame.texel.x);
                // Bound, relative: max(LSB x deposits per texel, 2^-24 max|coordinate| / texel size),
                // both with their counts. A texel gathers at most (2 S - 1 + 1)^2 = 4 S^2 taps, each
                // rounded by at most 1 LSB = 1e-9 of the flat texel flux. A photon's coordinate is off
                // by at most 8 u max|coordinate| / texel texels (as in FloorIrradianceMatchesSection3),
                // moving the taps of at most 4 S^2 photons of flux 1/S^2 each by twice that; the
                // photons' own fluxes differ by the rounding of their area and products, 16 u.
                const double lsb_term = 4.0 * sub * sub * 1e-9;
                const double coord = 2.0 * kE + 2.0 * frame.texel.x;
                const double coord_term = 8.0 * (8.0 * kUnit * coord / frame.texel.x) + 16.0 * kUnit;
                const double bound = std::max(lsb_term, coord_term);
                const double spread = (hi - lo) / hi;
                std::printf("S = %u channel %d: E in [%.9g, %.9g] (E_s %.3g), spread %.3e, bound %.3e (ratio %.4f)\n",
                            sub, c, lo, hi, in.sun_irradiance[c], spread, bound, spread / bound);
                EXPECT_LE(spread, bound) << "S = " << sub << " channel " << c;
                EXPECT_NEAR(hi / in.sun_irradiance[c], 1.0, bound);
            }
        }
}

// (c) Sparse photons: 16 cells on a 64-texel map, n = 1, vertical sun: photons land 4 texels
// apart. The adaptive kernel's hats reach from one neighbour's landing point to the other's, 4
// texels on each side, and hats spaced h apart sum to one everywhere; the footprint kernel spreads
// each photon over its cell's 4 x 4 texels: either way the covered interior is uniform and equal
// to E_s, to rounding. The bilinear kernel leaves the texels between photons empty (spread 1),
// which is what shows this test can fail.
TEST_F(caustics_flat, AdaptiveKernelFillsBetweenSparsePhotons) {
    constexpr uint32_t kCells = 16;
    passes::WaterSurfaceInputs surface = flat_surface();
    surface.grid_resolution = kCells;
    for (const CausticKernel kernel : {CausticKernel::Adaptive, CausticKernel::Footprint, CausticKernel::Bilinear}) {
        passes::CausticInputs in = flat_caustics(0.0, 1.0);
        in.sigma_t = glm::dvec3(0.0);
        in.grid_resolution = kCells;
        in.kernel = kernel;
        const CausticRun run = run_caustics(context(), surface, in);
        const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
        // Covered interior: texel centres within E - 1 m (the outermost photons sit at E - 0.5 m
        // and a tent reaches 1 m, so every such texel gets both of its neighbouring photons).
        for (int c = 0; c < 3; ++c) {
            const auto [lo, hi] = interior_range(run, frame, c, kE - 1.0);
            const double spread = (hi - lo) / std::max(hi, 1e-300);
            if (kernel == CausticKernel::Bilinear) {
                std::printf("bilinear channel %d: E in [%.6g, %.6g], spread %.3f (holes between photons)\n", c, lo, hi,
                            spread);
                EXPECT_GT(spread, 0.5) << "the bilinear kernel should leave texels between sparse photons empty";
                continue;
            }
            // Bound, relative: the hats' sides come from fp32 landing coordinates, each off by at
            // most 8 u max|coordinate| / texel texels (as above), so each hat weight by that over
            // the side and the partition of unity by twice it per photon, at most 4 photons per axis
            // reach a texel: 2 axes x 4 x 2 x 8 u coord/texel; plus 16 u for the photons' fluxes
            // and the LSB rounding of at most 64 taps of 1e-9.
            const double coord = 2.0 * kE + 8.0 * frame.texel.x;
            const double bound = 2.0 * 4.0 * 2.0 * 8.0 * kUnit * coord / frame.texel.x + 16.0 * kUnit + 64e-9;
            std::printf("%s channel %d: E in [%.9g, %.9g] (E_s %.3g), spread %.3e, bound %.3e\n",
                        kernel == CausticKernel::Adaptive ? "adaptive" : "footprint", c, lo, hi, in.sun_irradiance[c],
                        spread, bound);
            EXPECT_LE(spread, bound) << "channel " << c;
            EXPECT_NEAR(hi / in.sun_irradiance[c], 1.0, bound) << "channel " << c;
        }
    }
}

// (d) The bilinear kernel keeps its fixed one-texel tent, sampled at texel centres, so off whole
// numbers of texels per photon it does not partition the map: n = 1, flat water, vertical sun,
// photons d = cell / texel texels apart. Its own ripple, derived: photon i lands at texel
// coordinate u_i (its cell's centre), carries E_s cell^2, and gives texel k the weight
// tent(k - u_i) per axis, so texel (k, l) holds E_s (d sum_i tent(k - u_i)) (d sum_j tent(l - v_j)).
// Checked texel by texel within the rounding bound of RefractionFreeMapIsUniform (4 d^-2 taps of
// 1e-9 and the coordinates' 8 u max|coordinate| / texel). At d = 1 (photons on texel centres) and
// d = 2 (on texel edges, half to each side) the sums are exactly 1; at d = 1.33 and 0.67 they
// ripple (0.80 to 1.74 of E_s), and the map must follow the prediction there.
TEST_F(caustics_flat, BilinearKernelRipplesAsDerivedOffWholeSpacings) {
    for (const uint32_t texels : {64u, 128u, 85u, 43u}) {  // d = 1, 2, 1.33, 0.67
        passes::CausticInputs in = flat_caustics(0.0, 1.0);
        in.sigma_t = glm::dvec3(0.0);
        in.kernel = CausticKernel::Bilinear;
        in.half_extent = kE;  // as run_caustics sets them, for the frame below
        in.grid_resolution = kR;
        in.map_width = in.map_height = texels + 2;
        const CausticRun run = run_caustics(context(), flat_surface(), in);
        const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
        const double cell = 2.0 * kE / kR, d = cell / frame.texel.x;
        // The predicted factor of texel k along one axis: d sum_i tent(k - u_i), texel coordinates
        // whose integers are texel centres.
        auto factor = [&](int k, double corner) {
            double sum = 0.0;
            for (uint32_t i = 0; i < kR; ++i) {
                const double u = (-kE + (i + 0.5) * cell - corner) / frame.texel.x - 0.5;
                sum += std::max(0.0, 1.0 - std::abs(k - u));
            }
            return d * sum;
        };
        const double coord = 2.0 * kE / frame.texel.x + 2.0;
        const double bound = 4.0 / (d * d) * 1e-9 + 4.0 * (8.0 * kUnit * coord) + 16.0 * kUnit;
        double worst = 0.0, lo = 1e300, hi = 0.0;
        for (uint32_t y = 0; y < frame.height; ++y) {
            const double z = frame.corner.y + (y + 0.5) * frame.texel.y;
            if (std::abs(z) > kE - 1.5 * std::max(cell, frame.texel.y)) continue;
            for (uint32_t x = 0; x < frame.width; ++x) {
                const double xw = frame.corner.x + (x + 0.5) * frame.texel.x;
                if (std::abs(xw) > kE - 1.5 * std::max(cell, frame.texel.x)) continue;
                const double predicted = factor(int(x), frame.corner.x) * factor(int(y), frame.corner.y);
                const double got = run.irradiance[4 * (size_t(y) * frame.width + x)] / in.sun_irradiance[0];
                worst = std::max(worst, std::abs(got / predicted - 1.0));
                lo = std::min(lo, got);
                hi = std::max(hi, got);
            }
        }
        std::printf(
            "bilinear, photons %.3f texels apart: texels %.6f .. %.6f of E_s, worst off the derived ripple "
            "%.2e (bound %.2e)\n",
            d, lo, hi, worst, bound);
        EXPECT_LE(worst, bound) << "d = " << d;
        if (texels == 85u || texels == 43u) {
            EXPECT_GT(hi - lo, 0.05) << "the ripple should show at d = " << d;
        }
    }
}

}  // namespace
}  // namespace vkw::test
