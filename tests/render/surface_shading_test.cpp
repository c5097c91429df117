// The surface's alternative shading (effects.water; Optical Phenomena c. 2008 sections 5-7) against closed forms:
// a camera 3 m above flat water over a black floor, the sun below the horizon and a medium that
// only absorbs, so that a pixel of the surface is R L_sky plus, with Optical Phenomena c. 2008's depth colour,
// T C_w (1 - exp(-k d)) / n^2 (d: the refracted ray's path to the floor); without it the refracted
// ray brings nothing. R is Optical Phenomena c. 2008's power term (1 - E.N)^q, Schlick's approximation or the exact
// form, evaluated here in double from the pixel's own ray (flat water: the normal is +y).
#include "engine/core/errors.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 48, kHeight = 36;
constexpr double kIor = 1.333, kSky = 0.5, kDepth = 2.0;
constexpr double kPower = 4.5, kBlendK = 0.5;
const glm::dvec3 kWaterColour(0.0, 0.2, 0.1);

Scene surface_scene(const std::vector<std::string>& overrides) {
    const char* json = R"({
      "camera": {"position": [0, 3, 3], "direction": [0, -1, -1], "fov_y_deg": 60},
      "sun": {"elevation_deg": -10, "azimuth_deg": 0, "irradiance": [1, 1, 1]},
      "sky": {"radiance": [0.5, 0.5, 0.5]},
      "floor": {"height": -2, "albedo": [0, 0, 0], "half_extent": 40},
      "water": {"level": 0, "ior": 1.333, "half_extent": 40, "grid_resolution": 16, "waves": {"model": "flat"}},
      "medium": {"sigma_a": [0.1, 0.1, 0.1], "sigma_s": [0, 0, 0]}
    })";
    return parse_scene(json, "surface.json", overrides);
}

// The worst relative difference between the image and `expected(cos_i, d)` (radiance per channel)
// over the pixels whose ray meets the water within its square, and how many.
struct Result {
    double worst = 0.0;
    int pixels = 0;
    double worst_cos_i = 0.0;  // where the worst difference is, for the failure message
    uint32_t worst_x = 0, worst_y = 0;
};
Result compare(const Scene& scene, const ImageRGBA32F& image,
               const std::function<glm::dvec3(double cos_i, double path)>& expected) {
    Result result;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const ref::Ray ray = ref::camera_ray(scene.camera, kWidth, kHeight, x + 0.5, y + 0.5);
            if (!(ray.direction.y < -0.05)) continue;  // the surface only, well away from the horizon
            const double cos_i = -ray.direction.y;
            const double sin_t = std::sqrt(1.0 - cos_i * cos_i) / kIor;
            const double path = kDepth / std::sqrt(1.0 - sin_t * sin_t);
            const glm::dvec3 want = expected(cos_i, path);
            const float* got = &image.rgba[4 * (size_t(y) * kWidth + x)];
            for (int c = 0; c < 3; ++c) {
                if (want[c] <= 0.0) continue;
                const double difference = std::abs(got[c] / want[c] - 1.0);
                if (difference > result.worst) result = {difference, result.pixels, cos_i, x, y};
            }
            ++result.pixels;
        }
    }
    return result;
}

double exact_reflectance(double cos_i) {
    const double sin_t = std::sqrt(1.0 - cos_i * cos_i) / kIor;
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    const double rs = (cos_i - kIor * cos_t) / (cos_i + kIor * cos_t);
    const double rp = (kIor * cos_i - cos_t) / (kIor * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// The shader's chain is a handful of fp32 operations (the pixel's ray, a cosine, pow or the
// Fresnel equations, exp) on fp32-rounded constants: each within a few units of 2^-24 relative,
// except the cosine near grazing, where R's slope amplifies it; pixels stay 3 degrees above the
// horizon, where dR/dcos / R < 20 and the cosine of a pixel's rasterised position differs from
// the centre ray's by 1e-6: 1e-4 holds the chain.
constexpr double kChainTolerance = 1e-4;

using SurfaceShading = GpuTest;

TEST_F(SurfaceShading, ExactFresnelReflectsTheSky) {
    const Scene scene = surface_scene({});
    Renderer renderer(context());
    const RenderResult rendered = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const Result r =
        compare(scene, rendered.image, [](double c, double) { return glm::dvec3(kSky * exact_reflectance(c)); });
    std::printf("exact: %d pixels, worst %.2e at (%u, %u), cos_i %.4f\n", r.pixels, r.worst, r.worst_x, r.worst_y,
                r.worst_cos_i);
    EXPECT_GT(r.pixels, int(kWidth * kHeight) / 2);
    EXPECT_LE(r.worst, kChainTolerance);
}

TEST_F(SurfaceShading, Seed001PowerTermFresnel) {
    const Scene scene = surface_scene({"effects.water.fresnel=power"});
    Renderer renderer(context());
    const RenderResult rendered = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const Result r =
        compare(scene, rendered.image, [](double c, double) { return glm::dvec3(kSky * std::pow(1.0 - c, kPower)); });
    std::printf("power term q = 4.5: %d pixels, worst %.2e at (%u, %u), cos_i %.4f\n", r.pixels, r.worst, r.worst_x,
                r.worst_y, r.worst_cos_i);
    EXPECT_GT(r.pixels, int(kWidth * kHeight) / 2);
    EXPECT_LE(r.worst, kChainTolerance);
}

TEST_F(SurfaceShading, SchlickFresnel) {
    const Scene scene = surface_scene({"effects.water.fresnel=schlick"});
    Renderer renderer(context());
    const RenderResult rendered = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const double r0 = std::pow((kIor - 1.0) / (kIor + 1.0), 2.0);
    const Result r = compare(scene, rendered.image, [r0](double c, double) {
        return glm::dvec3(kSky * (r0 + (1.0 - r0) * std::pow(1.0 - c, 5.0)));
    });
    std::printf("Schlick: %d pixels, worst %.2e at (%u, %u), cos_i %.4f\n", r.pixels, r.worst, r.worst_x, r.worst_y,
                r.worst_cos_i);
    EXPECT_LE(r.worst, kChainTolerance);
}

TEST_F(SurfaceShading, Seed001DepthColourBlend) {
    const Scene scene = surface_scene({"effects.water.fresnel=power", "effects.water.depth_blend={}"});
    Renderer renderer(context());
    const RenderResult rendered = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const Result r = compare(scene, rendered.image, [](double c, double path) {
        const double R = std::pow(1.0 - c, kPower);
        // The black floor fades to C_w over the path; T and the n^2 of the radiance crossing the surface.
        return glm::dvec3(kSky * R) + (1.0 - R) * kWaterColour * (1.0 - std::exp(-kBlendK * path)) / (kIor * kIor);
    });
    std::printf("power term + depth colour: %d pixels, worst %.2e at (%u, %u), cos_i %.4f\n", r.pixels, r.worst,
                r.worst_x, r.worst_y, r.worst_cos_i);
    EXPECT_GT(r.pixels, int(kWidth * kHeight) / 2);
    EXPECT_LE(r.worst, kChainTolerance);
}

TEST(SurfaceShadingSchema, FieldsAndRanges) {
    const Scene scene = surface_scene({"effects.water.fresnel=power", "effects.water.fresnel_power=3",
                                       "effects.water.depth_blend={\"colour\": [0.1, 0.2, 0.3], \"k\": 2}"});
    EXPECT_EQ(scene.effects.water.fresnel, SurfaceFresnel::Power);
    EXPECT_EQ(scene.effects.water.fresnel_power, 3.0);
    ASSERT_TRUE(scene.effects.water.depth_blend.has_value());
    EXPECT_EQ(scene.effects.water.depth_blend->k, 2.0);
    EXPECT_FALSE(surface_scene({}).effects.water.depth_blend.has_value());
    EXPECT_THROW(surface_scene({"effects.water.fresnel=fast"}), UserError);
    EXPECT_THROW(surface_scene({"effects.water.fresnel_power=0.5"}), UserError);
    EXPECT_THROW(surface_scene({"effects.water.depth_blend={\"kk\": 1}"}), UserError);
    EXPECT_FALSE(surface_scene({}).effects.water.glitter);
    EXPECT_TRUE(surface_scene({"effects.water.glitter=true"}).effects.water.glitter);
    EXPECT_THROW(surface_scene({"effects.water.glitter=1"}), UserError);
}

// Flat water has no slopes to leave unresolved (engine/water/unresolved_slopes.hpp): the glitter
// keeps the sun's disk there, and the image is the one without it, bit for bit. This scene's
// closed-form tests above hold with the glitter on as they do off.
TEST_F(SurfaceShading, GlitterLeavesFlatWaterAsItIs) {
    Renderer renderer(context());
    const RenderResult off = renderer.render(surface_scene({}), {kWidth, kHeight, true, fg::TimingMode::None});
    const RenderResult on =
        renderer.render(surface_scene({"effects.water.glitter=true"}), {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_EQ(on.image.rgba, off.image.rgba);
}

}  // namespace
}  // namespace vkw::test
