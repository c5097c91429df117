// Receiver meshes on the device: the top face of a box above the water is a Lambertian
// surface lit by the sun and the sky, L = rho (E_s cos(theta_s) + pi L_sky) / pi (the
// model's closed form, docs/model.md section 1), read at the pixel that sees its centre.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/render/overhead_scene.hpp"
#include "tests/scene/gltf_test_files.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <numbers>

namespace vkw::test {
namespace {

using ReceiverPass = GpuTest;

TEST_F(ReceiverPass, BoxTopAboveTheWaterMatchesTheClosedForm) {
    // Looking straight down at a 2 m box whose top (y = 1) fills the centre of the view.
    const Scene scene =
        overhead_receiver_scene(R"({"type": "box", "half_size": [1, 1, 1], "albedo": [0.7, 0.5, 0.3]})", "box.json");
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {33, 33, true, fg::TimingMode::None});
    const float* centre = result.image.pixel(16, 16);
    const double cos_sun = -scene.sun.direction.y;
    for (int c = 0; c < 3; ++c) {
        const double albedo = scene.receivers[0].albedo[c];
        const double expected =
            albedo * (scene.sun.irradiance[c] * cos_sun + std::numbers::pi * scene.sky.radiance[c]) / std::numbers::pi;
        // As in the first-pixels test: ~10 fp32 roundings of the inputs and the shading,
        // plus the interpolated normal's renormalisation (another few): 2e-6 relative.
        EXPECT_NEAR(centre[c], expected, 2e-6 * expected) << "channel " << c;
    }
}

// A glTF file of two materials (test::two_material_squares) lifted to y = 1 and seen from
// straight above: each square shows its own base colour, applied once, in both renderers (a
// base colour of 0.5 once rendered at 0.25, squared by both, so they agreed with each other).
TEST_F(ReceiverPass, EachGltfMaterialIsItsOwnAlbedoInBothRenderers) {
    const std::filesystem::path dir = scratch_dir("receiver_two_materials");
    const std::filesystem::path file =
        write_text(dir / "squares.gltf",
                   two_material_squares(R"({ "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1] } },
                                { "pbrMetallicRoughness": { "baseColorFactor": [0.2, 0.4, 0.8, 1] } })"));
    // The camera straight over each square's centre, at x = -0.5 (grey) and x = +0.5 (blue); the
    // centre pixel sees it. The same view of a built-in box whose top is that square, of albedo the
    // material's base colour, is what the real-time square must show.
    const std::pair<double, std::string> squares[] = {{-0.5, "[0.5, 0.5, 0.5]"}, {0.5, "[0.2, 0.4, 0.8]"}};
    for (const auto& [x, albedo] : squares) {
        const std::string centre = std::to_string(x);
        const auto scene_with = [&](const std::string& receiver) {
            return overhead_receiver_scene(receiver, dir / "squares.json", x);
        };
        const Scene gltf =
            scene_with(R"({"type": "gltf", "file": ")" + file.filename().string() + R"(", "translation": [0, 1, 0]})");
        const Scene box = scene_with(R"({"type": "box", "half_size": [0.5, 0.5, 1], "translation": [)" + centre +
                                     R"(, 0.5, 0], "albedo": )" + albedo + "}");
        Renderer renderer(context());
        const RenderOptions options{33, 33, true, fg::TimingMode::None};
        const RenderResult square = renderer.render(gltf, options);
        const RenderResult box_top = renderer.render(box, options);
        const ImageRGBA32F reference = ref::render_reference(gltf, {33, 33, 0, {}});
        const double cos_sun = -gltf.sun.direction.y;
        for (int c = 0; c < 3; ++c) {
            const double rho = box.receivers[0].albedo[c];
            const double expected =
                rho * (gltf.sun.irradiance[c] * cos_sun + std::numbers::pi * gltf.sky.radiance[c]) / std::numbers::pi;
            // Real time against the closed form. Its fp32 shading of a lit point carries an error
            // that depends on more than the point: this view of it measures 1e-6 to 7e-6 relative,
            // whether the point is the glTF square or a built-in box's top of the same albedo (they
            // differ from each other by up to 3.5e-6), so the box test's 2e-6 does not hold here; the
            // cause is not traced. 1e-5 relative, where a base colour applied twice is off by 1 - rho
            // (0.2 to 0.8) of the value.
            EXPECT_NEAR(square.image.pixel(16, 16)[c], expected, 1e-5 * expected)
                << "square at x = " << x << ", channel " << c;
            EXPECT_NEAR(box_top.image.pixel(16, 16)[c], expected, 1e-5 * expected)
                << "box top at x = " << x << ", channel " << c;
            // The reference against the closed form: double precision throughout, then stored as
            // fp32 (half an ulp, 6e-8 relative): 1e-7 relative.
            EXPECT_NEAR(reference.pixel(16, 16)[c], expected, 1e-7 * expected)
                << "square at x = " << x << ", channel " << c;
        }
    }
}

}  // namespace
}  // namespace vkw::test
