// The sun's glitter seen from the water, in a whole frame (docs/model.md section 1, "Sun glitter"):
// under waves that are all finer than a pixel's footprint, the refracted sun is the transmission
// lobe of their slopes, and the frame's pixels, each weighted by its solid angle and by the cosine
// of its ray to the vertical, add up to the flux the facets let through: the integral over the
// slopes of T(l.h) (l.h) / h_y p(z) (tests/optics/glitter_facets.hpp). The frame is black but for
// the sun: a black sky, a black floor, water that neither absorbs nor scatters.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/optics/glitter_facets.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr double kFovDeg = 24.0;
// Two perpendicular sines 2 cm long of slope amplitude A k = 0.1 each: a slope variance of
// (A k)^2 / 2 = 0.005 along x and along z.
constexpr double kWavelength = 0.02, kSlopeAmplitude = 0.1;
constexpr double kSlopeVariance = 0.5 * kSlopeAmplitude * kSlopeAmplitude;

Scene glitter_scene(bool glitter) {
    const double amplitude = kSlopeAmplitude * kWavelength / (2.0 * std::numbers::pi);
    const std::string wave = "{\"amplitude\": " + std::to_string(amplitude) +
                             ", \"wavelength\": " + std::to_string(kWavelength) + ", \"direction_deg\": ";
    const std::string json = R"({
      "camera": {"position": [0, -20, 0], "direction": [0, 1, 0], "fov_y_deg": 24, "near": 0.05, "far": 500},
      "sun": {"elevation_deg": 45, "azimuth_deg": 0, "irradiance": [1, 1, 1]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -40, "albedo": [0, 0, 0], "half_extent": 200},
      "water": {"level": 0, "ior": 1.333, "half_extent": 100, "grid_resolution": 64,
                "waves": {"model": "sum", "components": [)" +
                             wave + "0, \"phase_deg\": 0}, " + wave + R"(90, "phase_deg": 90}]}},
      "medium": {"sigma_a": [0, 0, 0], "sigma_s": [0, 0, 0]},
      "effects": {"water": {"glitter": )" +
                             (glitter ? "true" : "false") + "}}}";
    Scene scene = parse_scene(json, "glitter.json", {});
    // Looking up along the sun's light as the level surface refracts it, at its image.
    const glm::dvec3 to_sun = -scene.sun.direction;
    scene.camera.target = scene.camera.position - refracted(to_sun, {0.0, 1.0, 0.0}, kGlitterIor);
    return scene;
}

// The sum over the pixels of green radiance times the pixel's solid angle times |o_y|: the integral
// of L |o_y| over the directions the frame covers.
double weighted_sum(const Scene& scene, const ImageRGBA32F& image) {
    const glm::dvec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    const double side = 2.0 * std::tan(0.5 * kFovDeg * std::numbers::pi / 180.0) / kSize;  // at unit distance
    double sum = 0.0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::dvec3 d = ref::camera_ray(scene.camera, kSize, kSize, x + 0.5, y + 0.5).direction;
            const double cosine = glm::dot(d, forward);
            sum += image.rgba[4 * (size_t(y) * kSize + x) + 1] * side * side * cosine * cosine * cosine * d.y;
        }
    }
    return sum;
}

using GlitterFrame = GpuTest;

// The lobe's light against the flux, within 1e-3 relative. The parts of that bound: the pixels'
// sum over a lobe whose angular spread, (1 - k) sigma = 0.027 rad at k = 0.625, spans 4 pixels of
// 0.0065 rad per standard deviation (a midpoint rule's error far below 1e-4 on a Gaussian), and
// the frame's edge 8 of them from its centre; the waves' share left resolved, sinc^2(k w / 2) below
// 2e-3 for footprints w of 17 cm or more, which moves the lobe's mean slope by at most 3e-4 and
// its covariance by 2e-3 of itself, changing the flux at second order; the sun's disk, 3e-5 in slope
// variance; Smith's visibility, 1 to 1e-17 at 45 degrees and sigma 0.07; fp32 per pixel, 1e-6.
TEST_F(GlitterFrame, TheRefractedSunsLobeCarriesTheFluxTheFacetsLetThrough) {
    Renderer renderer(context());
    const Scene scene = glitter_scene(true);
    const RenderResult on = renderer.render(scene, {kSize, kSize, true, fg::TimingMode::None});
    const double expected =
        facet_flux(-scene.sun.direction, {0.0, 0.0}, {kSlopeVariance, 0.0, kSlopeVariance}, Lobe::Transmitted);
    EXPECT_NEAR(weighted_sum(scene, on.image), expected, 1e-3 * expected);
    // Without the glitter the sun's image, 1.4e-5 sr of the frame's 0.17 sr spread over it, is met
    // only where a pixel's centre ray happens to refract onto its disk: not the flux.
    const Scene disk = glitter_scene(false);
    const RenderResult off = renderer.render(disk, {kSize, kSize, true, fg::TimingMode::None});
    EXPECT_GT(std::abs(weighted_sum(disk, off.image) / expected - 1.0), 0.1);
}

}  // namespace
}  // namespace vkw::test
