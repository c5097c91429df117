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

TEST(SpirvReflection, BindingsCarryTheShadersNames) {
    // A block is named by its type (`Flux` in `buffer Flux { ... };`, also where the block has an
    // instance name: `Constants` in `uniform Constants { ... } constants;`), any other resource by
    // its variable: the names passes declare their resources under.
    const ReflectedStage probe = reflect_file("tests/reflection_probe.comp.plain.spv");
    std::vector<std::string> names;
    for (const ReflectedBinding& b : probe.bindings) names.push_back(b.name);
    EXPECT_EQ(names, (std::vector<std::string>{"Constants", "Values", "textures", "separate_texture",
                                               "separate_sampler", "storage", "texels", "storage_texels"}));
    const ReflectedStage blur = reflect_file("godrays/godray_blur.comp.spv");
    ASSERT_EQ(blur.bindings.size(), 3u);
    EXPECT_EQ(blur.bindings[0].name, "source");
    EXPECT_EQ(blur.bindings[2].name, "target");
}

TEST(SpirvReflection, ComputeStagesCarryTheirWorkgroupSize) {
    const ReflectedStage blur = reflect_file("godrays/godray_blur.comp.spv");  // local_size_x = local_size_y = 8
    EXPECT_EQ(std::vector<uint32_t>(std::begin(blur.local_size), std::end(blur.local_size)),
              (std::vector<uint32_t>{8, 8, 1}));
    // local_size_x = kGroupSize, a constant of 64 (not a specialization constant).
    const ReflectedStage fft = reflect_file("water/ocean_fft.comp.spv");
    EXPECT_EQ(std::vector<uint32_t>(std::begin(fft.local_size), std::end(fft.local_size)),
              (std::vector<uint32_t>{64, 1, 1}));
    const ReflectedStage sky = reflect_file("sky/sky.frag.frame.spv");
    EXPECT_EQ(std::vector<uint32_t>(std::begin(sky.local_size), std::end(sky.local_size)),
              (std::vector<uint32_t>{1, 1, 1}));
}

// Two stages of one pipeline, as reflect_spirv would give them, using `a` and `b` at binding 0.
std::vector<ReflectedStage> two_stages(const std::string& a, const std::string& b) {
    ReflectedStage vertex{"v.spv", VK_SHADER_STAGE_VERTEX_BIT, {{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, a}}};
    ReflectedStage fragment{"f.spv", VK_SHADER_STAGE_FRAGMENT_BIT, {{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, b}}};
    return {vertex, fragment};
}

TEST(SpirvReflection, LayoutBindingsTakeTheStagesCommonName) {
    const std::vector<ReflectedStage> stages = two_stages("FrameConstants", "FrameConstants");
    const PipelineLayoutDesc layout = derive_pipeline_layout("p", stages);
    EXPECT_EQ(name_layout_bindings("p", layout, stages), std::vector<std::string>{"FrameConstants"});
}

TEST(SpirvReflection, StagesNamingOneBindingDifferentlyThrow) {
    const std::vector<ReflectedStage> stages = two_stages("FrameConstants", "Frame");
    const PipelineLayoutDesc layout = derive_pipeline_layout("p", stages);
    try {
        name_layout_bindings("p", layout, stages);
        FAIL() << "no throw";
    } catch (const InternalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("binding 0 is 'Frame'"), std::string::npos) << what;
        EXPECT_NE(what.find("'FrameConstants'"), std::string::npos) << what;
    }
}

TEST(SpirvReflection, TwoBindingsOfOneNameThrow) {
    ReflectedStage stage{
        "c.spv",
        VK_SHADER_STAGE_COMPUTE_BIT,
        {{0, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, "Flux"}, {0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, "Flux"}}};
    const PipelineLayoutDesc layout = derive_pipeline_layout("p", {stage});
    EXPECT_THROW(name_layout_bindings("p", layout, {stage}), InternalError);
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
