// Khronos glTF 2.0 sample models that nobody here wrote (Debian's assimp-testmodels, installed by
// tools/install-deps.sh), under flat water, in both renderers: BoxTextured in its three encodings
// (a .gltf with an external PNG, one with everything embedded, a .glb), and 2CylinderEngine (a .glb
// of 34 materials over a node hierarchy). Where the reference image is locally uniform, the
// real-time image shows the same colour, so the materials and the texture are where the model puts
// them, in both renderers at once.
#include "engine/scene/gltf_mesh.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/render/uniform_agreement.hpp"
#include "tests/scene/gltf_test_files.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

const std::filesystem::path kSamples = "/usr/share/assimp/models/glTF2";
constexpr uint32_t kWidth = 256, kHeight = 192;

// Where the camera looks at the model from: in the water at the model 1.3 m deep, or above it at
// the model 1 m over the water. Either way no view ray to the model crosses the surface, so each
// pixel's path is the model's closed form in both renderers, and the receiver's colour is what
// differs between pixels.
struct Placement {
    double model_height;
    const char* camera;
    const char* sun_irradiance;
};
constexpr Placement kUnderWater{-1.3, R"({"position": [0.9, -0.6, 1.5], "target": [0, -1.3, 0], "fov_y_deg": 45})",
                                "[3, 3, 3]"};
// Lit by the sky alone: 2CylinderEngine has coplanar twin surfaces, which the reference's shadow ray
// (offset 1e-9 m, under the float positions' rounding) finds blocking each other in the sun and the
// real-time shadow map finds with acne; sky light has no shadows in the model (docs/model.md
// section 1), so each part shows its base colour times the sky's radiance in both.
constexpr Placement kAboveWater{1.0, R"({"position": [1.1, 1.9, 1.9], "target": [0, 1.0, 0], "fov_y_deg": 45})",
                                "[0, 0, 0]"};

// The model in clear, flat water (level 0) over a black floor.
Scene sample_scene(const std::filesystem::path& model, const Placement& placement, const std::string& transform,
                   const std::string& extra = "") {
    const std::filesystem::path dir = scratch_dir("khronos_" + model.stem().string());
    return parse_scene(R"({
      "camera": )" + std::string(placement.camera) +
                           R"(,
      "sun": {"elevation_deg": 60, "azimuth_deg": 200, "irradiance": )" +
                           placement.sun_irradiance + R"(},
      "sky": {"radiance": [0.3, 0.35, 0.4]},
      "floor": {"height": -2.5, "albedo": [0, 0, 0], "half_extent": 10},
      "water": {"level": 0, "half_extent": 10, "waves": {"model": "flat"}},
      "medium": {"sigma_a": [0.05, 0.05, 0.05], "sigma_s": [0, 0, 0]},
      "receivers": [{"type": "gltf", "file": ")" +
                           model.string() + R"(", )" + transform + extra + R"(}]
    })",
                       dir / "scene.json", {}, SceneLoadOptions{.allow_outside_paths = true});
}

using KhronosSamples = GpuTest;

// The model centred over the origin at the placement's height, turned about y, and scaled to
// `size` metres along its longest side.
std::string fitted(const Mesh& mesh, const Placement& placement, double size, double turn_deg) {
    const glm::dvec3 extent = mesh.bounds_max - mesh.bounds_min;
    const double scale = size / std::max({extent.x, extent.y, extent.z});
    const glm::dvec3 centre = 0.5 * (mesh.bounds_min + mesh.bounds_max);
    // world = T R S object: the centre lands at R (scale centre) + T.
    const double turn = glm::radians(turn_deg);
    const glm::dvec3 turned(std::cos(turn) * centre.x + std::sin(turn) * centre.z, centre.y,
                            -std::sin(turn) * centre.x + std::cos(turn) * centre.z);
    const glm::dvec3 at = glm::dvec3(0.0, placement.model_height, 0.0) - scale * turned;
    return R"("translation": [)" + std::to_string(at.x) + ", " + std::to_string(at.y) + ", " + std::to_string(at.z) +
           R"(], "rotation_deg": [0, )" + std::to_string(turn_deg) + R"(, 0], "scale": [)" + std::to_string(scale) +
           ", " + std::to_string(scale) + ", " + std::to_string(scale) + "]";
}

TEST_F(KhronosSamples, BoxTexturedShowsItsTextureInBothRenderersInEveryEncoding) {
    ASSERT_TRUE(std::filesystem::exists(kSamples)) << kSamples << " is missing: run tools/install-deps.sh";
    // Debian's copy of the external-image encoding samples with MIRRORED_REPEAT and CLAMP_TO_EDGE
    // where the other two repeat, over texture coordinates beyond [0, 1]: its faces differ from
    // theirs, and each must still agree with the reference.
    const std::filesystem::path external = kSamples / "BoxTextured-glTF/BoxTextured.gltf";
    const std::filesystem::path embedded = kSamples / "BoxTextured-glTF-Embedded/BoxTextured.gltf";
    const std::filesystem::path binary = kSamples / "BoxTextured-glTF-Binary/BoxTextured.glb";
    const Mesh mesh = load_gltf_mesh(external);
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_EQ(mesh.textures[0].image->width, 211u);  // CesiumLogoFlat.png
    EXPECT_EQ(mesh.textures[0].wrap_u, TextureWrap::MirroredRepeat);
    EXPECT_EQ(mesh.textures[0].wrap_v, TextureWrap::ClampToEdge);
    for (const std::filesystem::path& file : {embedded, binary}) {
        const Mesh other = load_gltf_mesh(file);
        EXPECT_EQ(other.positions, mesh.positions) << file;
        EXPECT_EQ(other.uvs, mesh.uvs) << file;
        ASSERT_EQ(other.textures.size(), 1u) << file;
        EXPECT_EQ(other.textures[0].image->rgba, mesh.textures[0].image->rgba) << file;
        EXPECT_EQ(other.textures[0].wrap_u, TextureWrap::Repeat) << file;
    }
    const std::string transform = fitted(mesh, kUnderWater, 1.2, 30.0);
    Renderer renderer(context());
    const RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    std::vector<ImageRGBA32F> images;
    for (const std::filesystem::path& file : {external, embedded, binary}) {
        const Scene scene = sample_scene(file, kUnderWater, transform);
        images.push_back(renderer.render(scene, options).image);
        const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
        const UniformAgreement agreement = compare_uniform(images.back(), reference);
        // The logo's flat areas and the box's white: thousands of uniform pixels, in at least four
        // colours (untextured, the box would show one per lit face, three at most).
        EXPECT_GT(agreement.uniform, 1000) << file;
        EXPECT_GE(agreement.colours.size(), 4u) << file;
        EXPECT_EQ(agreement.disagreeing, 0) << file << agreement.examples;
        if (file == external) {
            // Untextured (white), the box's faces are far from the textured reference's colours.
            const Scene plain_scene = sample_scene(file, kUnderWater, transform, R"(, "texture": "none")");
            const RenderResult plain = renderer.render(plain_scene, options);
            EXPECT_GT(compare_uniform(plain.image, reference).disagreeing, agreement.uniform / 2);
        }
    }
    // The same model and sampler draw the same image, bit for bit; the mirrored wrap another one.
    EXPECT_EQ(images[1].rgba, images[2].rgba);
    EXPECT_NE(images[0].rgba, images[1].rgba);
}

// 2CylinderEngine: 34 materials over 82 nodes in a .glb. Its parts keep their own base colours
// (grey, orange, teal, red and blue ones) through the node transforms, in both renderers.
TEST_F(KhronosSamples, TheEnginesMaterialsStayApartInBothRenderers) {
    ASSERT_TRUE(std::filesystem::exists(kSamples)) << kSamples << " is missing: run tools/install-deps.sh";
    const std::filesystem::path file = kSamples / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    const Mesh mesh = load_gltf_mesh(file);
    std::vector<glm::dvec3> colours;  // the file's distinct base colours
    for (const MeshPart& part : mesh.parts) {
        if (std::find(colours.begin(), colours.end(), part.base_color) == colours.end())
            colours.push_back(part.base_color);
    }
    EXPECT_EQ(colours.size(), 7u);  // 0.85 grey, black, orange, teal, red, light blue, blue
    // Above the water: under it, the real-time flat-surface stand-in lights every receiver without the
    // other meshes' shadows (docs/model.md section 4), and the engine's parts shadow each other.
    const Scene scene = sample_scene(file, kAboveWater, fitted(mesh, kAboveWater, 1.6, 30.0));
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const UniformAgreement agreement = compare_uniform(real_time.image, reference);
    EXPECT_GT(agreement.uniform, 1000);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.examples;
    // Lit by the sky alone, a part above the water shows its base colour times the sky's radiance
    // (L = rho pi L_sky / pi). Count the base colours that some real-time pixel shows within the
    // fp32 shading's 1e-5 relative (the receiver tests'): from this camera, five of the six that are
    // not black, each part in its own material's colour (one colour for the file would show one).
    std::set<std::size_t> seen;
    for (int y = 0; y < int(kHeight); ++y) {
        for (int x = 0; x < int(kWidth); ++x) {
            const float* pixel = real_time.image.pixel(x, y);
            if (std::max({pixel[0], pixel[1], pixel[2]}) <= kLitRadiance) continue;
            for (std::size_t k = 0; k < colours.size(); ++k) {
                bool match = true;
                for (int c = 0; c < 3 && match; ++c) {
                    const double expected = colours[k][c] * scene.sky.radiance[c];
                    match = std::abs(pixel[c] - expected) <= 1e-5 * std::max(expected, 1e-3);
                }
                if (match) seen.insert(k);
            }
        }
    }
    EXPECT_GE(seen.size(), 5u);
}

}  // namespace
}  // namespace vkw::test
