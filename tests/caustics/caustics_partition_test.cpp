// The splat kernels partition the map exactly: with n = 1 the water bends no ray, so under any
// surface the floor's irradiance is exactly uniform (docs/model.md section 4, "How the photon map
// keeps this law texel by texel"), and whatever the map shows beyond rounding is the kernel's
// error. Scene: a 1-D sine along x (A = 0.01 m, lambda = 0.25 m) over a floor 0.913 m down, a sun
// at elevation 60 degrees and azimuth 237 or 270 degrees (the landed lattice both stretched along x
// by up to +-15% over a period and sheared), no extinction; photons 1.0 to 4.0 texels apart in
// steps of 0.1, for the adaptive and footprint kernels. The former adaptive kernel (a symmetric
// tent sampled at texel centres, at least a texel wide) rippled by +-8-11% here.
#include "engine/scene/scene.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kAmplitude = 0.01, kWavelength = 0.25, kDepth = 0.913;
constexpr double kHalfExtent = 0.25;      // two wavelengths of water
constexpr uint32_t kPhotonsPerSide = 40;  // one per cell: R = 40, photons 12.5 mm apart
const glm::dvec3 kSunIrradiance{1.0, 2.0, 0.5};

passes::WaterSurfaceInputs sine_surface() {
    passes::WaterSurfaceInputs s;
    s.level = 0.0;
    s.half_extent = kHalfExtent;
    s.grid_resolution = kPhotonsPerSide;
    s.waves.model = WaveModel::Sum;
    s.waves.components = {{kAmplitude, kWavelength, 0.0, 0.0, 0.0, -1.0}};  // h = A sin(k x)
    return s;
}

// Photons `texels_per_photon` texels apart: W - 2 = that times R (a whole number in steps of 0.1,
// with R = 40), the same along z.
passes::CausticInputs sine_caustics(double azimuth_deg, double texels_per_photon, CausticKernel kernel) {
    passes::CausticInputs c;
    c.sun_direction = -direction_toward_sun(60.0, azimuth_deg);
    c.sun_irradiance = kSunIrradiance;
    c.ior = 1.0;
    c.sigma_t = glm::dvec3(0.0);
    c.floor_height = -kDepth;
    c.half_extent = kHalfExtent;
    c.max_amplitude = kAmplitude;
    c.kernel = kernel;
    const uint32_t texels = static_cast<uint32_t>(std::lround(texels_per_photon * kPhotonsPerSide));
    c.map_width = c.map_height = texels + 2;
    return c;
}

using caustics_partition = GpuTest;

TEST_F(caustics_partition, RefractionFreeSineIsUniformAtEverySpacing) {
    const passes::WaterSurfaceInputs surface = sine_surface();
    const double k = 2.0 * std::numbers::pi / kWavelength;
    double worst = 0.0;
    for (const CausticKernel kernel : {CausticKernel::Adaptive, CausticKernel::Footprint}) {
        const char* name = kernel == CausticKernel::Adaptive ? "adaptive" : "footprint";
        for (const double azimuth : {237.0, 270.0}) {
            double kernel_worst = 0.0;
            for (int tenths = 10; tenths <= 40; ++tenths) {
                const double spacing = tenths / 10.0;
                const passes::CausticInputs in = sine_caustics(azimuth, spacing, kernel);
                const CausticRun run = run_caustics(context(), surface, in);
                const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
                // The interior: texels whose squares lie between the outermost photons' landing
                // points, which sit half a photon spacing inside the water's edge and move by at
                // most A |shear| along each axis.
                const double photon = 2.0 * kHalfExtent / kPhotonsPerSide;
                const glm::dvec2 reach = glm::dvec2(kHalfExtent - 0.5 * photon) - kAmplitude * glm::abs(frame.shear);
                auto inside = [&](uint32_t i, double corner, double texel, double limit) {
                    const double lo = corner + i * texel;
                    return lo >= -limit && lo + texel <= limit;
                };
                // Bound, relative, per texel (fp32 and the fixed point; the lattice's own shape adds
                // nothing, which is what the test is about):
                // - coordinates: a landing point's or a sun coordinate's texel coordinate is off by
                //   at most delta = 4 u C texels, C = max(W, H) the largest coordinate (the point's
                //   and the origin's rounding, the subtraction, the dot product). Per axis the map
                //   is covered by two hats at a time (the lattice does not fold at n = 1), each built
                //   from its own copy of their shared node: their sum is off by at most
                //   2 x 2 delta / side; the flux ratio (the sun hat's integral over the landed one's)
                //   by at most 2 delta / side, side >= the spacing times 1 - A k |shear| (the
                //   sine's least stretch). The footprint kernel alike: its quads' shared edges are
                //   computed twice (gaps and overlaps at most 2 delta wide) and each quad's area
                //   and its flux by at most 2 delta / side per axis. Both axes: 12 delta / side;
                // - the photons' own fp32 arithmetic (area, Fresnel, products): 16 u;
                // - the fixed point: at most n^2 photons' taps per texel, n = 2 ceil(spacing
                //   (1 + A k |shear|)) + 1 per axis, each rounded by at most 1 LSB = 1e-9 of the
                //   flat texel's flux.
                const double stretch = kAmplitude * k * std::max(std::abs(frame.shear.x), std::abs(frame.shear.y));
                const double narrowest = spacing * (1.0 - stretch);
                const double hats = 2.0 * std::ceil(spacing * (1.0 + stretch)) + 1.0;
                const double delta = 4.0 * kUnit * std::max(frame.width, frame.height);
                const double bound = 12.0 * delta / narrowest + 16.0 * kUnit + hats * hats * 1e-9;
                for (int c = 0; c < 3; ++c) {
                    double error = 0.0;
                    size_t texels = 0;
                    for (uint32_t y = 0; y < frame.height; ++y) {
                        if (!inside(y, frame.corner.y, frame.texel.y, reach.y)) continue;
                        for (uint32_t x = 0; x < frame.width; ++x) {
                            if (!inside(x, frame.corner.x, frame.texel.x, reach.x)) continue;
                            const double e = run.irradiance[4 * (size_t(y) * frame.width + x) + c];
                            error = std::max(error, std::abs(e / kSunIrradiance[c] - 1.0));
                            ++texels;
                        }
                    }
                    ASSERT_GT(texels, 100u) << "the interior should hold most of the map";
                    EXPECT_LE(error, bound) << name << " azimuth " << azimuth << " spacing " << spacing << " texels"
                                            << " channel " << c;
                    kernel_worst = std::max(kernel_worst, error / bound);
                    if (c == 0 && (tenths % 10 == 0 || error > bound)) {
                        std::printf(
                            "%s azimuth %.0f, photons %.1f texels apart: worst texel %.3e from E_s over %zu "
                            "texels (bound %.3e)\n",
                            name, azimuth, spacing, error, texels, bound);
                    }
                }
            }
            std::printf("%s azimuth %.0f: worst error / bound over spacings 1.0 .. 4.0: %.4f\n", name, azimuth,
                        kernel_worst);
            worst = std::max(worst, kernel_worst);
        }
    }
    std::printf("worst error / bound: %.4f\n", worst);
}

// The fold depth D_f of the same sine refracting (n = 1.333), the sun in the sine's plane: the
// shallowest floor at which the landing map X(x0) = x0 + (h + D) q(x0), q = t_x / -t_y, stops
// being monotone, D_f = min over x0 with q' < 0 of -(1 + h' q) / q' - h (double precision,
// q' by central differences on 20000 points of a period: 0.4356 m at 30 degrees from the zenith,
// 0.1635 m at 60).
double fold_depth(double zenith_deg) {
    const double k = 2.0 * std::numbers::pi / kWavelength, n = 1.333, a = zenith_deg * std::numbers::pi / 180.0;
    auto q = [&](double x) {
        const glm::dvec2 s(std::sin(a), -std::cos(a));
        const double slope = kAmplitude * k * std::cos(k * x);
        const glm::dvec2 normal = glm::normalize(glm::dvec2(-slope, 1.0));
        const double c = -glm::dot(s, normal), eta = 1.0 / n;
        const glm::dvec2 t = eta * s + (eta * c - std::sqrt(1.0 - eta * eta * (1.0 - c * c))) * normal;
        return t.x / -t.y;
    };
    double best = 1e300;
    for (int i = 0; i < 20000; ++i) {
        const double x = kWavelength * i / 20000.0, e = 1e-6;
        const double dq = (q(x + e) - q(x - e)) / (2.0 * e);
        if (dq >= 0.0) continue;
        const double slope = kAmplitude * k * std::cos(k * x);
        best = std::min(best, -(1.0 + slope * q(x)) / dq - kAmplitude * std::sin(k * x));
    }
    return best;
}

// The fold depth from the map alone, as one would find it without knowing it: the brightest
// texel's irradiance E_max(d) at floor depths d = 0.5 .. 0.9 D_f (9 depths), a quadratic fitted to
// 1 / E_max(d) by least squares, and its root nearest D_f; the adaptive kernel. Within 1% of D_f.
// The resolution this needs: near the crest X'(x0) ~ (1 - d / D_f) + (d / D_f) (k^2 / 2) (x0 - x_c)^2,
// so at 0.9 D_f the peak is about 5 mm wide on the floor, and a texel must be a tenth of that for
// its average to follow the peak (texels of lambda / 64 = 3.9 mm read the root 9-11% deep). Here
// one wavelength of water, R = 128 photons along it (1.95 mm apart) and texels of lambda / 512
// (0.49 mm), 4 texels per photon spacing.
constexpr double kFoldHalfExtent = 0.125;
constexpr uint32_t kFoldTexels = 512;
TEST_F(caustics_partition, FoldDepthFromTheBrightestTexel) {
    for (const double zenith : {30.0, 60.0}) {
        const double exact = fold_depth(zenith);
        passes::WaterSurfaceInputs surface = sine_surface();
        surface.half_extent = kFoldHalfExtent;
        surface.grid_resolution = 128;
        std::vector<double> depth, inverse;
        for (int step = 0; step <= 8; ++step) {
            const double d = (0.5 + 0.05 * step) * exact;
            passes::CausticInputs in = sine_caustics(90.0, 1.0, CausticKernel::Adaptive);
            in.sun_direction = sun_at(zenith, {1.0, 0.0, 0.0});
            in.ior = 1.333;
            in.floor_height = -d;
            in.half_extent = kFoldHalfExtent;
            in.map_width = kFoldTexels + 2;
            in.map_height = 10;
            in.fit_margin = 0.0;
            const CausticRun run = run_caustics(context(), surface, in);
            const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
            double brightest = 0.0;
            for (uint32_t y = 0; y < frame.height; ++y) {
                for (uint32_t x = 0; x < frame.width; ++x) {
                    brightest = std::max(brightest, double(run.irradiance[4 * (size_t(y) * frame.width + x)]));
                }
            }
            ASSERT_GT(brightest, 0.0);
            depth.push_back(d);
            inverse.push_back(1.0 / brightest);
        }
        // Least squares for 1/E = c0 + c1 d + c2 d^2 (normal equations, 3 x 3, Cramer's rule).
        double m[3][3] = {}, r[3] = {};
        for (size_t i = 0; i < depth.size(); ++i) {
            const double p[3] = {1.0, depth[i], depth[i] * depth[i]};
            for (int a = 0; a < 3; ++a) {
                r[a] += p[a] * inverse[i];
                for (int b = 0; b < 3; ++b) m[a][b] += p[a] * p[b];
            }
        }
        auto det = [](const double x[3][3]) {
            return x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) -
                   x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
                   x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
        };
        double c[3];
        for (int a = 0; a < 3; ++a) {
            double x[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) x[i][j] = j == a ? r[i] : m[i][j];
            c[a] = det(x) / det(m);
        }
        const double discriminant = c[1] * c[1] - 4.0 * c[2] * c[0];
        ASSERT_GE(discriminant, 0.0) << "the fitted 1/E_max has no root";
        const double r1 = (-c[1] + std::sqrt(discriminant)) / (2.0 * c[2]);
        const double r2 = (-c[1] - std::sqrt(discriminant)) / (2.0 * c[2]);
        const double root = std::abs(r1 - exact) < std::abs(r2 - exact) ? r1 : r2;
        std::printf("zenith %.0f: fold depth %.4f m (exact %.4f m), error %.2f%%\n", zenith, root, exact,
                    100.0 * (root / exact - 1.0));
        EXPECT_NEAR(root / exact, 1.0, 0.01) << "zenith " << zenith;
    }
}

}  // namespace
}  // namespace vkw::test
