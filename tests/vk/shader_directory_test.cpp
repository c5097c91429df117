// Where the SPIR-V is read from (engine/vk/shader_module.hpp): the environment first, then the
// folder an install puts beside the library or executable, then the build tree; so an installed
// vkwater never reads the build tree it was built in, even while that tree still exists.
#include "engine/vk/shader_module.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace {

class ShaderDirectory : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("vkwater_shader_dir_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_ / "prefix/lib");
        fs::create_directories(root_ / "prefix/share/vkwater/shaders");
        fs::create_directories(root_ / "build/shaders");
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

TEST_F(ShaderDirectory, TheEnvironmentWins) {
    EXPECT_EQ(vkw::shader_directory_among("/somewhere", root_ / "prefix/lib/libvkwater.so", root_ / "build/shaders"),
              fs::path("/somewhere"));
}

TEST_F(ShaderDirectory, AnInstalledLibraryReadsItsOwnPrefixNotTheBuildTree) {
    EXPECT_EQ(vkw::shader_directory_among(nullptr, root_ / "prefix/lib/libvkwater.so", root_ / "build/shaders"),
              root_ / "prefix/share/vkwater/shaders");
    EXPECT_EQ(vkw::shader_directory_among("", root_ / "prefix/bin/vkwater", root_ / "build/shaders"),
              root_ / "prefix/share/vkwater/shaders");
}

TEST_F(ShaderDirectory, AMultiarchLibraryFolderIsOneLevelDeeper) {
    EXPECT_EQ(vkw::shader_directory_among(nullptr, root_ / "prefix/lib/x86_64-linux-gnu/libvkwater.so",
                                          root_ / "build/shaders"),
              root_ / "prefix/share/vkwater/shaders");
}

TEST_F(ShaderDirectory, ABinaryInTheBuildTreeReadsTheBuildTree) {
    EXPECT_EQ(vkw::shader_directory_among(nullptr, root_ / "build/tools/vkwater/vkwater", root_ / "build/shaders"),
              root_ / "build/shaders");
}

TEST_F(ShaderDirectory, WithNeitherTheErrorNamesTheInstalledFolder) {
    EXPECT_EQ(vkw::shader_directory_among(nullptr, root_ / "elsewhere/bin/vkwater", root_ / "gone"),
              root_ / "elsewhere/share/vkwater/shaders");
}

}  // namespace
