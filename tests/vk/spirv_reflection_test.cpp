// The reflection of compiled shaders from the build tree: the bindings each entry point uses,
// with their descriptor types and counts, its stage, and its push-constant block's size.
#include "engine/vk/spirv_reflection.hpp"
#include "engine/core/errors.hpp"
#include "engine/vk/shader_module.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

// The file as ShaderModule reads it; reflection needs no device.
ReflectedStage reflect_file(const std::string& file) {
    std::ifstream in(shader_directory() / file, std::ios::binary | std::ios::ate);
    EXPECT_TRUE(in) << file << " is not built";
    std::vector<uint32_t> words(static_cast<size_t>(in.tellg()) / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
    return reflect_spirv(words, file);
}

struct Expected {
    uint32_t set, binding;
    VkDescriptorType type;
    uint32_t count;
};

void expect_bindings(const ReflectedStage& stage, const std::vector<Expected>& expected) {
    ASSERT_EQ(stage.bindings.size(), expected.size()) << stage.shader;
    for (size_t i = 0; i < expected.size(); ++i) {
        const ReflectedBinding& b = stage.bindings[i];
        EXPECT_EQ(b.set, expected[i].set) << stage.shader << " #" << i;
        EXPECT_EQ(b.binding, expected[i].binding) << stage.shader << " #" << i;
        EXPECT_EQ(descriptor_type_name(b.type), descriptor_type_name(expected[i].type)) << stage.shader << " #" << i;
        EXPECT_EQ(b.count, expected[i].count) << stage.shader << " #" << i;
    }
}

TEST(SpirvReflection, SkyFrameVariantUsesTheFrameConstantsOnly) {
    const ReflectedStage sky = reflect_file("sky/sky.frag.frame.spv");
    EXPECT_EQ(sky.stage, VK_SHADER_STAGE_FRAGMENT_BIT);
    expect_bindings(sky, {{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}});
    EXPECT_EQ(sky.push_constant_bytes, 0u);
}

TEST(SpirvReflection, SkyPerPixelVariantAlsoReadsTheCameraMediumMask) {
    const ReflectedStage sky = reflect_file("sky/sky.frag.per_pixel.spv");
    expect_bindings(
        sky, {{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}, {0, 3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}});
}

TEST(SpirvReflection, GodrayBlurComputeShader) {
    const ReflectedStage blur = reflect_file("godrays/godray_blur.comp.spv");
    EXPECT_EQ(blur.stage, VK_SHADER_STAGE_COMPUTE_BIT);
    expect_bindings(blur, {{0, 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                           {0, 2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                           {0, 3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}});
    EXPECT_EQ(blur.push_constant_bytes, 8u);  // ivec2 step
}

TEST(SpirvReflection, FullscreenVertexShaderUsesNothing) {
    const ReflectedStage vertex = reflect_file("common/fullscreen.vert.spv");
    EXPECT_EQ(vertex.stage, VK_SHADER_STAGE_VERTEX_BIT);
    EXPECT_TRUE(vertex.bindings.empty());
    EXPECT_EQ(vertex.push_constant_bytes, 0u);
}

TEST(SpirvReflection, EveryResourceKindOfTheProbe) {
    const ReflectedStage probe = reflect_file("tests/reflection_probe.comp.plain.spv");
    EXPECT_EQ(probe.shader, "tests/reflection_probe.comp.plain.spv");
    // Binding 8 is declared in the GLSL (and kept in the SPIR-V) but never read: not used.
    expect_bindings(probe, {{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                            {0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                            {0, 2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3},
                            {0, 3, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1},
                            {0, 4, VK_DESCRIPTOR_TYPE_SAMPLER, 1},
                            {0, 5, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                            {0, 6, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1},
                            {0, 7, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, 1}});
    EXPECT_EQ(probe.push_constant_bytes, 20u);  // vec4 + float, no tail padding
}

TEST(SpirvReflection, OtherSetIsReported) {
    const ReflectedStage probe = reflect_file("tests/reflection_probe.comp.other_set.spv");
    ASSERT_FALSE(probe.bindings.empty());
    EXPECT_EQ(probe.bindings.back().set, 1u);
    EXPECT_EQ(probe.bindings.back().binding, 0u);
    EXPECT_EQ(probe.bindings.back().type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

TEST(SpirvReflection, NotSpirvThrowsNamingTheShader) {
    try {
        reflect_spirv({0x12345678u, 0u, 0u, 0u, 0u}, "broken.comp.spv");
        FAIL() << "no throw";
    } catch (const InternalError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.comp.spv"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vkw::test
