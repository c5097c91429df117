// Reflection and refraction of the scene's objects (passes/scene_views/scene_view.hpp,
// shaders/water/scene_lookup.glsl), both methods, against the CPU reference's
// exact ray trace of the same flat water: a red box stands in the water over a black
// floor under a sky without red, so the red channel is the box alone (seen directly, in
// the reflection and through the surface). Plus the needs rules (culled = forced-on) and
// finite output with the camera grazing the surface and under it.
#include "engine/scene/receiver_boxes.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// scenes/box.json: the box stands from y = -1.6 to 0.4 through flat water (level 0), the
// floor 2 m down; with the camera and effects replaced.
Scene box_in_calm_water(const std::string& camera, const std::string& effects, const std::string& more = {}) {
    std::vector<std::string> overrides = {"camera=" + camera, "effects=" + effects};
    if (!more.empty()) overrides.push_back(more);
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "box.json", overrides);
}

const char* kCameraAbove = R"({"position": [0.8, 2.2, 2.6], "target": [0, -0.8, 0], "fov_y_deg": 60})";

float red(const ImageRGBA32F& image, int x, int y) { return image.pixel(x, y)[0]; }

float brightest_red(const ImageRGBA32F& image) {
    float brightest = 0.0f;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) brightest = std::max(brightest, red(image, x, y));
    }
    return brightest;
}

struct EdgeReport {
    int mismatched = 0;      // pixels whose red differs from the reference by more than delta
    int far_from_edges = 0;  // of those, how many lie more than the allowed distance from an edge
    std::string examples;    // the first few of them: "(x, y) real-time vs reference"
};

// Edges: reference pixels whose 3x3 neighbourhood spans more than delta in red. A
// mismatch is allowed within `reach` pixels (Chebyshev) of an edge.
EdgeReport compare_edges(const ImageRGBA32F& real_time, const ImageRGBA32F& reference, float delta, int reach) {
    std::vector<uint8_t> edge(size_t(kWidth) * kHeight, 0);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            float lo = 1e30f, hi = -1e30f;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = std::clamp(x + dx, 0, kWidth - 1), v = std::clamp(y + dy, 0, kHeight - 1);
                    lo = std::min(lo, red(reference, u, v));
                    hi = std::max(hi, red(reference, u, v));
                }
            }
            edge[size_t(y) * kWidth + x] = hi - lo > delta;
        }
    }
    EdgeReport report;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (std::abs(red(real_time, x, y) - red(reference, x, y)) <= delta) continue;
            ++report.mismatched;
            bool near_edge = false;
            for (int dy = -reach; dy <= reach && !near_edge; ++dy) {
                for (int dx = -reach; dx <= reach && !near_edge; ++dx) {
                    const int u = x + dx, v = y + dy;
                    near_edge = u >= 0 && v >= 0 && u < kWidth && v < kHeight && edge[size_t(v) * kWidth + u];
                }
            }
            if (!near_edge && ++report.far_from_edges <= 5) {
                report.examples += " (" + std::to_string(x) + ", " + std::to_string(y) + ") " +
                                   std::to_string(red(real_time, x, y)) + " vs " + std::to_string(red(reference, x, y));
            }
        }
    }
    return report;
}

// A frame of `scene` against the CPU ray trace of it, their edges compared: delta 1% of the ray
// trace's brightest red and reach 2 pixels, as derived in the first test below.
struct AgainstRayTrace {
    ImageRGBA32F real_time, reference;
    float delta = 0.0f;
    int reach = 2;
    EdgeReport report;
};
AgainstRayTrace render_against_ray_trace(Context& context, const Scene& scene) {
    Renderer renderer(context);
    AgainstRayTrace run;
    run.real_time = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None}).image;
    run.reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    run.delta = 0.01f * brightest_red(run.reference);
    run.report = compare_edges(run.real_time, run.reference, run.delta, run.reach);
    return run;
}

struct MethodCase {
    const char* name;
    const char* effects;
};

class SceneLookupEdges : public GpuTest, public ::testing::WithParamInterface<MethodCase> {};
using SceneLookupGrazing = GpuTest;

TEST_P(SceneLookupEdges, ReflectedAndRefractedBoxEdgesLandWhereTheRayTracePutsThem) {
    const AgainstRayTrace run =
        render_against_ray_trace(context(), box_in_calm_water(kCameraAbove, GetParam().effects));
    // delta: 1% of the brightest red. Inside a face the lookups return the radiance of the
    // view texels around the hit that show the same face, whose points lie within one texel
    // (about 1 cm here) of the exact one; the face's radiance changes by under 0.1% over that (flat lit faces are
    // uniform; under the water the stand-in's exp(-sigma_t depth / cos) moves by
    // 0.1 m^-1 x 1 cm / 0.6 < 0.2%), so only edges can differ by more than 1%.
    // reach: 2 pixels. A view texel is one camera pixel wide (the guard band widens the
    // view and its target by the same 1.5), the lookup ends on a texel up to half a texel from
    // the hit and reconstructs its estimate at that texel's centre, another half, and the
    // reading between texels keeps to the surface that texel shows: an edge can move
    // by one pixel each way from the ray trace's, two with the pixel's own rounding.
    const float delta = run.delta;
    const int reach = run.reach;
    const EdgeReport& report = run.report;
    EXPECT_EQ(report.far_from_edges, 0) << GetParam().name << ": " << report.mismatched
                                        << " pixels differ by more than " << delta << ", " << report.far_from_edges
                                        << " of them more than " << reach
                                        << " pixels from any edge:" << report.examples;
    // Without the lookups the same comparison must fail (the test can see the effect):
    // the box's reflection and its lower half through the water, about a hundred pixels
    // at this size (98 measured), are missing; half of them is a safe floor.
    const Scene without =
        box_in_calm_water(kCameraAbove, R"({"reflection": {"mode": "off"}, "refraction": {"mode": "off"}})");
    Renderer renderer(context());
    const RenderResult plain = renderer.render(without, {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(compare_edges(plain.image, run.reference, delta, reach).far_from_edges, 50)
        << "the reflected and refracted box should be missing without the scene views";
    const double rel_mse = metrics::rel_mse(metrics::rgb_view(run.real_time), metrics::rgb_view(run.reference),
                                            metrics::counted_pixels(kWidth, kHeight, nullptr));
    std::printf(
        "[ figures  ] %s: relMSE %.3g against the reference; %d pixels differ by > 1%% of the peak, "
        "%d of them more than %d px from an edge\n",
        GetParam().name, rel_mse, report.mismatched, report.far_from_edges, reach);
}

// The shader skips a ray's lookups where it meets none of the boxes that hold the receivers
// (engine/scene/receiver_boxes.hpp); past the frame constants' eight boxes, the rest share the last.
// Eight small spheres first, out of every ray's way (behind the camera, 8 m under the floor), so
// that the red box shares the eighth box with the last sphere: its edges, seen directly, in the
// reflection and through the surface, must still land where the ray trace puts them.
TEST_P(SceneLookupEdges, ABoxThatSharesTheLastReceiverBoxIsStillLookedUp) {
    std::string receivers;
    for (int i = 0; i < 8; ++i) {
        receivers += R"({"type": "sphere", "radius": 0.1, "translation": [)" + std::to_string(i - 4) +
                     ", -10, 12], \"albedo\": [0, 0, 0]}, ";
    }
    receivers += R"({"type": "box", "half_size": [0.5, 1.0, 0.5], "translation": [0, -0.6, 0],
                     "rotation_deg": [0, 25, 0], "albedo": [1, 0, 0]})";
    const Scene scene = box_in_calm_water(kCameraAbove, GetParam().effects, "receivers=[" + receivers + "]");
    const ReceiverBoxes boxes = receiver_boxes(scene);
    ASSERT_EQ(boxes.count, kReceiverBoxes);
    ASSERT_LT(boxes.lo[kReceiverBoxes - 1].z, scene.receivers[8].mesh.bounds_min.z);
    ASSERT_GT(boxes.hi[kReceiverBoxes - 1].z, scene.receivers[7].mesh.bounds_min.z) << "the box shares no box";
    const AgainstRayTrace run = render_against_ray_trace(context(), scene);
    // delta and reach as in the first test.
    EXPECT_EQ(run.report.far_from_edges, 0)
        << GetParam().name << ": " << run.report.mismatched << " pixels differ by more than " << run.delta << ", "
        << run.report.far_from_edges << " of them more than " << run.reach
        << " pixels from any edge:" << run.report.examples;
}

// The box lowered whole under the flat water (from 1.6 m to 0.8 m deep): seen from above, every
// refracted ray that meets it bends toward it, and many of them start where the camera's straight
// view behind the surface meets nothing. The projective lookup once started only from that view,
// so the box showed shrunk and shifted toward its unrefracted place (at this size 54 pixels more
// than 2 from any edge, measured with that start alone); it now starts from the ray's end there.
TEST_P(SceneLookupEdges, AFloatingBoxUnderTheWaterLandsWhereTheRayTracePutsIt) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "box.json",
                                   {"camera=" + std::string(kCameraAbove), "effects=" + std::string(GetParam().effects),
                                    "receivers[0].half_size=[0.5, 0.4, 0.5]", "receivers[0].translation=[0, -1.2, 0]"});
    const EdgeReport report = render_against_ray_trace(context(), scene).report;
    EXPECT_EQ(report.far_from_edges, 0) << GetParam().name << ": " << report.mismatched << " pixels differ, "
                                        << report.far_from_edges << " of them away from edges:" << report.examples;
}

// A wide slab under the water seen at a grazing angle, as lake's bed at its far shore: the
// camera's straight rays through the far part of the water pass beyond the slab's far edge, while
// the refracted rays, bent down, meet its top. The projective lookup's fixed-point steps start
// from what lies straight behind the surface point and land on texels that show nothing; the
// bracketed crossing finds the slab. The edges stay within reach of the ray trace's either way
// (the missing part lies along the far edge), so the slab's whole red is compared too: with the
// steps alone it was 0.45 of the reference's (measured), with the bracket 0.85.
TEST_F(SceneLookupGrazing, ASlabUnderTheWaterSeenAtAGrazingAngleShowsWholeThroughTheSurface) {
    const Scene scene =
        load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "box.json",
                   {R"(camera={"position": [0, 0.8, 6], "target": [0, -0.5, -2], "fov_y_deg": 60})",
                    R"(effects={"reflection": {"method": "projective"}, "refraction": {"method": "projective"}})",
                    "receivers[0].half_size=[2, 0.2, 2]", "receivers[0].translation=[0, -1.2, 0]"});
    const AgainstRayTrace run = render_against_ray_trace(context(), scene);
    const EdgeReport& report = run.report;
    EXPECT_EQ(report.far_from_edges, 0) << report.mismatched << " pixels differ, " << report.far_from_edges
                                        << " of them away from edges:" << report.examples;
    // The slab's red summed over the image. Each column it covers has a near and a far edge, each of
    // which may lie `reach` pixels from the ray trace's, so the sums may differ by at most
    // 2 edges x reach x the brightest red per column.
    double real_time_red = 0.0, reference_red = 0.0;
    int columns = 0;
    for (int x = 0; x < kWidth; ++x) {
        bool covered = false;
        for (int y = 0; y < kHeight; ++y) {
            real_time_red += red(run.real_time, x, y);
            reference_red += red(run.reference, x, y);
            covered = covered || red(run.reference, x, y) > run.delta;
        }
        columns += covered;
    }
    const double bound = 2.0 * run.reach * columns * brightest_red(run.reference);
    EXPECT_NEAR(real_time_red, reference_red, bound) << "the slab's red over " << columns << " columns";
    std::printf("[ figures  ] the slab's red %.4g against the ray trace's %.4g (%.2f; bound %.2f)\n", real_time_red,
                reference_red, real_time_red / reference_red, bound / reference_red);
}

// A green box floats through the flat water (from 0.3 m below the surface to 0.3 m above, 2 m
// long toward the camera's view) and hides a red tile 1.4 m down behind it: the red channel is the
// tile alone. The box's top hides the water just behind it and its submerged part hides the tile
// from the camera, but the refracted rays from the water the camera sees beyond the box bend down
// onto the tile. The refraction view's first layer holds the box there, its second layer the tile
// (passes/scene_views/scene_view.hpp).
Scene tile_behind_a_floating_box(const std::string& effects) {
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "box.json",
                      {R"(camera={"position": [0, 2.5, 6], "target": [0, -0.6, -2], "fov_y_deg": 22})",
                       "effects=" + effects, "sun.elevation_deg=40", "sun.azimuth_deg=0",
                       R"(receivers=[{"type": "box", "half_size": [0.6, 0.3, 1.0], "albedo": [0, 1, 0]},
                                     {"type": "box", "half_size": [0.5, 0.1, 0.5], "translation": [0, -1.5, -3.7],
                                      "albedo": [1, 0, 0]}])"});
}

TEST_P(SceneLookupEdges, TheTileAFloatingBoxHidesIsSeenBehindItThroughTheSurface) {
    const std::string method = GetParam().effects;
    const std::string with_layer =
        method.substr(0, method.size() - 1) + R"(, "refraction_second_layer": {"mode": "on"}})";
    const std::string without_layer =
        method.substr(0, method.size() - 1) + R"(, "refraction_second_layer": {"mode": "off"}})";
    const AgainstRayTrace run = render_against_ray_trace(context(), tile_behind_a_floating_box(with_layer));
    EXPECT_EQ(run.report.far_from_edges, 0)
        << GetParam().name << ": " << run.report.mismatched << " pixels differ, " << run.report.far_from_edges
        << " of them away from edges:" << run.report.examples;
    // Without the second layer the tile is missing (the test can see the layer): 48 pixels away from
    // edges at this size (measured); half of it is a safe floor.
    const AgainstRayTrace first_only = render_against_ray_trace(context(), tile_behind_a_floating_box(without_layer));
    EXPECT_GT(first_only.report.far_from_edges, 20) << GetParam().name << ": the hidden slab should be missing";
    std::printf("[ figures  ] %s: %d pixels away from edges without the second layer, %d with it\n", GetParam().name,
                first_only.report.far_from_edges, run.report.far_from_edges);
}

// A red sphere (radius 0.7 m) under the flat water, seen through the surface: its shading changes
// smoothly across its disc. The lookups end on one texel of the view; read from that texel alone,
// each texel's value would be copied to the pixels whose rays land in it (steps across the disc).
// Read bilinearly between the texels around the hit that show the same surface (filter_hit), it
// follows the ray trace at every pixel of the disc at least 2 pixels from its silhouette.
// Bound per pixel: half the ray trace's largest change from that pixel to a neighbour. A view texel
// is about one pixel here (the views' guard band widens the target by the same 1.5 as the view), so
// the one texel's reading, its centre up to half a texel from the hit in each direction, errs by up to
// about that much and more: 75 of the 705 pixels exceed it with the projective method, 57 with the
// screen-space march (measured with filter_hit returning at once). A bilinear reading of shading that
// is linear to first order over a texel leaves only its second-order term and the hit's placement
// within the texel: measured, no pixel exceeds even a quarter of the change.
TEST_P(SceneLookupEdges, ASphereUnderTheWaterIsReadBetweenTheViewsTexels) {
    const Scene scene = box_in_calm_water(
        kCameraAbove, GetParam().effects,
        R"(receivers=[{"type": "sphere", "radius": 0.7, "translation": [0, -1.0, 0], "albedo": [1, 0, 0]}])");
    Renderer renderer(context());
    const ImageRGBA32F real_time = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None}).image;
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    constexpr int kFromSilhouette = 2;
    int interior = 0, beyond = 0;
    std::string examples;
    for (int y = kFromSilhouette; y < kHeight - kFromSilhouette; ++y) {
        for (int x = kFromSilhouette; x < kWidth - kFromSilhouette; ++x) {
            bool inside = true;
            for (int dy = -kFromSilhouette; dy <= kFromSilhouette && inside; ++dy) {
                for (int dx = -kFromSilhouette; dx <= kFromSilhouette && inside; ++dx) {
                    inside = red(reference, x + dx, y + dy) > 0.0f;
                }
            }
            if (!inside) continue;
            ++interior;
            const float centre = red(reference, x, y);
            const float change =
                std::max({std::abs(red(reference, x + 1, y) - centre), std::abs(red(reference, x - 1, y) - centre),
                          std::abs(red(reference, x, y + 1) - centre), std::abs(red(reference, x, y - 1) - centre)});
            if (std::abs(red(real_time, x, y) - centre) > 0.5f * change && ++beyond <= 5) {
                examples += " (" + std::to_string(x) + ", " + std::to_string(y) + ") " +
                            std::to_string(red(real_time, x, y)) + " vs " + std::to_string(centre);
            }
        }
    }
    // The sphere covers about 700 pixels at least 2 from its silhouette (705 measured).
    ASSERT_GT(interior, 500) << GetParam().name << ": the sphere should fill much of the view";
    EXPECT_EQ(beyond, 0) << GetParam().name << ": " << beyond << " of " << interior
                         << " pixels differ from the ray trace by more than half its change to a neighbour:"
                         << examples;
}

INSTANTIATE_TEST_SUITE_P(
    Methods, SceneLookupEdges,
    ::testing::Values(
        MethodCase{"projective", R"({"reflection": {"method": "projective"}, "refraction": {"method": "projective"}})"},
        MethodCase{"screen_space",
                   R"({"reflection": {"method": "screen_space"}, "refraction": {"method": "screen_space"}})"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

bool all_finite_and_non_negative(const ImageRGBA32F& image) {
    return std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v) && v >= 0.0f; });
}

using SceneLookupRulesShallow = GpuTest;

class SceneLookupExtremes : public GpuTest, public ::testing::WithParamInterface<MethodCase> {};

TEST_P(SceneLookupExtremes, GrazingAndUnderwaterCamerasStayFinite) {
    // The check mode scans every written target (the views too) for NaN/Inf and names the pass.
    const char* cameras[] = {
        R"({"position": [0, 0.001, 4], "target": [0, 0.001, 0], "fov_y_deg": 60})",  // grazing the surface
        R"({"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 60})",          // on the water plane
        R"({"position": [0, -0.5, 3], "target": [0, 0.5, 0], "fov_y_deg": 90})",     // under the water, looking up
    };
    Renderer renderer(context());
    for (const char* camera : cameras) {
        const Scene scene = box_in_calm_water(camera, GetParam().effects);
        const RenderResult result = renderer.render(scene, {64, 48, true, fg::TimingMode::None});
        EXPECT_TRUE(all_finite_and_non_negative(result.image)) << GetParam().name << " " << camera;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Methods, SceneLookupExtremes,
    ::testing::Values(
        MethodCase{"projective", R"({"reflection": {"method": "projective"}, "refraction": {"method": "projective"}})"},
        MethodCase{"screen_space",
                   R"({"reflection": {"method": "screen_space"}, "refraction": {"method": "screen_space"}})"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST_F(SceneLookupRulesShallow, ShallowBlendFadesScreenSpaceRefractionToTheDirectView) {
    // Ojeda & Susín 2013's blend weights the refracted result by (water depth along the view) / blend,
    // clamped to 1. A blend depth far below any depth in the frame (1e-9 m against 0.5 m or
    // more) leaves every weight at 1: the image equals the unblended one exactly. A blend of
    // 10 m (5 to 20 times the depths here) mixes in the direct view: it moves the box's part
    // under the water (93 pixels change at 64x48; the black floor reads 0 either way), so at
    // least half of them must change.
    const std::string screen_space = R"("method": "screen_space")";
    const auto render_with = [&](const std::string& blend) {
        Renderer renderer(context());
        const Scene scene = box_in_calm_water(kCameraAbove, R"({"refraction": {)" + screen_space + blend + "}}");
        return renderer.render(scene, {64, 48, true, fg::TimingMode::None}).image;
    };
    const ImageRGBA32F off = render_with("");
    EXPECT_EQ(render_with(R"(, "shallow_blend": 1e-9)").rgba, off.rgba);
    const ImageRGBA32F blended = render_with(R"(, "shallow_blend": 10)");
    int changed = 0;
    for (size_t i = 0; i < off.rgba.size(); i += 4) changed += blended.rgba[i] != off.rgba[i];
    EXPECT_GT(changed, 46) << "the blend changed only " << changed << " of " << off.rgba.size() / 4 << " pixels";
}

// The needs rules: a view the rule culls holds nothing the water's rays would meet, so
// forcing it on changes no pixel: the forced view is empty (its lookups all fall back to
// the same exact sky or floor), and the images are equal exactly.
Scene sphere_scene(double sphere_height, const std::string& effects) {
    return parse_scene(R"({
      "camera": {"position": [0, 2, 4], "target": [0, -0.5, 0], "fov_y_deg": 60},
      "sun": {"elevation_deg": 50, "irradiance": [3, 3, 3]},
      "sky": {"radiance": [0.3, 0.4, 0.6]},
      "floor": {"height": -2, "half_extent": 10},
      "water": {"level": 0, "half_extent": 10, "grid_resolution": 8, "waves": {"model": "flat"}},
      "medium": {"sigma_a": [0.1, 0.1, 0.1], "sigma_s": [0, 0, 0]},
      "receivers": [{"type": "sphere", "radius": 0.5, "translation": [0, )" +
                           std::to_string(sphere_height) + R"(, 0]}],
      "effects": )" + effects +
                           "}",
                       "sphere.json");
}

using SceneLookupRules = GpuTest;

TEST_F(SceneLookupRules, CulledReflectionEqualsForcedOn) {
    // A sphere wholly under the water, the camera above: no object on the reflected rays' side.
    Renderer renderer(context());
    const RenderResult culled = renderer.render(sphere_scene(-1.0, "{}"), {64, 48, true, fg::TimingMode::None});
    const size_t pipelines = renderer.pipelines().size();
    const RenderResult forced =
        renderer.render(sphere_scene(-1.0, R"({"reflection": {"mode": "on"}})"), {64, 48, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines) << "forcing the reflection on created no view pipeline";
    EXPECT_EQ(culled.image.rgba, forced.image.rgba);
}

TEST_F(SceneLookupRules, CulledSecondLayerEqualsForcedOn) {
    // One convex box on the refracted rays' side hides only its own back: the second layer holds
    // nothing, and every lookup ends as it does without it.
    Renderer renderer(context());
    const Scene culled_scene = box_in_calm_water(kCameraAbove, "{}");
    ASSERT_FALSE(decide_frame_needs(culled_scene, 64.0 / 48.0).needs(Effect::RefractionSecondLayer));
    const RenderResult culled = renderer.render(culled_scene, {64, 48, true, fg::TimingMode::None});
    const size_t pipelines = renderer.pipelines().size();
    const RenderResult forced =
        renderer.render(box_in_calm_water(kCameraAbove, R"({"refraction_second_layer": {"mode": "on"}})"),
                        {64, 48, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines) << "forcing the second layer on created no pipeline";
    EXPECT_EQ(culled.image.rgba, forced.image.rgba);
}

TEST_F(SceneLookupRules, CulledRefractionEqualsForcedOn) {
    // A sphere wholly above the water, the camera above: nothing on the refracted rays' side.
    Renderer renderer(context());
    const RenderResult culled = renderer.render(sphere_scene(1.0, "{}"), {64, 48, true, fg::TimingMode::None});
    const size_t pipelines = renderer.pipelines().size();
    const RenderResult forced =
        renderer.render(sphere_scene(1.0, R"({"refraction": {"mode": "on"}})"), {64, 48, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines) << "forcing the refraction on created no view pipeline";
    EXPECT_EQ(culled.image.rgba, forced.image.rgba);
}

}  // namespace
}  // namespace vkw::test
