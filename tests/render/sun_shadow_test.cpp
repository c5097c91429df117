// The sun shadow map (passes/receivers/sun_shadow.hpp): a 2 m box standing on a floor with no water,
// the sun 60 degrees high toward +x. Closed forms of the model (docs/model.md section 1), at the
// pixels that see chosen world points (projected with the frame's own view_proj):
// - a floor point inside the box's shadow gets skylight only: L = rho pi L_sky / pi;
// - a floor point far outside it gets sun and sky: L = rho (E_s sin(60) + pi L_sky) / pi;
// - the box top, the occluder nearest the sun, is not shadowed by itself (the bias works);
// - under clear water, a box above it shadows the floor's stand-in sun along the refracted beam;
// - under clear water, a slab under the water shadows the floor along the refracted beam, with
//   the stand-in and with the caustic map.
#include "engine/scene/scene_loader.hpp"
#include "passes/common/frame_constants.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/optics.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace vkw::test {
namespace {

using SunShadow = GpuTest;

constexpr uint32_t kSize = 64;

// The pixel whose footprint contains world point p (the viewport flips y: row 0 is the top).
const float* pixel_seeing(const RenderResult& result, const FrameConstants& constants, const glm::dvec3& p) {
    const glm::vec4 clip = constants.view_proj * glm::vec4(glm::vec3(p), 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const int x = static_cast<int>(std::floor((0.5f + 0.5f * ndc.x) * float(kSize)));
    const int y = static_cast<int>(std::floor((0.5f - 0.5f * ndc.y) * float(kSize)));
    return result.image.pixel(x, y);
}

// The floor's radiance under clear flat water (sigma = 0, docs/model.md section 3), channel c:
// in a shadow (skylight through T_hemi only) and lit (plus the sun E_s cos(theta_s) T).
struct ClearWaterFloor {
    double shadowed, lit;
};
ClearWaterFloor clear_water_floor(const Scene& scene, int c) {
    const double cos_s = -scene.sun.direction.y;
    const double transmittance = 1.0 - ref::fresnel_reflectance(cos_s, 1.0, scene.water->ior);
    const double rho = scene.floor.albedo[c];
    const double sky = std::numbers::pi * scene.sky.radiance[c] * ref::hemispherical_transmittance(scene.water->ior);
    const double sun = scene.sun.irradiance[c] * cos_s * transmittance;
    return {rho * sky / std::numbers::pi, rho * (sun + sky) / std::numbers::pi};
}

TEST_F(SunShadow, BoxShadowsTheFloorAndNotItself) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 20, 0.001], "target": [0, 0, 0], "fov_y_deg": 30},
      "sun": {"elevation_deg": 60, "azimuth_deg": 90, "irradiance": [2, 3, 4]},
      "sky": {"radiance": [0.2, 0.3, 0.4]},
      "floor": {"height": 0, "half_extent": 10, "albedo": [0.6, 0.5, 0.4]},
      "receivers": [{"type": "box", "half_size": [1, 1, 1], "translation": [0, 1, 0], "albedo": [0.7, 0.5, 0.3]}]
    })",
                                    "shadow.json");
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {kSize, kSize, true, fg::TimingMode::None});
    const FrameConstants constants = make_frame_constants(scene, kSize, kSize);
    // The top edge (y = 2) casts to x = -1 - 2 / tan(60) = -2.15 m: the shadow spans x in
    // [-2.15, -1], z in [-1, 1] on the floor. Its middle is more than a pixel (0.17 m) from every edge.
    const float* shadowed = pixel_seeing(result, constants, {-1.58, 0.0, 0.0});
    const float* lit_floor = pixel_seeing(result, constants, {3.0, 0.0, 3.0});
    const float* box_top = pixel_seeing(result, constants, {0.3, 2.0, 0.2});
    const double cos_sun = -scene.sun.direction.y;
    ASSERT_NEAR(cos_sun, std::sqrt(3.0) / 2.0, 1e-12);
    for (int c = 0; c < 3; ++c) {
        const double sky = std::numbers::pi * scene.sky.radiance[c];
        const double sun = scene.sun.irradiance[c] * cos_sun;
        const double floor_rho = scene.floor.albedo[c], box_rho = scene.receivers[0].albedo[c];
        const double expected_shadowed = floor_rho * sky / std::numbers::pi;
        const double expected_lit = floor_rho * (sun + sky) / std::numbers::pi;
        const double expected_top = box_rho * (sun + sky) / std::numbers::pi;
        // As in receivers_test: ~10 fp32 roundings of the inputs and the shading, plus the
        // interpolated normal's renormalisation: 2e-6 relative. The visibility is exactly 0 or 1.
        EXPECT_NEAR(shadowed[c], expected_shadowed, 2e-6 * expected_shadowed) << "channel " << c;
        EXPECT_NEAR(lit_floor[c], expected_lit, 2e-6 * expected_lit) << "channel " << c;
        EXPECT_NEAR(box_top[c], expected_top, 2e-6 * expected_top) << "channel " << c;
    }
}

TEST_F(SunShadow, ObjectsAboveTheWaterShadowTheSunAlongTheRefractedBeam) {
    // A box floating above clear water (sigma = 0), the sun 60 degrees high toward +x, the camera
    // under the water looking down; the floor lit by the flat stand-in (caustics off) or by the
    // caustic photons (on), which the box stops before they enter the water.
    // The refracted beam t = (-0.375, -0.927, 0) enters the surface 0.809 m toward +x of a
    // floor point 2 m down; the box (y from 1 to 3) shadows the surface for x in
    // [-2.73, 0.42]. Floor x = -1.96 enters at x = -1.15: shadowed; floor x = 2.5 enters
    // at 3.31: lit. Both are more than a metre from every shadow edge.
    for (const char* caustics : {"off", "on"}) {
        const Scene scene = parse_scene(R"({
          "camera": {"position": [0, -0.1, 0.001], "target": [0, -2, 0], "fov_y_deg": 120},
          "sun": {"elevation_deg": 60, "azimuth_deg": 90, "irradiance": [2, 3, 4]},
          "sky": {"radiance": [0.2, 0.3, 0.4]},
          "floor": {"height": -2, "half_extent": 10, "albedo": [0.6, 0.5, 0.4]},
          "water": {"level": 0, "half_extent": 10},
          "medium": {"sigma_a": [0, 0, 0], "sigma_s": [0, 0, 0], "g": 0},
          "effects": {"caustics": {"mode": ")" +
                                            std::string(caustics) + R"("}},
          "receivers": [{"type": "box", "half_size": [1, 1, 1], "translation": [0, 2, 0]}]
        })",
                                        "shadow_under_water.json");
        Renderer renderer(context());
        const RenderResult result = renderer.render(scene, {kSize, kSize, true, fg::TimingMode::None});
        const FrameConstants constants = make_frame_constants(scene, kSize, kSize);
        const float* shadowed = pixel_seeing(result, constants, {-1.96, -2.0, 0.0});
        const float* lit = pixel_seeing(result, constants, {2.5, -2.0, 0.0});
        for (int c = 0; c < 3; ++c) {
            const ClearWaterFloor expected = clear_water_floor(scene, c);
            // fp32 shading as above, and T_hemi by 16-point Gauss-Legendre in fp32 (1e-6): 1e-5.
            // Shadowed: the sun term is an exact 0 (no photon entered there, or the stand-in's
            // visibility is 0).
            EXPECT_NEAR(shadowed[c], expected.shadowed, 1e-5 * expected.shadowed)
                << "caustics " << caustics << ", channel " << c;
            if (std::string(caustics) == "off") {
                EXPECT_NEAR(lit[c], expected.lit, 1e-5 * expected.lit) << c;
            }
        }
    }
}

TEST_F(SunShadow, ObjectsUnderTheWaterShadowAlongTheRefractedBeam) {
    // A slab under clear water (y from -1.25 to -0.75, x and z in [-1, 1]), the sun 60 degrees
    // high toward +x: the refracted beam t = (-0.375, -0.927, 0) carries the slab's shadow
    // 0.404 m toward -x per metre of depth, so on the floor (y = -2) it spans x in
    // [-1 - 1.25 * 0.404, 1 - 0.75 * 0.404] = [-1.51, 0.70], z in [-1, 1]. The camera lies
    // under the slab's level and looks along z at floor points under it: x = -0.4 (0.9 m inside
    // every edge) is shadowed, x = 3 is lit. Where their beams enter the surface nothing
    // stands above the water, so only the map's beam half can shadow them. The pixel
    // footprint at that grazing view is 0.33 m along z and 0.03 m along x: inside the shadow.
    for (const char* caustics : {"off", "on"}) {
        const auto scene_looking_at = [&](double x) {
            return parse_scene(R"({
              "camera": {"position": [)" +
                                   std::to_string(x) + R"(, -1.6, 4], "target": [)" + std::to_string(x) +
                                   R"(, -2, 0], "fov_y_deg": 30},
              "sun": {"elevation_deg": 60, "azimuth_deg": 90, "irradiance": [2, 3, 4]},
              "sky": {"radiance": [0.2, 0.3, 0.4]},
              "floor": {"height": -2, "half_extent": 10, "albedo": [0.6, 0.5, 0.4]},
              "water": {"level": 0, "half_extent": 10},
              "medium": {"sigma_a": [0, 0, 0], "sigma_s": [0, 0, 0], "g": 0},
              "effects": {"caustics": {"mode": ")" +
                                   std::string(caustics) + R"("}},
              "receivers": [{"type": "box", "half_size": [1, 0.25, 1], "translation": [0, -1, 0]}]
            })",
                               "slab_under_water.json");
        };
        Renderer renderer(context());
        const Scene shadowed_scene = scene_looking_at(-0.4);
        const RenderResult shadowed_image = renderer.render(shadowed_scene, {kSize, kSize, true, fg::TimingMode::None});
        const float* shadowed =
            pixel_seeing(shadowed_image, make_frame_constants(shadowed_scene, kSize, kSize), {-0.4, -2.0, 0.0});
        const Scene lit_scene = scene_looking_at(3.0);
        const RenderResult lit_image = renderer.render(lit_scene, {kSize, kSize, true, fg::TimingMode::None});
        const float* lit = pixel_seeing(lit_image, make_frame_constants(lit_scene, kSize, kSize), {3.0, -2.0, 0.0});
        for (int c = 0; c < 3; ++c) {
            const ClearWaterFloor expected = clear_water_floor(shadowed_scene, c);
            // Shadowed: the sun term is multiplied by an exact 0, whatever computed it (the
            // stand-in or the caustic map): fp32 shading and T_hemi as above, 1e-5.
            EXPECT_NEAR(shadowed[c], expected.shadowed, 1e-5 * expected.shadowed)
                << "caustics " << caustics << ", channel " << c;
            // Lit, with the stand-in: as in the test above (the caustic map's own flat-water
            // accuracy is tested in tests/caustics).
            if (std::string(caustics) == "off") {
                EXPECT_NEAR(lit[c], expected.lit, 1e-5 * expected.lit) << c;
            }
        }
    }
}

TEST_F(SunShadow, ShadowMapPassRunsOnlyWithObjectsAndTheSunUp) {
    const std::string pipeline = "sun shadow map/sun shadow map/dynamic";
    const auto renders_shadow_map = [&](const std::string& extra) {
        const Scene scene = parse_scene(
            R"({"camera": {"position": [0, 5, 5], "target": [0, 0, 0]}, "sky": {"radiance": [0.2, 0.3, 0.4]})" + extra +
                "}",
            "shadow.json");
        Renderer renderer(context());
        renderer.render(scene, {16, 16, true, fg::TimingMode::None});
        return renderer.pipelines().contains(pipeline);
    };
    const std::string box = R"(, "receivers": [{"type": "box", "half_size": [1, 1, 1]}])";
    EXPECT_TRUE(renders_shadow_map(R"(, "sun": {"elevation_deg": 60})" + box));
    EXPECT_FALSE(renders_shadow_map(R"(, "sun": {"elevation_deg": 60})"));
    EXPECT_FALSE(renders_shadow_map(R"(, "sun": {"elevation_deg": -10})" + box));
}

}  // namespace
}  // namespace vkw::test
