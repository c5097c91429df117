// The CPU reference renderer against the closed forms of docs/model.md for flat water:
// radiance seen from above (section 3) at view elevations 5, 20, 45 and 90 degrees,
// the floor's sun irradiance under the water for several sun angles (its caustic
// layer), the in-scatter layer from above, from within and under total internal reflection
// (section 6), Snell's window radius seen
// from below (section 7), determinism, and a clear refusal of what it does not compute yet.
#include "engine/core/errors.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/reference_renderer.hpp"
#include "tools/reference/water_transport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace vkw::ref {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kIor = 1.333;
constexpr double kDepth = 1.5;

// Flat water over a grey floor 1.5 m down, constant sky, coastal-like medium with
// g = 0.9 so that every term of the model contributes.
Scene calm_scene(double sun_elevation_deg,
                 const std::string& camera = R"("position": [0, 2, 0], "target": [0, 0, -1])") {
    const std::string text = R"({
      "camera": {)" + camera +
                             R"(, "fov_y_deg": 60},
      "sun": {"elevation_deg": )" +
                             std::to_string(sun_elevation_deg) + R"(, "azimuth_deg": 90, "irradiance": [3, 2, 1]},
      "sky": {"radiance": [0.3, 0.45, 0.7]},
      "floor": {"height": -1.5, "albedo": [0.6, 0.5, 0.4], "half_extent": 50},
      "water": {"level": 0, "ior": 1.333, "half_extent": 50},
      "medium": {"sigma_a": [0.45, 0.06, 0.02], "sigma_s": [0.17, 0.2, 0.234], "g": 0.9}
    })";
    return parse_scene(text, "calm_test.json");
}

double fresnel_t(double cos_i) { return 1.0 - fresnel_reflectance(cos_i, 1.0, kIor); }

// docs/model.md section 3, written out here from its pieces: the floor's irradiance
// E_floor = E_s cos(theta_s) T(theta_s) exp(-sigma_t d / cos(theta_t)) plus skylight,
// then the view path of section 6 and the surface; the in-scatter term alone, carried through the
// surface, also in `in_scatter` when given.
glm::dvec3 closed_form_from_above(const Scene& scene, const glm::dvec3& view, glm::dvec3* in_scatter = nullptr) {
    const glm::dvec3 s = scene.sun.direction;
    const double cos_s = -s.y;
    const double sin_t_sun = std::sqrt(1 - cos_s * cos_s) / kIor, cos_t_sun = std::sqrt(1 - sin_t_sun * sin_t_sun);
    const glm::dvec3 t_sun{-s.x / std::sqrt(1 - cos_s * cos_s) * sin_t_sun, -cos_t_sun,
                           -s.z / std::sqrt(1 - cos_s * cos_s) * sin_t_sun};  // refracted sun, same azimuth
    const double cos_v = -view.y;
    const double sin_w = std::sqrt(1 - cos_v * cos_v) / kIor, cos_w = std::sqrt(1 - sin_w * sin_w);
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    const glm::dvec3 refracted_view{view.x / std::sqrt(1 - cos_v * cos_v + 1e-300) * sin_w, -cos_w,
                                    view.z / std::sqrt(1 - cos_v * cos_v + 1e-300) * sin_w};
    glm::dvec3 radiance;
    for (int c = 0; c < 3; ++c) {
        const double e_floor =
            scene.sun.irradiance[c] * cos_s * fresnel_t(cos_s) * std::exp(-sigma_t[c] * kDepth / cos_t_sun);
        const double e_sky =
            kPi * scene.sky.radiance[c] * hemispherical_transmittance(kIor) * std::exp(-sigma_t[c] * kDepth);
        const double l_behind = scene.floor.albedo[c] * (e_floor + e_sky) / kPi;
        InScatterInput in{scene.medium.sigma_s[c],
                          sigma_t[c],
                          scene.medium.g,
                          0.0,
                          kDepth / cos_w,
                          refracted_view,
                          t_sun,
                          scene.sun.irradiance[c] * cos_s * fresnel_t(cos_s) / cos_t_sun,
                          l_behind};
        const double l_water = water_path_radiance(in);
        const double reflectance = 1.0 - fresnel_t(cos_v);
        radiance[c] = reflectance * scene.sky.radiance[c] + fresnel_t(cos_v) / (kIor * kIor) * l_water;
        if (in_scatter) {
            in.l_behind = 0.0;
            (*in_scatter)[c] = fresnel_t(cos_v) / (kIor * kIor) * water_path_radiance(in);
        }
    }
    return radiance;
}

TEST(reference_flat_water, RadianceAndItsInScatterFromAboveMatchSections3And6) {
    const Scene scene = calm_scene(60.0);
    const WaterTransport transport(scene);
    for (double elevation : {5.0, 20.0, 45.0, 90.0}) {
        const double e = elevation * kPi / 180.0;
        // Look along -z (sun toward +x): no sun glint in the reflected direction.
        const glm::dvec3 view = elevation == 90.0 ? glm::dvec3(0, -1, 0) : glm::dvec3(0, -std::sin(e), -std::cos(e));
        const PixelRadiance pixel = transport.trace_camera_ray({{0, 2, 0}, view});
        glm::dvec3 expected_in_scatter;
        const glm::dvec3 expected = closed_form_from_above(scene, view, &expected_in_scatter);
        for (int c = 0; c < 3; ++c) {
            // Both sides are double precision; T_hemi comes from a numerical integral
            // exact to ~1e-9, which bounds the relative difference.
            EXPECT_NEAR(pixel.radiance[c], expected[c], 1e-8 * expected[c]) << elevation << " deg, channel " << c;
            // The in-scatter alone (section 6's second term through the surface): the same closed
            // form reached through different operations (the ray's crossing, the refraction), a
            // few dozen roundings, ~1e-14; the crossing at kOffset from the hit moves the path's
            // length by ~1e-9 m. It is part of the pixel, never the whole of it.
            ASSERT_GT(expected_in_scatter[c], 0.0);
            EXPECT_NEAR(pixel.in_scatter[c], expected_in_scatter[c], 1e-8 * expected_in_scatter[c])
                << elevation << " deg, channel " << c;
            EXPECT_LT(pixel.in_scatter[c], pixel.radiance[c]) << "the in-scatter alone, not the pixel's radiance";
        }
    }
}

// The sun under flat water: its cosines above and below, and the refracted direction t (Snell's law
// written out, not the renderer's refract).
struct SunUnderFlatWater {
    double cos_s, cos_t;
    glm::dvec3 t;
};
SunUnderFlatWater sun_under_flat_water(const Scene& scene) {
    const glm::dvec3 s = scene.sun.direction;
    const double cos_s = -s.y, sin_s = std::sqrt(1 - cos_s * cos_s);
    const double sin_t = sin_s / kIor, cos_t = std::sqrt(1 - sin_t * sin_t);
    return {cos_s, cos_t, {s.x / sin_s * sin_t, -cos_t, s.z / sin_s * sin_t}};
}

TEST(reference_flat_water, InScatterFromWithinIsSection6sTermOfTheViewSegment) {
    // From 0.5 m down, 45 degrees below the horizon toward the floor 1.5 m down: a path of
    // sqrt(2) m from depth z0 = 0.5, the segment of section 6 with nothing behind it.
    const Scene scene = calm_scene(60.0, R"("position": [0, -0.5, 0], "target": [0, -1.5, -1])");
    const WaterTransport transport(scene);
    const glm::dvec3 view = glm::normalize(glm::dvec3(0, -1, -1));
    const PixelRadiance pixel = transport.trace_camera_ray({{0, -0.5, 0}, view});
    const SunUnderFlatWater sun = sun_under_flat_water(scene);
    const double cos_s = sun.cos_s, cos_t = sun.cos_t;
    const glm::dvec3 t_sun = sun.t;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    for (int c = 0; c < 3; ++c) {
        const InScatterInput in{scene.medium.sigma_s[c],
                                sigma_t[c],
                                scene.medium.g,
                                0.5,
                                std::sqrt(2.0),
                                view,
                                t_sun,
                                scene.sun.irradiance[c] * cos_s * fresnel_t(cos_s) / cos_t,
                                0.0};
        const double expected = water_path_radiance(in);
        ASSERT_GT(expected, 0.0);
        // Double precision on both sides; the floor's hit found by the BVH to ~1e-12 m.
        EXPECT_NEAR(pixel.in_scatter[c], expected, 1e-10 * expected) << "channel " << c;
        EXPECT_LT(pixel.in_scatter[c], pixel.radiance[c]);
    }
}

TEST(reference_flat_water, InScatterUnderTotalReflectionAddsTheReflectedSegment) {
    // From 1 m down, rising at 30 degrees above the horizontal (60 degrees from the normal, past
    // the critical 48.6): the path meets the surface after 2 m, is totally reflected (R = 1) and
    // falls at 30 degrees to the floor 1.5 m down, 3 m further. The layer is section 6's term of
    // the first segment plus that of the reflected one, carried back over the first's 2 m.
    const Scene scene = calm_scene(60.0, R"("position": [0, -1, 0], "target": [0, -0.5, -0.8660254])");
    const WaterTransport transport(scene);
    const glm::dvec3 up = glm::normalize(glm::dvec3(0, 0.5, -0.8660254037844386));
    const PixelRadiance pixel = transport.trace_camera_ray({{0, -1, 0}, up});
    const glm::dvec3 down{up.x, -up.y, up.z};
    const SunUnderFlatWater sun = sun_under_flat_water(scene);
    const double cos_s = sun.cos_s, cos_t = sun.cos_t;
    const glm::dvec3 t_sun = sun.t;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    for (int c = 0; c < 3; ++c) {
        const double e_perp0 = scene.sun.irradiance[c] * cos_s * fresnel_t(cos_s) / cos_t;
        const double first = water_path_radiance(
            {scene.medium.sigma_s[c], sigma_t[c], scene.medium.g, 1.0, 2.0, up, t_sun, e_perp0, 0.0});
        const double reflected = water_path_radiance(
            {scene.medium.sigma_s[c], sigma_t[c], scene.medium.g, 0.0, 3.0, down, t_sun, e_perp0, 0.0});
        const double expected = first + std::exp(-2.0 * sigma_t[c]) * reflected;
        ASSERT_GT(reflected, 0.0);
        // Double precision on both sides; the surface and floor hits to ~1e-12 m.
        EXPECT_NEAR(pixel.in_scatter[c], expected, 1e-9 * expected) << "channel " << c;
        EXPECT_LT(pixel.in_scatter[c], pixel.radiance[c]);
    }
}

TEST(reference_flat_water, FloorSunIrradianceMatchesSection3) {
    for (double sun_elevation : {90.0, 60.0, 30.0, 5.0}) {
        const Scene scene = calm_scene(sun_elevation);
        const WaterTransport transport(scene);
        const double cos_s = std::sin(sun_elevation * kPi / 180.0);
        const double sin_t = std::sqrt(1 - cos_s * cos_s) / kIor, cos_t = std::sqrt(1 - sin_t * sin_t);
        const glm::dvec3 e = transport.sun_irradiance_under_water({0.3, -kDepth, -2.0}, {0, 1, 0});
        for (int c = 0; c < 3; ++c) {
            const double expected = scene.sun.irradiance[c] * cos_s * fresnel_t(cos_s) *
                                    std::exp(-scene.medium.sigma_t()[c] * kDepth / cos_t);
            EXPECT_NEAR(e[c], expected, 1e-12 * expected) << "sun " << sun_elevation << " channel " << c;
        }
    }
}

TEST(reference_flat_water, CausticLayerIsTheUniformFloorIrradianceInEveryPixel) {
    // Under flat water the floor's sun irradiance is the same everywhere (section 3), so
    // every pixel of the caustic layer must hold it: a pixel that misses it (a floor hit
    // misclassified as above the water, a self-shadowed point) shows at once.
    const Scene scene = calm_scene(60.0, R"("position": [0, 2, 0], "target": [0, 0, -1])");
    const uint32_t width = 64, height = 48;
    const ImageRGBA32F image = render_reference(scene, {width, height, 0, {}});
    ASSERT_EQ(image.layers.size(), 2u);
    ASSERT_EQ(image.layers[0].name, "caustic");
    ASSERT_EQ(image.layers[1].name, "inscatter");
    const WaterTransport transport(scene);
    const glm::dvec3 expected = transport.sun_irradiance_under_water({0, -kDepth, 0}, {0, 1, 0});
    for (size_t pixel = 0; pixel < size_t{width} * height; ++pixel) {
        for (int c = 0; c < 3; ++c) {
            // Stored as fp32: half an ulp, 2^-24 relative.
            ASSERT_NEAR(image.layers[0].rgb[3 * pixel + c], expected[c], std::ldexp(expected[c], -24))
                << "pixel " << pixel % width << "," << pixel / width << " channel " << c;
        }
    }
}

TEST(reference_flat_water, SnellsWindowRadiusIsFocalLengthTimesTanCritical) {
    // docs/model.md section 7: viewer 2 m down looking straight up, fov 120 degrees, albedo 0,
    // constant sky, sigma_s = 0, no sun: only the transmitted sky is left.
    const std::string text = R"({
      "camera": {"position": [0, -2, 0], "target": [0, 0, 0], "fov_y_deg": 120},
      "sun": {"elevation_deg": 60, "irradiance": [0, 0, 0]},
      "sky": {"radiance": [1, 1, 1]},
      "floor": {"height": -10, "albedo": [0, 0, 0], "half_extent": 100},
      "water": {"level": 0, "ior": 1.333, "half_extent": 100},
      "medium": {"sigma_a": [0.01, 0.01, 0.01], "sigma_s": [0, 0, 0], "g": 0}
    })";
    const Scene scene = parse_scene(text, "snell_test.json");
    const uint32_t size = 301;
    const ImageRGBA32F image = render_reference(scene, {size, size, 0, {}});
    const int centre = size / 2;
    const double centre_value = image.pixel(centre, centre)[0];
    ASSERT_GT(centre_value, 0.0);
    int radius_px = -1;
    for (int x = centre; x < int(size); ++x) {
        if (image.pixel(x, centre)[0] < 1e-3 * centre_value) {
            radius_px = x - centre;
            break;
        }
    }
    const double focal_px = (size / 2.0) / std::tan(60.0 * kPi / 180.0);
    const double expected = focal_px * std::tan(std::asin(1.0 / kIor));
    EXPECT_NEAR(radius_px, expected, 1.0);  // docs/model.md: within one pixel
}

TEST(reference_flat_water, OutputIsIdenticalForAnyThreadCount) {
    const Scene scene = calm_scene(45.0);
    const ImageRGBA32F one = render_reference(scene, {40, 30, 1, {}});
    const ImageRGBA32F two = render_reference(scene, {40, 30, 2, {}});
    EXPECT_EQ(one.rgba, two.rgba);
    for (size_t i = 0; i < one.layers.size(); ++i) EXPECT_EQ(one.layers[i].rgb, two.layers[i].rgb);
}

TEST(reference_flat_water, RefusesWhatItDoesNotComputeYetWithAClearMessage) {
    // Receiver meshes under an FFT ocean (the FFT ocean alone renders: ocean_reference_test.cpp).
    const Scene ocean = parse_scene(R"({
      "camera": {"position": [0, 2, 0], "target": [0, 0, -1]},
      "sun": {"elevation_deg": 45, "irradiance": [1, 1, 1]},
      "sky": {"radiance": [0.1, 0.1, 0.1]},
      "floor": {"height": -2, "half_extent": 8},
      "water": {"level": 0, "half_extent": 8,
                "waves": {"model": "fft", "resolution": 16, "patch_size": 8, "wind_speed": 5}},
      "receivers": [{"type": "box", "half_size": [0.3, 0.1, 0.3], "translation": [0, -0.5, 0]}]
    })",
                                    "ocean_with_box.json");
    try {
        render_reference(ocean, {4, 4, 1, {}});
        FAIL() << "receiver meshes under an FFT ocean were accepted";
    } catch (const UserError& error) {
        EXPECT_NE(std::string(error.what()).find("ocean_with_box.json: receivers"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace vkw::ref
