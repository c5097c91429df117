// A shader variant is asked for by its source and the macros it defines; its file follows from the
// table the build writes from shaders/CMakeLists.txt. These check the table against the build tree
// and the names it gives against the files the build made.
#include "engine/vk/shader_variant.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/shader_module.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <utility>

namespace vkw::test {
namespace {

TEST(ShaderVariants, EveryFileOfTheTableIsBuilt) {
    ASSERT_GT(compiled_shaders().size(), 100u);  // the receiver shader alone has 48 variants
    for (const CompiledShader& shader : compiled_shaders()) {
        EXPECT_TRUE(std::filesystem::exists(shader_directory() / (shader.file + ".spv"))) << shader.file;
    }
}

TEST(ShaderVariants, NoTwoFilesShareASourceAndItsMacros) {
    std::set<std::pair<std::string, std::set<std::string>>> keys;
    for (const CompiledShader& shader : compiled_shaders()) {
        EXPECT_TRUE(keys.insert({shader.source, shader.defines}).second) << shader.file;
    }
}

TEST(ShaderVariants, TheMacrosNameTheFile) {
    // The names shaders/CMakeLists.txt gives these variants.
    EXPECT_EQ(ShaderVariant{"receivers/receiver.frag"}
                  .define("VKWATER_CAUSTICS")
                  .define("VKWATER_PER_PIXEL_MEDIUM")
                  .define("VKWATER_SUN_SHADOW", false)
                  .file(),
              "receivers/receiver.frag.per_pixel_caustics");
    EXPECT_EQ(ShaderVariant{"sky/sky.frag"}.file(), "sky/sky.frag.frame");
    EXPECT_EQ(ShaderVariant{"caustics/caustic_photons.comp"}
                  .define("VKWATER_SPLAT_ADAPTIVE")
                  .define("VKWATER_SUN_SHADOW")
                  .file(),
              "caustics/caustic_photons.comp.adaptive_shadow");
    EXPECT_EQ(ShaderVariant{"godrays/godray_blur.comp"}.file(), "godrays/godray_blur.comp");  // no variants
}

TEST(ShaderVariants, AVariantTheBuildDoesNotCompileThrowsNamingTheOnesItDoes) {
    try {
        (void)ShaderVariant{"sky/sky.frag"}.define("VKWATER_CAUSTICS").file();
        FAIL() << "no throw";
    } catch (const InternalError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "shader 'sky/sky.frag' is not compiled with the macros VKWATER_CAUSTICS (shaders/CMakeLists.txt); "
                  "its variants define:\n  VKWATER_INFINITE_WATER\n  none\n  VKWATER_INFINITE_WATER, "
                  "VKWATER_PER_PIXEL_MEDIUM\n  VKWATER_PER_PIXEL_MEDIUM");
    }
    EXPECT_THROW((void)ShaderVariant{"sky/no_such.frag"}.file(), InternalError);
}

}  // namespace
}  // namespace vkw::test
