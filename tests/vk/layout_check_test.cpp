// Pipelines created with a layout that does not provide what their SPIR-V uses throw one
// InternalError naming the pass, the shader and the binding, before any Vulkan object of the
// pipeline exists (the fixture fails on a leak at device destruction). Correct layouts, and
// the supersets Vulkan allows, create their pipelines with validation clean.
#include "engine/core/errors.hpp"
#include "engine/vk/pipeline.hpp"
#include "engine/vk/shader_module.hpp"
#include "engine/vk/spirv_reflection.hpp"
#include "tests/support/gpu_test.hpp"

#include <stdexcept>
#include <string>

namespace vkw::test {
namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// What reflection_probe.comp uses; bindings 3 and 4 (a separate texture and sampler) declared
// as combined image samplers, which Vulkan's type correspondence allows for both.
ComputePipelineDesc probe_desc() {
    ComputePipelineDesc desc;
    desc.shader = "tests/reflection_probe.comp.plain";
    desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kCompute},
                            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kCompute},
                            {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3, kCompute},
                            {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kCompute},
                            {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kCompute},
                            {5, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, kCompute},
                            {6, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1, kCompute},
                            {7, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, 1, kCompute}};
    desc.layout.push_constant_bytes = 20;
    return desc;
}

// The sky with the fullscreen triangle: binding 0, the frame constants, in the fragment stage.
GraphicsPipelineDesc sky_desc() {
    GraphicsPipelineDesc desc;
    desc.vertex_shader = "common/fullscreen.vert";
    desc.fragment_shader = "sky/sky.frag.frame";
    desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
    desc.color_formats = {VK_FORMAT_R16G16B16A16_SFLOAT};
    return desc;
}

VkDescriptorSetLayoutBinding& binding(PipelineLayoutDesc& layout, uint32_t number) {
    for (VkDescriptorSetLayoutBinding& b : layout.bindings) {
        if (b.binding == number) return b;
    }
    throw std::logic_error("no binding " + std::to_string(number));
}

class LayoutCheck : public GpuTest {
protected:
    // The message the pipeline's creation threw; empty when it was created.
    template <class Desc>
    std::string creation_error(const Desc& desc, const std::string& pass) {
        try {
            Pipeline pipeline(context(), desc, pass);
            EXPECT_NE(pipeline.handle(), VK_NULL_HANDLE);
            return {};
        } catch (const InternalError& e) {
            return e.what();
        }
    }
};

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST_F(LayoutCheck, CorrectLayoutsCreateTheirPipelines) {
    EXPECT_EQ(creation_error(probe_desc(), "probe"), "");
    EXPECT_EQ(creation_error(sky_desc(), "sky"), "");
}

TEST_F(LayoutCheck, SupersetsAreAllowedAndTheUnusedBindingsCounted) {
    // Binding 8 is declared in the GLSL but never read, binding 9 not at all; a larger array
    // and stageFlags beyond the stage are supersets too.
    ComputePipelineDesc desc = probe_desc();
    desc.layout.bindings.push_back({8, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kCompute});
    desc.layout.bindings.push_back({9, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kCompute});
    binding(desc.layout, 2).descriptorCount = 4;
    binding(desc.layout, 0).stageFlags = VK_SHADER_STAGE_ALL;
    EXPECT_EQ(creation_error(desc, "probe superset"), "");
    const ShaderModule shader(context(), desc.shader);
    const std::vector<VkDescriptorSetLayoutBinding> unused =
        check_pipeline_layout("probe superset", desc.layout, {reflect_spirv(shader.words(), shader.file())});
    ASSERT_EQ(unused.size(), 2u);
    EXPECT_EQ(unused[0].binding, 8u);
    EXPECT_EQ(unused[1].binding, 9u);
}

TEST_F(LayoutCheck, WrongDescriptorTypeNamesPassShaderAndBothTypes) {
    ComputePipelineDesc desc = probe_desc();
    binding(desc.layout, 1).descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    const std::string error = creation_error(desc, "probe pass");
    EXPECT_CONTAINS(error,
                    "pipeline 'probe pass' (tests/reflection_probe.comp.plain.spv): binding 1 is storage "
                    "buffer x1 in the shader but uniform buffer x1 in the declared layout");
    // Both layouts follow, whole.
    EXPECT_CONTAINS(error, "declared set 0 {0: uniform buffer x1 compute, 1: uniform buffer x1 compute");
    EXPECT_CONTAINS(error, "SPIR-V compute uses {0: uniform buffer x1, 1: storage buffer x1");
}

TEST_F(LayoutCheck, SampledImageDeclaredAsStorageImageThrows) {
    ComputePipelineDesc desc = probe_desc();
    binding(desc.layout, 3).descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    EXPECT_CONTAINS(creation_error(desc, "probe"),
                    "binding 3 is sampled image x1 in the shader but storage image x1 in the declared layout");
}

TEST_F(LayoutCheck, MissingBindingThrows) {
    ComputePipelineDesc desc = probe_desc();
    desc.layout.bindings.erase(desc.layout.bindings.begin() + 5);  // binding 5
    EXPECT_CONTAINS(creation_error(desc, "probe"),
                    "pipeline 'probe' (tests/reflection_probe.comp.plain.spv): "
                    "binding 5 is storage image x1 in the shader but is not in the "
                    "declared layout");
}

TEST_F(LayoutCheck, SmallerArrayThrows) {
    ComputePipelineDesc desc = probe_desc();
    binding(desc.layout, 2).descriptorCount = 2;
    EXPECT_CONTAINS(creation_error(desc, "probe"),
                    "binding 2 is combined image sampler x3 in the shader but "
                    "combined image sampler x2 in the declared layout");
}

TEST_F(LayoutCheck, OtherSetThrows) {
    ComputePipelineDesc desc = probe_desc();
    desc.shader = "tests/reflection_probe.comp.other_set";
    EXPECT_CONTAINS(creation_error(desc, "probe"),
                    "(tests/reflection_probe.comp.other_set.spv): set 1 binding 0 "
                    "is storage buffer x1 in the shader but the declared layout has "
                    "only set 0");
}

TEST_F(LayoutCheck, WrongPushConstantSizeThrows) {
    ComputePipelineDesc desc = probe_desc();
    desc.layout.push_constant_bytes = 32;  // the block as a C++ struct with alignas(16) members
    EXPECT_CONTAINS(creation_error(desc, "probe"),
                    "pipeline 'probe' (tests/reflection_probe.comp.plain.spv): the "
                    "push-constant block is 20 bytes in the shader but 32 bytes in "
                    "the declared layout");
    desc.layout.push_constant_bytes = 0;
    EXPECT_CONTAINS(creation_error(desc, "probe"), "is 20 bytes in the shader but 0 bytes in the declared layout");
}

TEST_F(LayoutCheck, StagesMayDeclareALeadingPartOfThePushBlock) {
    // water_surface.vert declares the water's whole block (108 bytes); the sky's fragment shader
    // declares none of it, a leading part of length 0. The longest block must be the whole range.
    GraphicsPipelineDesc desc = sky_desc();
    desc.vertex_shader = "water/water_surface.vert";
    const VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both},
                            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}};
    desc.layout.push_constant_bytes = 108;
    EXPECT_EQ(creation_error(desc, "water prefix"), "");
    desc.layout.push_constant_bytes = 112;
    EXPECT_CONTAINS(creation_error(desc, "water prefix"),
                    "pipeline 'water prefix' (water/water_surface.vert.spv): the push-constant block is 108 "
                    "bytes in the shader (the longest of the pipeline's stages) but 112 bytes in the declared layout");
}

TEST_F(LayoutCheck, GraphicsPipelineNamesTheFragmentShader) {
    GraphicsPipelineDesc desc = sky_desc();
    // A declared layout (so it is checked, not derived) that lacks the shader's binding 0.
    desc.layout.bindings = {{5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
    EXPECT_CONTAINS(creation_error(desc, "sky"),
                    "pipeline 'sky' (sky/sky.frag.frame.spv): binding 0 is uniform "
                    "buffer x1 in the shader but is not in the declared layout");
}

// An empty layout is the one the shaders ask for: the probe's eight bindings with their own types
// (3 and 4 the separate texture and sampler, not combined), its array's count, visible to the
// compute stage, and its 20-byte block; the sky's frame constants, visible to the
// fragment stage alone (the fullscreen triangle's vertex shader reads nothing).
TEST_F(LayoutCheck, AnEmptyLayoutIsDerivedFromTheShaders) {
    ComputePipelineDesc probe = probe_desc();
    const PipelineLayoutDesc declared = probe.layout;
    probe.layout = {};
    const Pipeline compute(context(), probe, "derived probe");
    ASSERT_EQ(compute.layout_desc().bindings.size(), declared.bindings.size());
    for (size_t i = 0; i < declared.bindings.size(); ++i) {
        const VkDescriptorSetLayoutBinding& got = compute.layout_desc().bindings[i];
        EXPECT_EQ(got.binding, declared.bindings[i].binding);
        const VkDescriptorType own = got.binding == 3   ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                                     : got.binding == 4 ? VK_DESCRIPTOR_TYPE_SAMPLER
                                                        : declared.bindings[i].descriptorType;
        EXPECT_EQ(got.descriptorType, own) << got.binding;
        EXPECT_EQ(got.descriptorCount, declared.bindings[i].descriptorCount) << got.binding;
        EXPECT_EQ(got.stageFlags, VkShaderStageFlags(VK_SHADER_STAGE_COMPUTE_BIT));
    }
    EXPECT_EQ(compute.layout_desc().push_constant_bytes, 20u);
    GraphicsPipelineDesc sky = sky_desc();
    sky.layout = {};
    const Pipeline graphics(context(), sky, "derived sky");
    ASSERT_EQ(graphics.layout_desc().bindings.size(), 1u);
    EXPECT_EQ(graphics.layout_desc().bindings[0].binding, 0u);
    EXPECT_EQ(graphics.layout_desc().bindings[0].descriptorType, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(graphics.layout_desc().bindings[0].stageFlags, VkShaderStageFlags(VK_SHADER_STAGE_FRAGMENT_BIT));
    EXPECT_EQ(graphics.layout_desc().push_constant_bytes, 0u);
}

TEST_F(LayoutCheck, StageMissingFromStageFlagsThrows) {
    GraphicsPipelineDesc desc = sky_desc();
    desc.layout.bindings[0].stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
    EXPECT_CONTAINS(creation_error(desc, "sky"),
                    "pipeline 'sky' (sky/sky.frag.frame.spv): binding 0 (uniform "
                    "buffer x1) is used by the fragment stage but the declared "
                    "layout's stageFlags are vertex");
}

}  // namespace
}  // namespace vkw::test
