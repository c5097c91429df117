#include "engine/vk/pipeline.hpp"

#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/resources.hpp"
#include "engine/vk/shader_module.hpp"
#include "engine/vk/spirv_reflection.hpp"

#include <algorithm>
#include <iterator>
#include <memory>

namespace vkw {

namespace {

// A desc that leaves its layout empty gets the one its shaders ask for; a declared one is checked
// against them. Either way each binding gets the shaders' name for it.
PipelineLayoutDesc checked_or_derived_layout(const std::string& name, const PipelineLayoutDesc& declared,
                                             const std::vector<ReflectedStage>& stages) {
    PipelineLayoutDesc layout = declared;
    if (declared.bindings.empty() && declared.push_constant_bytes == 0) {
        layout = derive_pipeline_layout(name, stages);
    } else {
        check_pipeline_layout(name, declared, stages);
    }
    layout.names = name_layout_bindings(name, layout, stages);
    return layout;
}

}  // namespace

void Pipeline::create_layout(const Context& context, const PipelineLayoutDesc& desc, const std::string& name) {
    device_ = context.device();
    allocator_ = context.allocator();
    layout_desc_ = desc;
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    set_info.bindingCount = static_cast<uint32_t>(desc.bindings.size());
    set_info.pBindings = desc.bindings.data();
    VKW_CHECK(vkCreateDescriptorSetLayout(device_, &set_info, allocator_, &set_layout_),
              "set layout of '" + name + "'");
    context.set_name(set_layout_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, name);

    VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, desc.push_constant_bytes};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = desc.push_constant_bytes > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &range;
    VKW_CHECK(vkCreatePipelineLayout(device_, &layout_info, allocator_, &layout_), "layout of '" + name + "'");
    context.set_name(layout_, VK_OBJECT_TYPE_PIPELINE_LAYOUT, name);
}

Pipeline::Pipeline(const Context& context, const ComputePipelineDesc& desc, const std::string& name)
    : bind_point_(VK_PIPELINE_BIND_POINT_COMPUTE) {
    // The check comes before any object of this pipeline exists: a throw from a constructor
    // runs no destructor, so a layout made first would leak.
    ShaderModule shader(context, desc.shader);
    const ReflectedStage reflected = reflect_spirv(shader.words(), shader.file());
    create_layout(context, checked_or_derived_layout(name, desc.layout, {reflected}), name);
    std::copy(std::begin(reflected.local_size), std::end(reflected.local_size), local_size_.begin());
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = shader.handle();
    info.stage.pName = "main";
    info.layout = layout_;
    VKW_CHECK(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, allocator_, &pipeline_),
              "pipeline '" + name + "'");
    context.count_pipeline();
    context.set_name(pipeline_, VK_OBJECT_TYPE_PIPELINE, name);
}

Pipeline::Pipeline(const Context& context, const GraphicsPipelineDesc& desc, const std::string& name) {
    ShaderModule vertex(context, desc.vertex_shader);
    std::unique_ptr<ShaderModule> fragment;
    std::vector<ReflectedStage> reflected = {reflect_spirv(vertex.words(), vertex.file())};
    if (!desc.fragment_shader.empty()) {
        fragment = std::make_unique<ShaderModule>(context, desc.fragment_shader);
        reflected.push_back(reflect_spirv(fragment->words(), fragment->file()));
    }
    // Before the layout, as in the compute constructor: nothing is left to leak on a throw.
    create_layout(context, checked_or_derived_layout(name, desc.layout, reflected), name);

    // Both stages get every constant: constant_id i means the same in each, and a stage that
    // declares no constant i ignores its entry.
    std::vector<VkSpecializationMapEntry> constant_entries;
    for (uint32_t id = 0; id < desc.specialization_constants.size(); ++id) {
        constant_entries.push_back({id, id * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)});
    }
    VkSpecializationInfo specialization{};
    specialization.mapEntryCount = static_cast<uint32_t>(constant_entries.size());
    specialization.pMapEntries = constant_entries.data();
    specialization.dataSize = desc.specialization_constants.size() * sizeof(uint32_t);
    specialization.pData = desc.specialization_constants.data();
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
    stage.module = vertex.handle();
    stage.pName = "main";
    if (!constant_entries.empty()) stage.pSpecializationInfo = &specialization;
    stages.push_back(stage);
    if (fragment) {
        stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stage.module = fragment->handle();
        stages.push_back(stage);
    }

    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertex_bindings.size());
    vertex_input.pVertexBindingDescriptions = desc.vertex_bindings.data();
    vertex_input.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.vertex_attributes.size());
    vertex_input.pVertexAttributeDescriptions = desc.vertex_attributes.data();

    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = desc.topology;

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cull_mode;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    raster.depthClampEnable = desc.depth_clamp ? VK_TRUE : VK_FALSE;

    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depth_test;
    depth.depthWriteEnable = desc.depth_write;
    depth.depthCompareOp = desc.depth_compare;
    depth.stencilTestEnable = desc.stencil_test;
    depth.front = desc.stencil_front;
    depth.back = desc.stencil_back;

    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.color_formats.size());
    for (VkPipelineColorBlendAttachmentState& blend : blends) {
        blend.colorWriteMask =
            VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        if (desc.additive_blend) {
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.srcAlphaBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_ADD;
        }
    }
    VkPipelineColorBlendStateCreateInfo blend_state{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend_state.attachmentCount = static_cast<uint32_t>(blends.size());
    blend_state.pAttachments = blends.data();

    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamic_states;

    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = static_cast<uint32_t>(desc.color_formats.size());
    rendering.pColorAttachmentFormats = desc.color_formats.data();
    rendering.depthAttachmentFormat = format_is_depth(desc.depth_format) ? desc.depth_format : VK_FORMAT_UNDEFINED;
    rendering.stencilAttachmentFormat = format_has_stencil(desc.depth_format) ? desc.depth_format : VK_FORMAT_UNDEFINED;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = desc.render_pass ? nullptr : &rendering;
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend_state;
    info.pDynamicState = &dynamic;
    info.layout = layout_;
    info.renderPass = desc.render_pass;
    VKW_CHECK(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &info, allocator_, &pipeline_),
              "pipeline '" + name + "'");
    context.count_pipeline();
    context.set_name(pipeline_, VK_OBJECT_TYPE_PIPELINE, name);
}

Pipeline::~Pipeline() {
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, allocator_);
    if (layout_) vkDestroyPipelineLayout(device_, layout_, allocator_);
    if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, allocator_);
}

}  // namespace vkw
