// The caustic layer (passes/caustics/caustic_layer.hpp) against the reference's (tools/reference), at
// 64x48, where the real-time sun term under the water is exact (flat water: the flat-surface
// stand-in is the model's irradiance): the floor seen through the surface, receiver meshes seen
// through it (the refraction scene view's own layer), and the floor seen from a camera in the
// water. And the layer leaves the image as it is.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/builtin_scene.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

RenderOptions with_layer() {
    RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    options.caustic_layer = true;
    return options;
}

const ExtraLayer& caustic_of(const ImageRGBA32F& image) {
    for (const ExtraLayer& layer : image.layers) {
        if (layer.name == "caustic") return layer;
    }
    throw std::runtime_error("no caustic layer");
}

// The worst difference of the layers, relative to its allowance, over the pixels where the
// reference's is lit (above `floor_value` in some channel), skipping pixels within one of a
// reference edge (a neighbour whose value differs by more than 5%: a rasterised edge in one
// renderer and a ray test in the other can put a boundary pixel on either side; a smooth
// receiver varies by less, about 1.7% per pixel down the box's side), and how many were compared.
// The allowance is `relative` x the value, plus, where the real-time lookup goes through the
// refraction scene view (`view_lookup`), the largest difference to a neighbour in the
// reference: the view's texel (2/3 of a pixel) holds a receiver point within one texel of the
// exact hit, whose value then differs by at most that much.
struct LayerComparison {
    double worst = 0.0;  // of |got - want| / allowance
    int compared = 0, dark_in_reference_lit_here = 0;
};

LayerComparison compare_layers(const ExtraLayer& got, const ExtraLayer& want, double floor_value, double relative,
                               bool view_lookup) {
    LayerComparison result;
    auto at = [&](const ExtraLayer& layer, int x, int y, int c) {
        return double(layer.rgb[3 * (size_t(y) * kWidth + x) + c]);
    };
    for (int y = 1; y + 1 < int(kHeight); ++y) {
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            bool edge = false, lit = false;
            double variation[3] = {0.0, 0.0, 0.0};
            for (int c = 0; c < 3; ++c) {
                const double centre = at(want, x, y, c);
                lit = lit || centre > floor_value;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const double step = std::abs(at(want, x + dx, y + dy, c) - centre);
                        variation[c] = std::max(variation[c], step);
                        edge = edge || step > 0.05 * std::max(std::abs(centre), floor_value);
                    }
                }
            }
            if (edge) continue;
            if (!lit) {
                // The reference's 0 (sky, air, the surface from below) must be 0 here too.
                for (int c = 0; c < 3; ++c) result.dark_in_reference_lit_here += at(got, x, y, c) != 0.0;
                continue;
            }
            ++result.compared;
            for (int c = 0; c < 3; ++c) {
                const double w = at(want, x, y, c);
                const double allowance = relative * std::max(w, floor_value) + (view_lookup ? variation[c] : 0.0);
                result.worst = std::max(result.worst, std::abs(at(got, x, y, c) - w) / allowance);
            }
        }
    }
    return result;
}

// The sun term under flat water is E_perp max(0, -t.N) exp(-sigma_t l) in both renderers: a
// handful of fp32 operations on fp32-rounded constants (frame constants, exp), each within a
// few units of 2^-24: 1e-5 relative is a generous bound for that chain (the image test in
// water_vs_reference_test.cpp derives the same bound for the longer radiance chain).
constexpr double kChainTolerance = 1e-5;

class CausticLayer : public GpuTest, public ::testing::WithParamInterface<const char*> {};
using CausticLayerImage = GpuTest;

// calm: the floor through the surface (exact in both). box: also the box's sides under the
// water, which the real-time water reads from the refraction view's layer.
TEST_P(CausticLayer, FlatWaterLayerMatchesTheReference) {
    const bool box = std::string(GetParam()) == "box.json";
    Scene scene = builtin_scene(GetParam());
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, with_layer());
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const LayerComparison result =
        compare_layers(caustic_of(real_time.image), caustic_of(reference), 1e-3, kChainTolerance, box);
    std::printf("%s: %d pixels compared, worst difference / allowance %.3f\n", GetParam(), result.compared,
                result.worst);
    EXPECT_GT(result.compared, int(kWidth * kHeight) / 4) << "too few lit receiver pixels in view";
    EXPECT_LE(result.worst, 1.0);
    EXPECT_EQ(result.dark_in_reference_lit_here, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, CausticLayer, ::testing::Values("calm.json", "box.json"), [](const auto& param_info) {
    return std::string(param_info.param).substr(0, std::string(param_info.param).find('.'));
});

TEST_F(CausticLayerImage, BoxSidesUnderTheWaterAreCompared) {
    // What makes the box case above meaningful: the box's sunlit sides under the water fill
    // enough interior pixels (the reference's red channel is the box alone).
    const Scene scene = builtin_scene("box.json");
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const ExtraLayer& layer = caustic_of(reference);
    int box_lit = 0;
    for (size_t i = 0; i < size_t{kWidth} * kHeight; ++i) {
        const float* p = &reference.rgba[4 * i];
        box_lit += p[0] > 2.0f * (p[1] + p[2]) + 1e-3f && layer.rgb[3 * i] > 1e-3f;
    }
    EXPECT_GT(box_lit, 60);
}

using CausticLayerFromBelow = GpuTest;

TEST_F(CausticLayerFromBelow, FloorSeenFromTheWaterMatchesAndTheSurfaceIsZero) {
    // A camera 1 m under flat water looking down and across: the floor directly (its own
    // layer value) and the surface from below (0: its pixels see the air or a reflection).
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, -1, 3], "target": [0, -1.6, -2], "fov_y_deg": 70},
      "sun": {"elevation_deg": 55, "azimuth_deg": 30, "irradiance": [2, 3, 4]},
      "sky": {"radiance": [0.4, 0.5, 0.6]},
      "floor": {"height": -3, "half_extent": 30},
      "water": {"level": 0, "half_extent": 30, "waves": {"model": "flat"}},
      "medium": {"preset": "clear-ocean"}
    })",
                                    "below.json");
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, with_layer());
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const LayerComparison result =
        compare_layers(caustic_of(real_time.image), caustic_of(reference), 1e-3, kChainTolerance, false);
    std::printf("below: %d pixels compared, worst difference / allowance %.3f\n", result.compared, result.worst);
    EXPECT_GT(result.compared, int(kWidth * kHeight) / 4);
    EXPECT_LE(result.worst, 1.0);
    EXPECT_EQ(result.dark_in_reference_lit_here, 0);
}

TEST_F(CausticLayerImage, LayerLeavesTheImageUnchanged) {
    // The layer is a second output of the same shaders: the radiance must not move by a bit.
    const Scene scene = builtin_scene("lake.json");
    Renderer renderer(context());
    const RenderResult plain = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const RenderResult layered = renderer.render(scene, with_layer());
    EXPECT_TRUE(plain.image.layers.empty());
    ASSERT_EQ(layered.image.layers.size(), 1u);
    EXPECT_EQ(plain.image.rgba, layered.image.rgba);
}

}  // namespace
}  // namespace vkw::test
