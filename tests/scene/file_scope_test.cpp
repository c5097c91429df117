// Files a scene names stay inside the scene file's folder tree unless the user allows otherwise:
// the glTF receiver itself, the buffers it names (as written, %XX-escaped, absolute, or through a
// symbolic link), each refused in one line that names the file, the field and the way out.
#include <gtest/gtest.h>

#include "engine/scene/file_scope.hpp"
#include "engine/scene/gltf_mesh.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/gltf_test_files.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

constexpr const char* kRefusal = "resolves outside the scene's folder";

std::string scene_with_gltf(const std::string& file) {
    return R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
        "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
        "receivers": [{ "type": "gltf", "file": ")" +
           file + R"(" }] })";
}

TEST(scene_file_scope, AReceiverOutsideTheSceneFolderIsRefusedUnlessAllowed) {
    const std::filesystem::path dir = test::scratch_dir("scope_receiver");
    std::filesystem::create_directories(dir / "scenes");
    std::filesystem::create_directories(dir / "models");
    test::write_text(dir / "models/pyramid.gltf", test::gltf_text(test::pyramid()));
    const std::filesystem::path scene_file =
        test::write_text(dir / "scenes/scene.json", scene_with_gltf("../models/pyramid.gltf"));

    const std::string message = test::user_error_of([&] { load_scene(scene_file); });
    EXPECT_EQ(message, scene_file.string() + ": receivers[0].file: the glTF file '../models/pyramid.gltf' " + kRefusal +
                           " '" + std::filesystem::canonical(dir / "scenes").string() +
                           "' (accepted: a path inside it, or --allow-outside-paths)");
    const Scene scene = load_scene(scene_file, {}, {.allow_outside_paths = true});
    ASSERT_EQ(scene.receivers.size(), 1u);
    EXPECT_EQ(scene.receivers[0].mesh.indices.size(), 18u);

    // ".." that comes back inside the tree is inside.
    std::filesystem::create_directories(dir / "scenes/sub");
    test::write_text(dir / "scenes/sub/pyramid.gltf", test::gltf_text(test::pyramid()));
    EXPECT_EQ(load_scene(test::write_text(dir / "scenes/back.json", scene_with_gltf("sub/../sub/pyramid.gltf")))
                  .receivers[0]
                  .mesh.indices.size(),
              18u);
}

TEST(scene_file_scope, BufferUrisOutsideTheSceneFolderAreRefused) {
    const std::filesystem::path dir = test::scratch_dir("scope_buffer");
    std::filesystem::create_directories(dir / "scene/data");
    const std::filesystem::path scene_file = test::write_text(dir / "scene/scene.json", scene_with_gltf("mesh.gltf"));
    const auto load_with_buffer = [&](const std::string& uri, const std::filesystem::path& bin_file, bool allow) {
        test::write_text(dir / "scene/mesh.gltf", test::gltf_text_with_buffer_file(test::pyramid(), uri, bin_file));
        return load_scene(scene_file, {}, {.allow_outside_paths = allow}).receivers[0].mesh.indices.size();
    };
    // Inside: loads; outside and allowed: loads.
    EXPECT_EQ(load_with_buffer("data/mesh.bin", dir / "scene/data/mesh.bin", false), 18u);
    EXPECT_EQ(load_with_buffer("../outside.bin", dir / "outside.bin", true), 18u);

    const std::string outside_bin = (dir / "outside.bin").string();
    for (const std::string& uri : {std::string("../outside.bin"), std::string("%2E%2E/outside.bin"), outside_bin,
                                   std::string("data/../../outside.bin")}) {
        SCOPED_TRACE(uri);
        const std::string message = test::user_error_of([&] { load_with_buffer(uri, outside_bin, false); });
        EXPECT_NE(message.find("receivers[0].file: glTF file '"), std::string::npos) << message;
        EXPECT_NE(message.find("': buffers[0].uri '" + uri + "' " + kRefusal), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
        // Allowed, the scope says nothing (tinygltf 2.7 then opens some of these forms and not others).
        std::string allowed_message;
        try {
            load_with_buffer(uri, outside_bin, true);
        } catch (const UserError& error) {
            allowed_message = error.what();
        }
        EXPECT_EQ(allowed_message.find(kRefusal), std::string::npos) << allowed_message;
    }
}

TEST(scene_file_scope, ASymbolicLinkInsideThatPointsOutsideIsOutside) {
    const std::filesystem::path dir = test::scratch_dir("scope_link");
    std::filesystem::create_directories(dir / "scene");
    std::filesystem::create_directories(dir / "elsewhere");
    test::write_text(dir / "elsewhere/pyramid.gltf", test::gltf_text(test::pyramid()));
    std::filesystem::create_directory_symlink(dir / "elsewhere", dir / "scene/linked");
    const std::filesystem::path scene_file =
        test::write_text(dir / "scene/scene.json", scene_with_gltf("linked/pyramid.gltf"));
    EXPECT_NE(test::user_error_of([&] { load_scene(scene_file); }).find(kRefusal), std::string::npos);
    EXPECT_EQ(load_scene(scene_file, {}, {.allow_outside_paths = true}).receivers[0].mesh.indices.size(), 18u);
}

TEST(scene_file_scope, UriEscapesAreDecodedAsTinygltfDoes) {
    EXPECT_EQ(decode_uri_escapes("%2E%2e/a%20b.bin"), "../a b.bin");
    EXPECT_EQ(decode_uri_escapes("100%"), "100%");    // a cut escape is kept as written
    EXPECT_EQ(decode_uri_escapes("%zz%4"), "%zz%4");  // so is a malformed one
    EXPECT_EQ(decode_uri_escapes("plain.bin"), "plain.bin");
}

}  // namespace
}  // namespace vkw
