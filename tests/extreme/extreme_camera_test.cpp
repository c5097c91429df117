// The camera at the edges: on the water plane and 1e-6 m above and below it, a
// 30-frame path through the surface (discontinuous by design: exempt from the continuity test,
// checked for flicker instead), and under the water looking along the sun's refracted beam, where
// the single-scattering closed form reaches its 1 + c = 0 limit (docs/model.md section 6).
#include "passes/frame/frame_needs.hpp"
#include "tests/extreme/extreme_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <algorithm>

namespace vkw::test {
namespace {

// Looking north and 20 degrees down from height y: the frame holds the surface's both sides.
std::string camera_at_height(double y) {
    char text[96];
    std::snprintf(text, sizeof text, "camera.position=[0, %.17g, 1]", y);
    return text;
}
const std::vector<std::string> kLookingAcross = {"camera.target=null", "camera.direction=[0, -0.342, -0.940]"};

class extreme_camera_height : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(extreme_camera_height, OnAndNextToTheWaterPlaneStable) {
    // No closed form: the real-time renderer takes each pixel's medium at its ray's near-plane
    // point (the camera-medium split), the reference at the eye, so within a near-plane distance (5 cm)
    // of the surface they differ by design.
    const double y = GetParam();
    Renderer renderer(context());
    expect_stable(context(), renderer, extreme_scene(joined(kLookingAcross, {camera_at_height(y)})),
                  "camera at y = " + std::to_string(y) + " m, flat water");
    expect_stable(context(), renderer, extreme_scene(joined(kLookingAcross, {camera_at_height(y), sine_waves(0.3)})),
                  "camera at y = " + std::to_string(y) + " m, sine of slope 0.3");
}

INSTANTIATE_TEST_SUITE_P(Height, extreme_camera_height, ::testing::Values(0.0, 1e-6, -1e-6),
                         [](const auto& param_info) {
                             return param_info.param == 0.0 ? std::string("on_the_plane")
                                    : param_info.param > 0  ? "one_micron_above"
                                                            : "one_micron_below";
                         });

// The frames of a path that cross the surface: those whose near-plane rectangle or eye reaches
// into the slab of the waves (|y - level| <= A). The real-time renderer takes each pixel's medium
// at its near-plane point, the reference at the eye: over these frames the view changes from the
// air's to the water's, discontinuous by design, so they are exempt from the continuity test.
bool crosses_the_surface(const Scene& scene) {
    const Water& water = *scene.water;
    const double a = make_surface(water.waves, water.level, water.time)->max_amplitude();
    double lo = scene.camera.position.y, hi = lo;
    for (const glm::dvec3& corner : near_plane_corners(scene.camera, double(kExtremeWidth) / kExtremeHeight)) {
        lo = std::min(lo, corner.y);
        hi = std::max(hi, corner.y);
    }
    return lo <= water.level + a && hi >= water.level - a;
}

// No flicker: each frame's mean radiance lies within its neighbours' range widened by a band, a
// fraction of their mean. Away from the crossing, 2%: the camera moves 1 cm a frame, which moves
// the mean by under 1% a frame (measured), and a smooth sequence leaves its neighbours' range by
// its curvature only, far less. Across the crossing, 25%: a frame whose whole view took the other
// medium alone (the per-frame flag of docs/model.md section 8) would swing by the difference between
// the views above and below, a factor of 2 here (0.263 and 0.125 on flat water), while the
// composition changes as the near plane cuts through the waves moved one frame 10% (measured) out
// of its neighbours' range. A step, the crossing itself, stays inside the middle frame's range.
constexpr double kSmoothBand = 0.02, kCrossingBand = 0.25;

void expect_no_flicker(const std::vector<double>& means, const std::vector<bool>& crossing, const std::string& what) {
    for (size_t i = 1; i + 1 < means.size(); ++i) {
        const double lo = std::min(means[i - 1], means[i + 1]), hi = std::max(means[i - 1], means[i + 1]);
        const double band = (crossing[i] ? kCrossingBand : kSmoothBand) * 0.5 * (means[i - 1] + means[i + 1]);
        EXPECT_GE(means[i], lo - band) << what << " frame " << i;
        EXPECT_LE(means[i], hi + band) << what << " frame " << i;
    }
}

using extreme_camera_path = GpuTest;

TEST_F(extreme_camera_path, ThirtyFramesThroughTheSurfaceWithoutFlicker) {
    // y from +0.145 m to -0.145 m in steps of 1 cm: frames 14 and 15 lie 5 mm either side of the
    // plane. Real time over the sine (its split follows the waves), the reference over flat water
    // (its floor is closed form there; a wavy reference frame costs a caustic map each).
    Renderer renderer(context());
    std::vector<double> real_time, reference;
    std::vector<bool> rt_crossing, ref_crossing;
    for (int frame = 0; frame < 30; ++frame) {
        const double y = 0.145 - 0.01 * frame;
        const std::string what = "path frame " + std::to_string(frame) + " (y = " + std::to_string(y) + " m)";
        const Scene wavy = extreme_scene(joined(kLookingAcross, {camera_at_height(y), sine_waves(0.3)}));
        const Scene flat = extreme_scene(joined(kLookingAcross, {camera_at_height(y)}));
        const ImageRGBA32F rt = render_real_time(renderer, wavy);
        expect_finite_non_negative(rt, what + ", real time");
        real_time.push_back(mean_radiance(rt));
        rt_crossing.push_back(crosses_the_surface(wavy));
        const ImageRGBA32F ref = render_reference(flat);
        expect_finite_non_negative(ref, what + ", reference");
        reference.push_back(mean_radiance(ref));
        ref_crossing.push_back(crosses_the_surface(flat));
        std::printf("frame %2d (y %+.3f m): mean real time %.5f%s, reference %.5f%s\n", frame, y, real_time.back(),
                    rt_crossing.back() ? " (crossing)" : "", reference.back(),
                    ref_crossing.back() ? " (crossing)" : "");
    }
    expect_no_flicker(real_time, rt_crossing, "real time");
    expect_no_flicker(reference, ref_crossing, "reference");
}

using extreme_camera = GpuTest;

TEST_F(extreme_camera, UnderwaterLookingAlongTheBeamsTowardTheSunMatchesTheClosedForm) {
    // The camera 0.5 m down looks along -t, the refracted sun's direction reversed: at the centre
    // of the frame c = -1, so 1 + c = 0 and the in-scatter takes its (1 - exp(-x)) / x -> 1 limit;
    // the Henyey-Greenstein peak (g = 0.9) lies there too. Sun 60 degrees from the zenith: t makes
    // asin(sin 60 / 1.333) = 40.5 degrees with the vertical, inside Snell's window, so the sun's
    // disk is seen through it. Godrays are off (flat water: the analytic in-scatter is exact), so
    // the singular godray term of docs/model.md section 6 does not arise here. The wide pool: the
    // lower rows see the floor by total internal reflection up to 4.4 m south.
    const double sin_t = std::sin(60.0 * 3.14159265358979323846 / 180.0) / 1.333;
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    char direction[96];
    std::snprintf(direction, sizeof direction, "camera.direction=[0, %.17g, %.17g]", cos_t,
                  sin_t);  // toward the sun (south, up)
    Renderer renderer(context());
    const CaseImages images = expect_stable(
        context(), renderer,
        extreme_scene(joined(kWidePool, {"camera.position=[0, -0.5, -0.5]", "camera.target=null", direction})),
        "under the water looking along the beams toward the sun");
    expect_closed_form(images, "looking along the beams");
}

}  // namespace
}  // namespace vkw::test
