// The in-scatter layer (keys::kInScatterLayer, EXR channels inscatter.R/G/B): the godrays'
// single-scattered radiance alone, in a frame that has other light (a bright sky reflected by the
// water, a grey floor), against docs/model.md section 6 on flat water; the layer is absent where
// the godrays do not run, and 0 where they add nothing.
#include "tests/godrays/godrays_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 7;  // as godrays_flat_test.cpp: one pyramid level, exact chords
constexpr int kCentre = 3;
constexpr double kUnit = 0x1.0p-24;
// godrays_flat_test.cpp's bound on the godray pixel's fp32 error (kRounding, derived there); the
// layer is the composite's same output, written to a second target cleared to 0: 0 + x = x.
constexpr double kRounding = (40.0 + 40.0 + 10.0 + 30.0) * kUnit + 2e-6 + 3e-6;

const ExtraLayer* find_layer(const ImageRGBA32F& image, const std::string& name) {
    const auto it = std::find_if(image.layers.begin(), image.layers.end(),
                                 [&](const ExtraLayer& layer) { return layer.name == name; });
    return it == image.layers.end() ? nullptr : &*it;
}

// godray_scene with light of its own: a sky of 0.5 W m^-2 sr^-1 (its reflection in the water and
// its light on the floor) and a grey floor; the beams stop at max_depth = 6 m as before.
Scene lit_scene(const std::string& camera, std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.end(), {"sky.radiance=[0.5,0.5,0.5]", "floor.albedo=[0.5,0.5,0.5]", "floor.height=-8",
                                       "effects.godrays.grid=64"});
    return godray_scene(camera, R"({"sigma_a": [0.9, 0.3, 0.1], "sigma_s": [0.3, 0.5, 0.8], "g": 0.9})", overrides);
}

RenderResult render_with_layer(Context& context, const Scene& scene) {
    Renderer renderer(context);
    RenderOptions options{kSize, kSize, true, fg::TimingMode::None};
    options.inscatter_layer = true;
    return renderer.render(scene, options);
}

using godrays_inscatter_layer = GpuTest;

TEST_F(godrays_inscatter_layer, HoldsSection6sInScatterAloneFromAbove) {
    // 3 m above the surface looking straight down (godrays_flat_test.cpp's vertical ray, whose tubes
    // are checked a pixel wide there): T / n^2 times the refracted ray's in-scatter.
    const Scene scene =
        lit_scene(R"({"position": [0, 3, 0], "direction": [0, -1, 0], "fov_y_deg": 6, "near": 0.01, "far": 100})");
    const RenderResult result = render_with_layer(context(), scene);
    const ExtraLayer* layer = find_layer(result.image, "inscatter");
    ASSERT_NE(layer, nullptr);
    const glm::dvec3 expected = expected_blurred(scene, kSize, kSize, kCentre, kCentre);
    const size_t centre = size_t{kCentre} * kSize + kCentre;
    for (int c = 0; c < 3; ++c) {
        ASSERT_GT(expected[c], 0.0);
        EXPECT_NEAR(layer->rgb[3 * centre + c] / expected[c], 1.0, kRounding) << "channel " << c;
        // The pixel holds the sky's reflection and the lit floor besides: at least twice the layer
        // here (the reflection alone is F(0) 0.5 = 0.01, the floor ~0.02 through the water), so a
        // layer that copied the pixel fails.
        EXPECT_GT(result.image.pixel(kCentre, kCentre)[c], layer->rgb[3 * centre + c] + 0.005) << "channel " << c;
    }
}

TEST_F(godrays_inscatter_layer, IsZeroWhereTheViewMissesTheWater) {
    // 3 m above the water's near edge looking 20 degrees down (60 degrees of view): the top row's rays
    // rise 6 degrees above the horizon into the sky, the bottom row's fall 46 degrees and enter the
    // water 2.9 m ahead, inside its 4 m half extent. The layer is exactly 0 in the sky (nothing is
    // added there; the target is cleared to 0) and positive where the rays pass through lit water.
    const Scene scene = lit_scene(
        R"({"position": [0, 3, 3], "direction": [0, -0.364, -1], "fov_y_deg": 60, "near": 0.01, "far": 100})");
    const RenderResult result = render_with_layer(context(), scene);
    const ExtraLayer* layer = find_layer(result.image, "inscatter");
    ASSERT_NE(layer, nullptr);
    for (uint32_t x = 0; x < kSize; ++x) {
        const size_t top = x;
        const size_t bottom = size_t{kSize - 1} * kSize + x;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(layer->rgb[3 * top + c], 0.0f) << "column " << x << " channel " << c;
            EXPECT_GT(layer->rgb[3 * bottom + c], 0.0f) << "column " << x << " channel " << c;
        }
        EXPECT_GT(result.image.pixel(x, 0)[0], 0.4f) << "column " << x << ": the sky, 0.5";
    }
}

TEST_F(godrays_inscatter_layer, IsAbsentWhereTheGodraysDoNotRun) {
    const Scene scene =
        lit_scene(R"({"position": [0, 3, 0], "direction": [0, -1, 0], "fov_y_deg": 6, "near": 0.01, "far": 100})",
                  {"effects.godrays.mode=off"});
    const RenderResult result = render_with_layer(context(), scene);
    EXPECT_EQ(find_layer(result.image, "inscatter"), nullptr);
}

}  // namespace
}  // namespace vkw::test
