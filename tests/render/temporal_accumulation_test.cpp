// Temporal accumulation (passes/frame/temporal_accumulation.hpp), rendered on the device and read
// back: still frames without the clamp are exactly the running mean of the jittered frames, a
// stale history is clamped into this frame's neighbourhood, and the reprojection matrix takes a
// point's clip coordinates under one camera to those under the other.
#include "passes/frame/temporal_accumulation.hpp"
#include "engine/core/errors.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tests/support/builtin_scene.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/metrics/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

RenderOptions options(bool temporal) {
    RenderOptions o{kWidth, kHeight, true, fg::TimingMode::None};
    o.temporal.enabled = temporal;
    return o;
}

// The renderer's next temporal frame: the camera shifted by its jitter, as the callers do.
RenderResult temporal_frame(Renderer& renderer, Scene scene, const RenderOptions& temporal) {
    scene.camera.image_shift_ndc = renderer.next_temporal_shift(kWidth, kHeight);
    return renderer.render(scene, temporal);
}

// Frame `index` of a temporal sequence as the renderer renders it before the accumulation.
RenderResult jittered_frame(Renderer& renderer, Scene scene, uint32_t index) {
    scene.camera.image_shift_ndc = image_shift_for_pixel_offset(passes::temporal_jitter(index), kWidth, kHeight);
    return renderer.render(scene, options(false));
}

using TemporalAccumulation = GpuTest;

// Pool with its clock stopped and the camera still, the clamp off and no floor on the weights: 16
// frames are the running mean h_n = h_(n-1) + (c_n - h_(n-1)) / (n + 1) of the 16 jittered frames,
// which are the 16 strata of a 4 x 4 box filter. Each step rounds its difference, product, weight
// and sum once each, every term at most 2 M (M the largest |c| of the pixel): at most 7 M 2^-24 a
// step, carried on with a factor below 1, so 15 steps stay within 105 M 2^-24; asserted 128 M 2^-24.
TEST_F(TemporalAccumulation, StillFramesWithoutTheClampAreTheMeanOfTheirJitteredFrames) {
    const Scene scene = builtin_scene("pool.json");
    Renderer renderer(context());
    RenderOptions temporal = options(true);
    temporal.temporal.clamp_history = false;
    temporal.temporal.blend_floor = 0.0;
    RenderResult accumulated;
    for (uint32_t i = 0; i < passes::kTemporalJitterCycle; ++i) accumulated = temporal_frame(renderer, scene, temporal);
    EXPECT_EQ(renderer.temporal_frames(), passes::kTemporalJitterCycle);

    Renderer plain(context());
    std::vector<double> sum(accumulated.image.rgba.size(), 0.0), largest(accumulated.image.rgba.size(), 0.0);
    for (uint32_t i = 0; i < passes::kTemporalJitterCycle; ++i) {
        const RenderResult frame = jittered_frame(plain, scene, i);
        for (size_t k = 0; k < sum.size(); ++k) {
            sum[k] += frame.image.rgba[k];
            largest[k] = std::max(largest[k], std::abs(double(frame.image.rgba[k])));
        }
    }
    size_t outside = 0, differ_from_frame_0 = 0;
    const RenderResult first = jittered_frame(plain, scene, 0);
    for (size_t k = 0; k < sum.size(); ++k) {
        if (k % 4 == 3) continue;  // alpha
        const double mean = sum[k] / passes::kTemporalJitterCycle;
        if (!(std::abs(accumulated.image.rgba[k] - mean) <= 128.0 * largest[k] * 0x1p-24)) ++outside;
        if (first.image.rgba[k] != accumulated.image.rgba[k]) ++differ_from_frame_0;
    }
    EXPECT_EQ(outside, 0u);
    // The mean is not frame 0 itself: the jitter moved the pool's edges and caustics.
    EXPECT_GT(differ_from_frame_0, sum.size() / 8);
}

// The first frame of a sequence is its jittered frame as it is.
TEST_F(TemporalAccumulation, TheFirstFrameIsItsJitteredFrame) {
    const Scene scene = builtin_scene("calm.json");
    Renderer renderer(context());
    const RenderResult first = temporal_frame(renderer, scene, options(true));
    Renderer plain(context());
    EXPECT_EQ(first.image.rgba, jittered_frame(plain, scene, 0).image.rgba);
    // A camera without the next frame's jitter is the caller's mistake, refused.
    EXPECT_THROW(renderer.render(scene, options(true)), InternalError);
}

// Eight frames of calm with a grey floor, then one where the floor is nearly black: the history
// the scene no longer shows is clamped into the range of this frame's 3 x 3 neighbourhood, and a
// blend of two values in that range stays in it (to one rounding, 2^-23 relative). Without the
// clamp the old floor shows through.
TEST_F(TemporalAccumulation, AStaleHistoryIsClampedIntoTheNeighbourhood) {
    const Scene grey = builtin_scene("calm.json");
    const Scene dark = builtin_scene("calm.json", {"floor.albedo=[0.02, 0.02, 0.02]"});
    auto outside_neighbourhood = [&](bool clamp) {
        Renderer renderer(context());
        RenderOptions temporal = options(true);
        temporal.temporal.clamp_history = clamp;
        for (int i = 0; i < 8; ++i) temporal_frame(renderer, grey, temporal);
        const RenderResult accumulated = temporal_frame(renderer, dark, temporal);
        Renderer plain(context());
        const RenderResult current = jittered_frame(plain, dark, 8);
        size_t outside = 0;
        for (int y = 0; y < int(kHeight); ++y) {
            for (int x = 0; x < int(kWidth); ++x) {
                for (int c = 0; c < 3; ++c) {
                    float lowest = current.image.pixel(x, y)[c], highest = lowest;
                    for (int dy = -1; dy <= 1; ++dy) {
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int u = std::clamp(x + dx, 0, int(kWidth) - 1);
                            const int v = std::clamp(y + dy, 0, int(kHeight) - 1);
                            lowest = std::min(lowest, current.image.pixel(u, v)[c]);
                            highest = std::max(highest, current.image.pixel(u, v)[c]);
                        }
                    }
                    const float value = accumulated.image.pixel(x, y)[c];
                    const float slack = 0x1p-23f * std::max(std::abs(lowest), std::abs(highest));
                    if (value < lowest - slack || value > highest + slack) ++outside;
                }
            }
        }
        return outside;
    };
    EXPECT_EQ(outside_neighbourhood(true), 0u);
    EXPECT_GT(outside_neighbourhood(false), size_t{kWidth} * kHeight / 4);  // the floor's pixels, at least
}

// The history follows a moving camera: pool with its clock stopped, the camera turning to pan its
// image by about 2.5 pixels a frame over 12 frames, accumulated without the clamp (which would hide
// a history read from the wrong place). At the end pose the accumulated frame must be nearer the
// 16-sample box filter there than the point-sampled frame is. Measured at 64x48: relMSE 0.059
// against 0.119; with each pixel's own history instead of the reprojected one, the smear of the
// pan takes it to 0.225, and the test fails.
TEST_F(TemporalAccumulation, TheHistoryFollowsAMovingCamera) {
    Scene scene = builtin_scene("pool.json");  // its sharp caustics: a smeared history shows
    scene.camera.position = {0.0, 1.2, 4.0};
    const glm::dvec3 start{-1.0, -1.5, -2.0}, end{1.0, -1.5, -2.0};
    RenderOptions temporal = options(true);
    temporal.temporal.clamp_history = false;
    Renderer renderer(context());
    RenderResult accumulated;
    constexpr int kSteps = 12;
    for (int i = 0; i <= kSteps; ++i) {
        scene.camera.target = start + (end - start) * (double(i) / kSteps);
        accumulated = temporal_frame(renderer, scene, temporal);
    }
    Renderer plain(context());
    const RenderResult point = plain.render(scene, options(false));
    const RenderResult box = render_filtered(plain, scene, options(false), pixel_filter_from_spp(16));
    const auto pixels = metrics::counted_pixels(kWidth, kHeight, nullptr);
    const double temporal_error =
        metrics::rel_mse(metrics::rgb_view(accumulated.image), metrics::rgb_view(box.image), pixels);
    const double point_error = metrics::rel_mse(metrics::rgb_view(point.image), metrics::rgb_view(box.image), pixels);
    std::printf("against the box-filtered frame: temporal %.4g, point-sampled %.4g\n", temporal_error, point_error);
    EXPECT_LT(temporal_error, point_error);
}

// A world point's clip coordinates under this frame's camera, through the reprojection, are its
// clip coordinates under the previous camera (to double rounding).
TEST(TemporalReprojection, TakesAPointToWhereThePreviousCameraSawIt) {
    Camera previous, current;
    previous.position = {0.0, 2.0, 5.0};
    previous.target = {0.0, 0.0, 0.0};
    current.position = {0.3, 1.8, 5.2};
    current.target = {0.1, 0.0, -0.2};
    const double aspect = 4.0 / 3.0;
    const glm::dmat4 before = projection_matrix(previous, aspect) * view_matrix(previous);
    const glm::dmat4 now = projection_matrix(current, aspect) * view_matrix(current);
    const glm::dmat4 reprojection = passes::temporal_reprojection(before, now);
    for (const glm::dvec3 point :
         {glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(1.0, -0.5, -3.0), glm::dvec3(-2.0, 0.3, 1.0)}) {
        const glm::dvec4 clip_now = now * glm::dvec4(point, 1.0);
        const glm::dvec4 expected = before * glm::dvec4(point, 1.0);
        const glm::dvec4 moved = reprojection * (clip_now / clip_now.w);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(moved[i] / moved.w, expected[i] / expected.w, 1e-12);
    }
}

TEST(TemporalJitter, VisitsEachStratumOfTheBoxFilterOncePerCycle) {
    const PixelFilter box = pixel_filter_from_spp(passes::kTemporalJitterCycle);
    std::vector<int> visits(passes::kTemporalJitterCycle, 0);
    for (uint32_t f = 0; f < passes::kTemporalJitterCycle; ++f) {
        const glm::dvec2 offset = passes::temporal_jitter(f);
        EXPECT_EQ(offset, passes::temporal_jitter(f + passes::kTemporalJitterCycle));
        for (uint32_t i = 0; i < passes::kTemporalJitterCycle; ++i) visits[i] += offset == box.stratum_centre(i);
    }
    for (int v : visits) EXPECT_EQ(v, 1);
    // Frames 4j to 4j + 3 hold one offset in each quarter of the pixel.
    for (uint32_t j = 0; j < 4; ++j) {
        int quarters = 0;
        for (uint32_t f = 4 * j; f < 4 * j + 4; ++f) {
            const glm::dvec2 o = passes::temporal_jitter(f);
            quarters |= 1 << ((o.x > 0.0 ? 1 : 0) + (o.y > 0.0 ? 2 : 0));
        }
        EXPECT_EQ(quarters, 15) << "frames " << 4 * j << " to " << 4 * j + 3;
    }
}

}  // namespace
}  // namespace vkw::test
