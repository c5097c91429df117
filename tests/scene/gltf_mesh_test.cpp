// load_gltf_mesh on glTF files the test writes itself: counts, bounds, flat normals, strips,
// node transforms, materials, and the refusals (POINTS, LINES, missing file, malformed file,
// out-of-range index), then a glTF receiver resolved relative to its scene file.
#include <gtest/gtest.h>

#include "engine/scene/gltf_mesh.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/gltf_test_files.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

using test::GltfSpec;

std::filesystem::path write_gltf(const std::string& test_name, const GltfSpec& spec) {
    return test::write_text(test::scratch_dir(test_name) / "mesh.gltf", test::gltf_text(spec));
}

std::string load_error(const std::filesystem::path& file) {
    return test::user_error_of([&] { load_gltf_mesh(file); });
}

TEST(scene_gltf, IndexedMeshKeepsCountsAndBounds) {
    GltfSpec spec = test::pyramid();
    for (int v = 0; v < 5; ++v)
        spec.normals.insert(spec.normals.end(), {0.0f, 2.0f, 0.0f});  // normalised by the loader
    const Mesh mesh = load_gltf_mesh(write_gltf("indexed", spec));
    EXPECT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.normals.size(), 5u);
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(mesh.indices, std::vector<uint32_t>(spec.indices.begin(), spec.indices.end()));
    EXPECT_EQ(mesh.bounds_min, glm::dvec3(-1.0, 0.0, -1.0));
    EXPECT_EQ(mesh.bounds_max, glm::dvec3(1.0, 2.0, 1.0));
    EXPECT_EQ(mesh.normals[3], glm::vec3(0.0f, 1.0f, 0.0f));
    ASSERT_EQ(mesh.parts.size(), 1u);  // no material: glTF's default white, over every index
    EXPECT_EQ(mesh.parts[0].base_color, glm::dvec3(1.0));
    EXPECT_EQ(mesh.parts[0].first_index, 0u);
    EXPECT_EQ(mesh.parts[0].index_count, 18u);
    EXPECT_EQ(mesh.parts[0].texture, -1);
    EXPECT_TRUE(mesh.textures.empty());
}

TEST(scene_gltf, MissingNormalsAreComputedFlatAndOutward) {
    const Mesh mesh = load_gltf_mesh(write_gltf("flat", test::pyramid()));
    ASSERT_EQ(mesh.positions.size(), 18u);  // 3 per triangle
    ASSERT_EQ(mesh.indices.size(), 18u);
    const glm::dvec3 centre(0.0, 0.5, 0.0);
    for (std::size_t t = 0; t < 6; ++t) {
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
            c(mesh.positions[mesh.indices[3 * t + 2]]);
        const glm::dvec3 n(mesh.normals[mesh.indices[3 * t]]);
        EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
        EXPECT_GT(glm::dot(n, (a + b + c) / 3.0 - centre), 0.0) << "triangle " << t;
        EXPECT_NEAR(glm::dot(n, glm::normalize(glm::cross(b - a, c - a))), 1.0, 1e-6) << "triangle " << t;
    }
    EXPECT_EQ(mesh.bounds_max, glm::dvec3(1.0, 2.0, 1.0));
}

TEST(scene_gltf, StripsAndFansBecomeCounterClockwiseLists) {
    GltfSpec strip;  // a unit square in y = 0, as a strip of two triangles, facing +y
    strip.positions = {0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1};
    strip.mode = 5;
    const Mesh from_strip = load_gltf_mesh(write_gltf("strip", strip));
    GltfSpec fan = strip;
    fan.positions = {0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0};
    fan.mode = 6;
    const Mesh from_fan = load_gltf_mesh(write_gltf("fan", fan));
    for (const Mesh* mesh : {&from_strip, &from_fan}) {
        ASSERT_EQ(mesh->indices.size(), 6u);
        for (const glm::vec3& n : mesh->normals) EXPECT_EQ(n, glm::vec3(0.0f, 1.0f, 0.0f));
    }
}

TEST(scene_gltf, NodeTransformAndMaterialAreApplied) {
    GltfSpec spec = test::pyramid();
    spec.node_extra = R"("translation": [10, 0, 0], "scale": [2, 2, 2], )";
    spec.material = R"({ "pbrMetallicRoughness": { "baseColorFactor": [0.25, 0.5, 0.75, 1] } })";
    const std::filesystem::path file = write_gltf("transform", spec);
    const Mesh mesh = load_gltf_mesh(file);
    EXPECT_EQ(mesh.bounds_min, glm::dvec3(8.0, 0.0, -2.0));
    EXPECT_EQ(mesh.bounds_max, glm::dvec3(12.0, 4.0, 2.0));
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].base_color, glm::dvec3(0.25, 0.5, 0.75));
}

// Each primitive keeps its own material's base colour, applied once; primitives of one colour
// share a part.
TEST(scene_gltf, EachPrimitiveKeepsItsMaterialsColour) {
    const std::filesystem::path dir = test::scratch_dir("two_materials");
    const std::string grey = R"({ "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1] } })";
    const std::string blue = R"({ "pbrMetallicRoughness": { "baseColorFactor": [0.2, 0.4, 0.8, 1] } })";
    const Mesh two = load_gltf_mesh(test::write_text(dir / "two.gltf", test::two_material_squares(grey + ", " + blue)));
    ASSERT_EQ(two.parts.size(), 2u);
    EXPECT_EQ(two.parts[0].first_index, 0u);
    EXPECT_EQ(two.parts[0].index_count, 6u);
    EXPECT_EQ(two.parts[0].base_color, glm::dvec3(0.5));
    EXPECT_EQ(two.parts[1].first_index, 6u);
    EXPECT_EQ(two.parts[1].index_count, 6u);
    EXPECT_EQ(two.parts[1].base_color, glm::dvec3(0.2, 0.4, 0.8));
    // Flat normals: every triangle's three vertices are its own, and the parts still cover them.
    EXPECT_EQ(two.indices.size(), 12u);

    const Mesh same =
        load_gltf_mesh(test::write_text(dir / "same.gltf", test::two_material_squares(grey + ", " + grey)));
    ASSERT_EQ(same.parts.size(), 1u);
    EXPECT_EQ(same.parts[0].index_count, 12u);

    const std::string bright = R"({ "pbrMetallicRoughness": { "baseColorFactor": [1.5, 0.4, 0.8, 1] } })";
    const std::filesystem::path bad =
        test::write_text(dir / "bad.gltf", test::two_material_squares(grey + ", " + bright));
    EXPECT_EQ(load_error(bad), "glTF file '" + bad.string() +
                                   "': materials[1].pbrMetallicRoughness.baseColorFactor [1.5, 0.4, 0.8] "
                                   "is not a valid albedo (accepted: each of r, g, b in [0, 1])");
}

// A .glb of `json` (padded with spaces to 4 bytes, as the format asks) and no binary chunk,
// declaring `version`.
std::filesystem::path write_glb(const std::string& test_name, std::string json, uint32_t version) {
    while (json.size() % 4 != 0) json += ' ';
    std::string bytes = "glTF";
    const auto word = [&](uint32_t value) { bytes.append(reinterpret_cast<const char*>(&value), 4); };
    word(version);
    word(uint32_t(20 + json.size()));
    word(uint32_t(json.size()));
    word(0x4E4F534Au);  // "JSON"
    bytes += json;
    return test::write_text(test::scratch_dir(test_name) / "mesh.glb", bytes);
}

TEST(scene_gltf, AGlbLoadsAndItsHeaderIsChecked) {
    const std::string json = test::gltf_text(test::pyramid());
    EXPECT_EQ(load_gltf_mesh(write_glb("glb", json, 2)).indices.size(), 18u);
    for (const uint32_t version : {1u, 99u}) {
        const std::filesystem::path file = write_glb("glb_version", json, version);
        EXPECT_EQ(load_error(file),
                  "glTF file '" + file.string() + "': .glb version " + std::to_string(version) + " (accepted: 2)");
    }
}

// Nesting that overflowed tinygltf's recursive parser (10^5 arrays in `extras`) is refused before
// it parses anything.
TEST(scene_gltf, DeepNestingIsRefusedBeforeParsing) {
    GltfSpec spec = test::pyramid();
    constexpr int kDepth = 100000;
    spec.top_extra = " \"extras\": " + std::string(kDepth, '[') + std::string(kDepth, ']') + ",";
    const std::filesystem::path file = write_gltf("deep", spec);
    EXPECT_EQ(load_error(file), "glTF file '" + file.string() + "': JSON nested " + std::to_string(kDepth + 1) +
                                    " levels deep (accepted: at most 64)");
}

// A required extension is named, not reported as the broken data it would have decoded.
TEST(scene_gltf, ARequiredExtensionIsRefusedByName) {
    GltfSpec spec = test::pyramid();
    spec.top_extra = R"( "extensionsUsed": ["KHR_draco_mesh_compression"],
                         "extensionsRequired": ["KHR_draco_mesh_compression"],)";
    const std::filesystem::path file = write_gltf("draco", spec);
    EXPECT_EQ(load_error(file), "glTF file '" + file.string() +
                                    "': needs the glTF extension 'KHR_draco_mesh_compression' (extensionsRequired), "
                                    "which vkwater does not support (accepted: KHR_texture_transform)");
}

// Sizes whose products or sums wrap around 2^64 are refused, not read outside the buffer (an
// accessor count of 2^61 + 1 once read far past it; ASan saw the read), and so are offsets.
TEST(scene_gltf, AccessorSizesThatWrapAreRefused) {
    std::string text = test::gltf_text(test::pyramid());
    const std::string count = R"("count": 5,)";
    ASSERT_NE(text.find(count), std::string::npos);
    text.replace(text.find(count), count.size(), R"("count": 2305843009213693953,)");
    const std::filesystem::path file = test::write_text(test::scratch_dir("wrap") / "mesh.gltf", text);
    const std::string message = load_error(file);
    EXPECT_TRUE(message.starts_with("glTF file '" + file.string() + "': ")) << message;
    EXPECT_NE(message.find("reaches past the end of its buffer"), std::string::npos) << message;

    // A bufferView offset of 2^64 - 16 once read 16 bytes before the buffer and exited 0.
    text = test::gltf_text(test::pyramid());
    const std::string offset = R"("byteOffset": 0, "byteLength")";
    ASSERT_NE(text.find(offset), std::string::npos);
    text.replace(text.find(offset), offset.size(), R"("byteOffset": 18446744073709551600, "byteLength")");
    const std::filesystem::path before = test::write_text(test::scratch_dir("wrap_offset") / "mesh.gltf", text);
    const std::string before_message = load_error(before);
    EXPECT_TRUE(before_message.starts_with("glTF file '" + before.string() + "': ")) << before_message;
    EXPECT_NE(before_message.find("reaches past the end of its buffer"), std::string::npos) << before_message;
}

// What tinygltf accepted: a NUL byte after the JSON, a data URI of another MIME type, base64
// without its padding.
TEST(scene_gltf, NulBytesAndMalformedDataUrisAreRefused) {
    const std::string text = test::gltf_text(test::pyramid());
    const std::filesystem::path dir = test::scratch_dir("data_uris");
    const std::filesystem::path nul = test::write_text(dir / "nul.gltf", text + std::string(1, '\0'));
    EXPECT_EQ(load_error(nul), "glTF file '" + nul.string() + "': a NUL byte at byte " + std::to_string(text.size()) +
                                   " of the JSON (glTF JSON is UTF-8 text)");

    std::string mime = text;
    const std::string type = "data:application/octet-stream;base64,";
    ASSERT_NE(mime.find(type), std::string::npos);
    mime.replace(mime.find(type), type.size(), "data:text/plain;base64,");
    const std::filesystem::path wrong_type = test::write_text(dir / "mime.gltf", mime);
    EXPECT_EQ(load_error(wrong_type),
              "glTF file '" + wrong_type.string() +
                  "': buffers[0].uri: a data URI starting 'data:text/plain;base64' (accepted: "
                  "data:application/octet-stream;base64, or data:application/gltf-buffer;base64,)");

    // The pyramid's buffer is 60 + 36 = 96 bytes, 128 base64 digits with no padding: drop one.
    std::string unpadded = text;
    const std::size_t end = unpadded.find("\" }] }");
    ASSERT_NE(end, std::string::npos);
    unpadded.erase(end - 1, 1);
    const std::filesystem::path short_payload = test::write_text(dir / "unpadded.gltf", unpadded);
    EXPECT_EQ(load_error(short_payload), "glTF file '" + short_payload.string() +
                                             "': buffers[0].uri: the data URI's base64 is malformed (127 characters; "
                                             "accepted: A-Z a-z 0-9 + /, padded with = to a multiple of 4)");
}

// Points and lines have no surface to light: skipped with one warning naming them; a file of
// nothing else has no triangles, and an unknown mode is malformed.
TEST(scene_gltf, PointsAndLinesAreSkippedWithOneWarningNamingThem) {
    GltfSpec spec = test::pyramid();
    spec.second_mode = 1;  // LINES
    const Mesh mesh = load_gltf_mesh(write_gltf("with-lines", spec));
    EXPECT_EQ(mesh.indices.size(), 18u);  // the pyramid's 6 triangles alone
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0], "skipped, not triangles: mesh 'Test' (meshes[0]), primitive 1 (LINES)");

    spec.second_mode = -1;
    spec.mode = 0;
    const std::filesystem::path points = write_gltf("points", spec);
    EXPECT_EQ(load_error(points), "glTF file '" + points.string() +
                                      "': contains no triangles (skipped, not triangles: mesh 'Test' (meshes[0]), "
                                      "primitive 0 (POINTS))");
    spec.mode = 7;
    const std::filesystem::path unknown = write_gltf("mode7", spec);
    EXPECT_EQ(load_error(unknown), "glTF file '" + unknown.string() +
                                       "': mesh 'Test' (meshes[0]), primitive 0: mode 7 is not a glTF primitive mode "
                                       "(accepted: 0 to 6; drawn: TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN)");
}

// One line per material that asks for what a Lambertian receiver leaves out, and one each for
// skins and morph targets (drawn in the bind pose and the base shape).
TEST(scene_gltf, LeftOutMaterialFeaturesSkinsAndMorphTargetsAreWarnings) {
    GltfSpec spec = test::pyramid();
    spec.material = R"({ "name": "Chrome", "pbrMetallicRoughness": { "metallicFactor": 1.0 },
      "emissiveFactor": [1, 0, 0], "alphaMode": "BLEND", "extensions": { "KHR_materials_clearcoat": {} } })";
    spec.node_extra = R"("skin": 0, )";
    spec.top_extra = R"( "skins": [{ "joints": [0] }],)";
    spec.primitive_extra = R"("targets": [{ "POSITION": 0 }], )";
    const Mesh mesh = load_gltf_mesh(write_gltf("left-out", spec));
    ASSERT_EQ(mesh.warnings.size(), 3u);
    EXPECT_EQ(mesh.warnings[0],
              "materials[0] 'Chrome': drawn as Lambertian (metallicFactor 1); ignored: emissiveFactor, alphaMode "
              "BLEND (drawn opaque), KHR_materials_clearcoat");
    EXPECT_EQ(mesh.warnings[1], "skins ignored, drawn in the bind pose: nodes[0]");
    EXPECT_EQ(mesh.warnings[2], "morph targets ignored, drawn in the base shape: mesh 'Test' (meshes[0]), primitive 0");

    // A dielectric, opaque, plain material is drawn as written: no warning.
    GltfSpec plain = test::pyramid();
    plain.material = R"({ "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0 } })";
    EXPECT_TRUE(load_gltf_mesh(write_gltf("plain", plain)).warnings.empty());
}

TEST(scene_gltf, MissingAndMalformedFilesAreRefusedNamingThePath) {
    const std::filesystem::path missing = test::scratch_dir("missing") / "nothing.gltf";
    EXPECT_EQ(load_error(missing), "cannot open glTF file '" + missing.string() + "': No such file or directory");
    const std::filesystem::path malformed = test::write_text(test::scratch_dir("malformed") / "bad.gltf", "{ not json");
    const std::string message = load_error(malformed);
    EXPECT_TRUE(message.starts_with("glTF file '" + malformed.string() + "': malformed glTF")) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(scene_gltf, OutOfRangeIndexIsRefused) {
    GltfSpec spec = test::pyramid();
    spec.indices[4] = 9;
    EXPECT_NE(load_error(write_gltf("bad_index", spec)).find("primitive 0: index 9 >= vertex count 5"),
              std::string::npos);
}

TEST(scene_gltf, ReceiverFileIsRelativeToTheSceneFile) {
    const std::filesystem::path dir = test::scratch_dir("receiver");
    std::filesystem::create_directories(dir / "assets");
    test::write_text(dir / "assets/pyramid.gltf", test::gltf_text(test::pyramid()));
    const std::string scene_text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
        "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
        "receivers": [{ "type": "gltf", "file": "assets/pyramid.gltf", "translation": [0, -1, 0], "albedo": [0.2, 0.3, 0.4] },
                      { "type": "gltf", "file": "assets/none.gltf" }] })";
    const std::filesystem::path scene_file = test::write_text(dir / "scene.json", scene_text);
    const std::string message = test::user_error_of([&] { load_scene(scene_file); });
    EXPECT_EQ(message, scene_file.string() + ": receivers[1].file: cannot open glTF file '" +
                           (dir / "assets/none.gltf").string() + "': No such file or directory");

    const Scene scene = load_scene(scene_file, {"receivers[1]=null"});
    ASSERT_EQ(scene.receivers.size(), 1u);
    const Receiver& receiver = scene.receivers[0];
    EXPECT_EQ(receiver.name, "receivers[0]");
    EXPECT_EQ(receiver.albedo, glm::dvec3(0.2, 0.3, 0.4));  // given: replaces the material's white
    EXPECT_TRUE(receiver.mesh.parts.empty());
    const std::vector<MeshPart> parts = receiver_albedo_parts(receiver);
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].base_color, glm::dvec3(0.2, 0.3, 0.4));
    EXPECT_EQ(parts[0].index_count, 18u);
    EXPECT_EQ(receiver.mesh.bounds_min, glm::dvec3(-1.0, -1.0, -1.0));
    EXPECT_EQ(receiver.mesh.bounds_max, glm::dvec3(1.0, 1.0, 1.0));
}

// A vertex that is NaN (or beyond the scene's lengths) is refused when the scene places the mesh:
// one line naming the receiver's file. It used to reach the GPU and exit 2.
TEST(scene_gltf, ANonFiniteVertexIsRefusedNamingTheFile) {
    GltfSpec spec;
    spec.positions = {0, 0, 0, 1, 0, 0, 0, 0, 1};
    const std::filesystem::path mesh = write_gltf("nan_vertex", spec);
    std::string text = test::gltf_text(spec);
    // The first position's x as NaN: its bytes in the base64 buffer, 00 00 c0 7f.
    const std::string zero_x = test::base64({0, 0, 0, 0, 0, 0});
    const std::string nan_x = test::base64({0, 0, 0xc0, 0x7f, 0, 0});
    ASSERT_EQ(text.find(zero_x.substr(0, 8)), text.find("base64,") + 7);
    text.replace(text.find("base64,") + 7, 8, nan_x.substr(0, 8));
    test::write_text(mesh, text);
    const std::filesystem::path scene_file = test::write_text(mesh.parent_path() / "scene.json", R"({
        "camera": { "position": [0, 1, 3], "target": [0, 0, 0] }, "sun": { "elevation_deg": 45 },
        "sky": { "radiance": [0.3, 0.4, 0.5] },
        "receivers": [{ "type": "gltf", "file": "mesh.gltf" }] })");
    const std::string message = test::user_error_of([&] { load_scene(scene_file); });
    EXPECT_NE(message.find("receivers[0].file: the mesh holds a vertex that is not a finite number"), std::string::npos)
        << message;
}

}  // namespace
}  // namespace vkw
