// glTF base colour textures and vertex colours as the loader hands them to both renderers: the
// image decoded texel for texel, the sampler's modes, the texture coordinates (with
// KHR_texture_transform), COLOR_0, the limits, and the receiver's `texture` and `albedo` fields.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/scene/gltf_mesh.hpp"
#include "engine/scene/gltf_texture.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/gltf_textured_square.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

using test::TexturedSquare;

std::filesystem::path write_square(const std::string& name, const TexturedSquare& square) {
    const std::filesystem::path dir = test::scratch_dir(name);
    return test::write_text(dir / "square.gltf", test::textured_square_text(square));
}

TEST(scene_gltf_texture, TheImageIsDecodedTexelForTexelWithItsCoordinates) {
    const TexturedSquare square;
    const Mesh mesh = load_gltf_mesh(write_square("texture_decoded", square));
    ASSERT_EQ(mesh.textures.size(), 1u);
    const TextureImage& image = *mesh.textures[0].image;
    EXPECT_EQ(image.width, 2u);
    EXPECT_EQ(image.height, 2u);
    EXPECT_EQ(image.rgba, square.rgba);  // PNG is lossless
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].texture, 0);
    ASSERT_EQ(mesh.uvs.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {  // u = (x + 1) / 2, v = (z + 1) / 2, exactly
        EXPECT_EQ(mesh.uvs[i], glm::vec2((mesh.positions[i].x + 1.0f) / 2.0f, (mesh.positions[i].z + 1.0f) / 2.0f));
    }
    EXPECT_TRUE(mesh.colors.empty());
    // Without a sampler: repeat, trilinear.
    EXPECT_EQ(mesh.textures[0].wrap_u, TextureWrap::Repeat);
    EXPECT_TRUE(mesh.textures[0].magnify_linear && mesh.textures[0].minify_linear && mesh.textures[0].mipmaps &&
                mesh.textures[0].mipmap_linear);
    EXPECT_TRUE(mesh.warnings.empty());
}

TEST(scene_gltf_texture, TheSamplersModesAreKept) {
    TexturedSquare square;
    square.sampler = R"({ "magFilter": 9728, "minFilter": 9984, "wrapS": 33071, "wrapT": 33648 })";
    const Mesh nearest = load_gltf_mesh(write_square("texture_sampler", square));
    ASSERT_EQ(nearest.textures.size(), 1u);
    const MeshTexture& texture = nearest.textures[0];
    EXPECT_EQ(texture.wrap_u, TextureWrap::ClampToEdge);
    EXPECT_EQ(texture.wrap_v, TextureWrap::MirroredRepeat);
    EXPECT_FALSE(texture.magnify_linear);
    EXPECT_FALSE(texture.minify_linear);
    EXPECT_TRUE(texture.mipmaps);
    EXPECT_FALSE(texture.mipmap_linear);
    square.sampler = R"({ "minFilter": 9729 })";  // LINEAR: the base level alone
    const Mesh base_level = load_gltf_mesh(write_square("texture_sampler_linear", square));
    EXPECT_TRUE(base_level.textures[0].minify_linear);
    EXPECT_FALSE(base_level.textures[0].mipmaps);
    square.sampler = R"({ "wrapS": 1234 })";
    const std::string error = test::user_error_of([&] { load_gltf_mesh(write_square("texture_bad_wrap", square)); });
    EXPECT_NE(error.find("samplers[0].wrapS 1234 is not a glTF wrap mode"), std::string::npos) << error;
}

// The extension's own example: offset (0, 1), rotation pi/2, scale 0.5 maps (u, v) to
// (0, 1) + R (0.5 u, 0.5 v) with R's columns (cos, sin) and (-sin, cos): (-0.5 v, 1 + 0.5 u).
TEST(scene_gltf_texture, KhrTextureTransformMapsTheCoordinates) {
    TexturedSquare square;
    square.texture_info_extra =
        R"("extensions": { "KHR_texture_transform": { "offset": [0, 1], "rotation": 1.57079632679, "scale": [0.5, 0.5] } }, )";
    square.top_extra =
        R"( "extensionsUsed": ["KHR_texture_transform"], "extensionsRequired": ["KHR_texture_transform"],)";
    const Mesh mesh = load_gltf_mesh(write_square("texture_transform", square));
    ASSERT_EQ(mesh.uvs.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        const double u = (mesh.positions[i].x + 1.0) / 2.0, v = (mesh.positions[i].z + 1.0) / 2.0;
        // Double arithmetic stored as float: half an ulp of values up to 1.5 (6e-8), and cos(pi/2)
        // of the rounded angle (5e-12).
        EXPECT_NEAR(mesh.uvs[i].x, -0.5 * v, 1e-7) << "vertex " << i;
        EXPECT_NEAR(mesh.uvs[i].y, 1.0 + 0.5 * u, 1e-7) << "vertex " << i;
    }
}

TEST(scene_gltf_texture, VertexColoursAreKeptAsLinearRgba) {
    TexturedSquare square;
    square.colors = {255, 0, 0, 255, 0, 255, 0, 51, 0, 0, 255, 255, 51, 102, 153, 255};
    const Mesh mesh = load_gltf_mesh(write_square("vertex_colours", square));
    ASSERT_EQ(mesh.colors.size(), 4u);
    EXPECT_EQ(mesh.colors[0], glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    // Normalised bytes, linear as glTF defines COLOR_0: 51 / 255 = 0.2 (float rounding of a double).
    EXPECT_EQ(mesh.colors[1], glm::vec4(0.0f, 1.0f, 0.0f, float(51 / 255.0)));
    EXPECT_EQ(mesh.colors[3], glm::vec4(float(51 / 255.0), float(102 / 255.0), float(153 / 255.0), 1.0f));
}

// alphaMode MASK makes the part a cutout at alphaCutoff (glTF's default 0.5), with the factor's
// alpha; BLEND stays opaque, with its warning; a cutoff outside [0, 1] is refused.
TEST(scene_gltf_texture, MaskMaterialsAreCutouts) {
    TexturedSquare square;
    square.base_color_factor = "[1, 1, 1, 0.8]";
    square.material_extra = R"("alphaMode": "MASK", "alphaCutoff": 0.25, )";
    const Mesh cutout = load_gltf_mesh(write_square("mask", square));
    ASSERT_EQ(cutout.parts.size(), 1u);
    EXPECT_EQ(cutout.parts[0].alpha, 0.8);
    EXPECT_EQ(cutout.parts[0].alpha_cutoff, 0.25);
    EXPECT_TRUE(cutout.warnings.empty());
    square.material_extra = R"("alphaMode": "MASK", )";
    EXPECT_EQ(load_gltf_mesh(write_square("mask_default", square)).parts[0].alpha_cutoff, 0.5);
    square.material_extra = R"("alphaMode": "BLEND", )";
    const Mesh blend = load_gltf_mesh(write_square("blend", square));
    EXPECT_LT(blend.parts[0].alpha_cutoff, 0.0);
    ASSERT_EQ(blend.warnings.size(), 1u);
    EXPECT_NE(blend.warnings[0].find("alphaMode BLEND (drawn opaque)"), std::string::npos) << blend.warnings[0];
    square.material_extra = R"("alphaMode": "MASK", "alphaCutoff": 1.5, )";
    const std::string error = test::user_error_of([&] { load_gltf_mesh(write_square("mask_bad", square)); });
    EXPECT_NE(error.find("materials[0].alphaCutoff 1.5 (accepted: 0 to 1)"), std::string::npos) << error;
}

TEST(scene_gltf_texture, ImagesBeyondTheLimitsOrUndecodableAreRefusedNamingThem) {
    TexturedSquare wide;
    wide.width = kMaxTextureSide + 1;
    wide.height = 1;
    wide.rgba.assign(4 * std::size_t(wide.width), 200);
    const std::string error = test::user_error_of([&] { load_gltf_mesh(write_square("texture_wide", wide)); });
    EXPECT_NE(error.find("images[0]: 8193 x 1 texels (accepted: 1 to 8192 per side)"), std::string::npos) << error;
    // Bytes that are no image: a data URI of text.
    std::string text = test::textured_square_text(TexturedSquare{});
    const std::size_t begin = text.find("data:image/png;base64,") + std::string("data:image/png;base64,").size();
    text.replace(begin, text.find('"', begin) - begin, test::base64({'n', 'o', 't', ' ', 'a', 'n', ' ', 'i'}));
    const std::filesystem::path file = test::write_text(test::scratch_dir("texture_garbage") / "g.gltf", text);
    const std::string garbage = test::user_error_of([&] { load_gltf_mesh(file); });
    EXPECT_NE(garbage.find("images[0]: not an image stb_image decodes"), std::string::npos) << garbage;
}

// Only base colour images are decoded: a normal map that is not an image at all costs nothing.
TEST(scene_gltf_texture, ImagesNoBaseColourUsesAreNotDecoded) {
    TexturedSquare square;
    square.top_extra = R"( "extras": {},)";
    std::string text = test::textured_square_text(square);
    // A second texture and image, used as the material's normal map only.
    text.replace(text.find(R"("textures": [{ "source": 0 }])"), std::string(R"("textures": [{ "source": 0 }])").size(),
                 R"("textures": [{ "source": 0 }, { "source": 1 }])");
    const std::string images = R"("images": [)";
    text.insert(text.find(images) + images.size(), R"({ "uri": "data:image/png;base64,bm90IGFuIGltYWdl" }, )");
    // The inserted image is images[0] now: point the base colour's texture at images[1].
    text.replace(text.find(R"("textures": [{ "source": 0 }, { "source": 1 }])"),
                 std::string(R"("textures": [{ "source": 0 }, { "source": 1 }])").size(),
                 R"("textures": [{ "source": 1 }, { "source": 0 }])");
    text.replace(text.find(R"("baseColorTexture")"), 0, R"("metallicFactor": 0, )");
    text.replace(text.find(R"("materials": [{ )") + std::string(R"("materials": [{ )").size(), 0,
                 R"("normalTexture": { "index": 1 }, )");
    const std::filesystem::path file = test::write_text(test::scratch_dir("texture_normal_map") / "n.gltf", text);
    const Mesh mesh = load_gltf_mesh(file);
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_EQ(mesh.textures[0].image->width, 2u);
}

TEST(scene_gltf_texture, ATextureWithoutItsCoordinatesIsDrawnUntexturedWithAWarning) {
    TexturedSquare square;
    square.texture_info_extra = R"("texCoord": 1, )";
    const Mesh mesh = load_gltf_mesh(write_square("texture_no_coordinates", square));
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].texture, -1);
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0],
              "base colour texture without its coordinates, drawn untextured: meshes[0], primitive 0 (no TEXCOORD_1)");
}

TEST(scene_gltf_texture, TheReceiversTextureAndAlbedoFieldsDecide) {
    TexturedSquare square;
    square.colors = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 51, 102, 153, 255};
    const std::filesystem::path file = write_square("texture_receiver_fields", square);
    const auto scene_with = [&](const std::string& fields) {
        return parse_scene(
            R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] }, "sun": { "elevation_deg": 45 },
          "sky": { "radiance": [0.3, 0.4, 0.5] },
          "receivers": [{ "type": "gltf", "file": "square.gltf")" +
                fields + " }] }",
            file.parent_path() / "scene.json");
    };
    const Mesh textured = scene_with("").receivers[0].mesh;
    EXPECT_EQ(textured.textures.size(), 1u);
    EXPECT_EQ(textured.parts[0].texture, 0);
    const Mesh untextured = scene_with(R"(, "texture": "none")").receivers[0].mesh;
    EXPECT_TRUE(untextured.textures.empty());
    EXPECT_EQ(untextured.parts[0].texture, -1);
    EXPECT_EQ(untextured.colors.size(), 4u);  // the vertex colours stay: they are not the texture
    const Mesh painted = scene_with(R"(, "albedo": [0.3, 0.3, 0.3])").receivers[0].mesh;
    EXPECT_TRUE(painted.textures.empty());
    EXPECT_TRUE(painted.parts.empty());
    EXPECT_TRUE(painted.colors.empty());
}

}  // namespace
}  // namespace vkw
