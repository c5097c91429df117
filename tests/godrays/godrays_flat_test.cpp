// Flat water against docs/model.md section 6, through the whole frame (beams, lines, resolve, blur,
// composite): nothing but the in-scatter lights these scenes (black sky, black floor far below),
// so each pixel is the godrays alone. The views: a horizontal ray at depth 2 m from a camera in the
// water, and a vertical ray down from a camera 3 m above the surface; g = 0 and g = 0.9; every
// channel with its own sigma_t.
//
// Why the lines are exact here. The beams are tubes: their photon cells (squares of side
// h = 2 E / G) swept along the refracted sun, carrying E_tube = E_perp0, and they tile the lit water.
// Where a tube is at least one pixel wide where it is seen (h / sqrt(A_pix) >= 1), every pixel
// takes the exact chord of its centre ray through each tube slice (passes/godrays/godrays_lines.hpp), so a
// pixel's sum is docs/model.md section 6's integral over the lit part of its ray. The line count and
// the resolution are chosen for that: G = 64 (h = 0.125 m) on 7 x 7 pixels (one pyramid level, no
// upsampling), with the fields of view below; each test checks the condition over its whole lit
// path before comparing. What remains is fp32 rounding, bounded in kRounding below.
#include "tests/godrays/godrays_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cmath>
#include <numbers>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 7;  // one pyramid level (passes/godrays/godrays_lines.hpp: fewer than 8 pixels)
constexpr int kCentre = 3;     // its 5 x 5 blur stays inside the image
constexpr double kUnit = 0x1.0p-24;

// Per channel sigma_t = (1.2, 0.8, 0.9) 1/m, sigma_s = (0.3, 0.5, 0.8) 1/m.
std::string medium(const char* g) {
    return std::string(R"({"sigma_a": [0.9, 0.3, 0.1], "sigma_s": [0.3, 0.5, 0.8], "g": )") + g + "}";
}

// Relative fp32 error of a pixel, first order in u = 2^-24: one chord deposit takes about 40
// roundings (the ray from the inverse view-projection, the prism's three bounds, the two-sided
// clip, the share, sinhc, the products) and exp of an optical depth x carries 4 x u of absolute
// error from x's own four roundings (x < 10 on these paths: 10 m at 1.2 1/m); the frame constants
// and the surface grid enter rounded (sun, n, sigma: 10 u through the Fresnel and refraction; the
// tube faces at +-4 m to 2.4e-7 m, 2e-6 of a 0.125 m chord). Deposits are positive, so the sum keeps
// the largest relative error. The fixed point rounds each deposit by at most 2^-29 L_ref, L_ref at
// most 10 times the pixel's value here, over at most 2 (10 m / h + 2) = 164 deposits: 3e-6. The
// resolve, the blur and the composite add 30 u. In all: (40 + 40 + 10 + 30) u + 2e-6 + 3e-6 < 1.3e-5.
constexpr double kRounding = (40.0 + 40.0 + 10.0 + 30.0) * kUnit + 2e-6 + 3e-6;

// Every point of the pixel's lit path is seen with its tube at least one pixel wide: h / sqrt(A_pix) >= 1
// with A_pix = Omega s^2 (camera in the water) or Omega (s_a + s_w / n)^2 (straight down from above)
// at the path's far end, its widest.
void expect_wide_tubes(const Scene& scene, double far_cone) {
    const double h = 2.0 * scene.water->half_extent / scene.effects.godrays.grid;
    const double pixel_angle = 2.0 * std::tan(scene.camera.fov_y_deg * std::numbers::pi / 360.0) / kSize;
    ASSERT_GE(h / (pixel_angle * far_cone), 1.0) << "the tubes must be a pixel wide for the chords to be exact";
}

void expect_centre_matches(const RenderResult& result, const Scene& scene) {
    const glm::dvec3 expected = expected_blurred(scene, kSize, kSize, kCentre, kCentre);
    for (int c = 0; c < 3; ++c) {
        ASSERT_GT(expected[c], 0.0);
        EXPECT_NEAR(result.image.pixel(kCentre, kCentre)[c] / expected[c], 1.0, kRounding) << "channel " << c;
    }
}

class godrays_flat : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(godrays_flat, HorizontalRayUnderWaterMatchesSection6) {
    // At depth 2 m looking along -x, the sun in the y-z plane: the lit path ends at the water's side
    // 4 m away; 10 degrees over 7 pixels.
    const Scene scene =
        godray_scene(R"({"position": [0, -2, 0], "direction": [-1, 0, 0], "fov_y_deg": 10, "near": 0.01, "far": 100})",
                     medium(GetParam()), {"effects.godrays.grid=64"});
    expect_wide_tubes(scene, 4.0 / std::cos(2.0 * 5.0 * std::numbers::pi / 180.0));
    expect_centre_matches(render_godrays(context(), scene, kSize, kSize), scene);
}

TEST_P(godrays_flat, VerticalRayFromAboveMatchesSection6) {
    // 3 m above the surface looking straight down: T / n^2 times the in-scatter of the refracted ray,
    // lit down to max_depth = 6 m; 6 degrees over 7 pixels. The cone's far end: s_a + s_w / n.
    const Scene scene =
        godray_scene(R"({"position": [0, 3, 0], "direction": [0, -1, 0], "fov_y_deg": 6, "near": 0.01, "far": 100})",
                     medium(GetParam()), {"effects.godrays.grid=64"});
    expect_wide_tubes(scene, 3.0 + 6.0 / scene.water->ior);
    expect_centre_matches(render_godrays(context(), scene, kSize, kSize), scene);
}

INSTANTIATE_TEST_SUITE_P(Phase, godrays_flat, ::testing::Values("0", "0.9"), [](const auto& param_info) {
    return std::string(param_info.param) == "0" ? "isotropic" : "forward";
});

using godrays_flat_resolution = GpuTest;

TEST_F(godrays_flat_resolution, HalfResolutionUpsamplesTheSameField) {
    // The horizontal view at 14 x 14 gathered at 7 x 7: the output pixels take the bilinear mix of
    // the godray pixels around them (every tap sees the sky at the same distance, so none is left
    // out), which the expectation mixes the same way from the exact godray pixels; the mix adds 4 u.
    const Scene scene =
        godray_scene(R"({"position": [0, -2, 0], "direction": [-1, 0, 0], "fov_y_deg": 10, "near": 0.01, "far": 100})",
                     medium("0.9"), {"effects.godrays.grid=64", "effects.godrays.resolution_scale=0.5"});
    const RenderResult result = render_godrays(context(), scene, 2 * kSize, 2 * kSize);
    for (const int x : {6, 7}) {
        // Output pixel x samples the godray image at (x + 0.5) / 2 - 0.5: between pixels 2 and 3 or 3 and 4.
        const double c = (x + 0.5) / 2.0 - 0.5;
        const int base = static_cast<int>(std::floor(c));
        const double f = c - base;
        for (const int y : {6, 7}) {
            const double cy = (y + 0.5) / 2.0 - 0.5;
            const int base_y = static_cast<int>(std::floor(cy));
            const double fy = cy - base_y;
            auto godray = [&](int i, int j) { return expected_blurred(scene, kSize, kSize, i, j); };
            const glm::dvec3 expected = (1 - f) * (1 - fy) * godray(base, base_y) +
                                        f * (1 - fy) * godray(base + 1, base_y) +
                                        (1 - f) * fy * godray(base, base_y + 1) + f * fy * godray(base + 1, base_y + 1);
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_NEAR(result.image.pixel(x, y)[ch] / expected[ch], 1.0, kRounding + 4 * kUnit)
                    << "pixel " << x << "," << y << " channel " << ch;
            }
        }
    }
}

using godrays_marched = GpuTest;

// The marched baseline samples the sun's light at each step's middle and integrates the view's
// transmittance over the step exactly. Along a straight view path through uniform flat-water light
// E(s) = E0 exp(-a s), with view extinction exp(-b s), every step of length D then returns
//   E(s_mid) integral of exp(-b s) = exact * sinhc(b D / 2) / sinhc((a + b) D / 2),
// the same factor for every step: the baseline's error in closed form, which falls as D^2.
double sinhc(double y) { return y == 0.0 ? 1.0 : std::sinh(y) / y; }

TEST_F(godrays_marched, ErrorFallsWithItsStepCountAsTheMidpointRuleSays) {
    // Straight down from above: the refracted view ray's light decays at a = sigma_t / cos(theta_t),
    // its view path at b = sigma_t, over the lit 6 m down to max_depth.
    double previous = 1e300;
    for (const int steps : {1, 4, 16, 64}) {
        const Scene scene = godray_scene(
            R"({"position": [0, 3, 0], "direction": [0, -1, 0], "fov_y_deg": 6, "near": 0.01, "far": 100})",
            medium("0.9"), {"effects.godrays.method=marched", "effects.godrays.march_steps=" + std::to_string(steps)});
        const RenderResult result = render_godrays(context(), scene, kSize, kSize);
        const glm::dvec3 exact = expected_in_scatter(scene, pixel_ray(scene, kSize, kSize, kCentre, kCentre));
        const glm::dvec3 t = *ref::refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / scene.water->ior);
        const double step = 6.0 / steps;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double b = scene.medium.sigma_t()[c], a = b / -t.y;
            const double predicted = sinhc(0.5 * b * step) / sinhc(0.5 * (a + b) * step) - 1.0;
            const double measured = result.image.pixel(kCentre, kCentre)[c] / exact[c] - 1.0;
            // The march's own rounding: N steps of about 30 roundings each, with exp of optical
            // depths below 20 (4 x 20 u each): (30 + 80) u per step, summed.
            EXPECT_NEAR(measured, predicted, (30.0 + 80.0) * kUnit * steps + kRounding)
                << steps << " steps, channel " << c;
            worst = std::max(worst, std::abs(measured));
        }
        EXPECT_LT(worst, previous) << "the error did not fall from " << previous << " at " << steps << " steps";
        previous = worst;
    }
}

TEST_F(godrays_marched, HorizontalRayUnderWaterIsExactWithOneStep) {
    // Along a horizontal ray the light is uniform (a = 0): one step is exact, as the closed form above says.
    const Scene scene =
        godray_scene(R"({"position": [0, -2, 0], "direction": [-1, 0, 0], "fov_y_deg": 10, "near": 0.01, "far": 100})",
                     medium("0.9"), {"effects.godrays.method=marched", "effects.godrays.march_steps=1"});
    const RenderResult result = render_godrays(context(), scene, kSize, kSize);
    const glm::dvec3 exact = expected_in_scatter(scene, pixel_ray(scene, kSize, kSize, kCentre, kCentre));
    for (int c = 0; c < 3; ++c) {
        std::printf("channel %d: relative error %.3e\n", c, result.image.pixel(kCentre, kCentre)[c] / exact[c] - 1.0);
        EXPECT_NEAR(result.image.pixel(kCentre, kCentre)[c] / exact[c], 1.0, kRounding) << c;
    }
}

}  // namespace
}  // namespace vkw::test
