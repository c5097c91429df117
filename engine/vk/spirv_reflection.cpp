#include "engine/vk/spirv_reflection.hpp"

#include "engine/core/errors.hpp"

#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace vkw {
namespace {

// One SPIRV-Cross context per reflection: it owns every object the C API hands out, and its
// error callback keeps the last message for the exception.
struct SpvcContext {
    spvc_context handle = nullptr;
    std::string last_error;
    SpvcContext() {
        if (spvc_context_create(&handle) != SPVC_SUCCESS) throw InternalError("SPIRV-Cross: no context");
        spvc_context_set_error_callback(
            handle, [](void* self, const char* error) { static_cast<SpvcContext*>(self)->last_error = error; }, this);
    }
    ~SpvcContext() { spvc_context_destroy(handle); }
    SpvcContext(const SpvcContext&) = delete;
    SpvcContext& operator=(const SpvcContext&) = delete;
};

VkShaderStageFlagBits stage_of(SpvExecutionModel model, const std::string& shader) {
    switch (model) {
        case SpvExecutionModelVertex: return VK_SHADER_STAGE_VERTEX_BIT;
        case SpvExecutionModelTessellationControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
        case SpvExecutionModelTessellationEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
        case SpvExecutionModelGeometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
        case SpvExecutionModelFragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
        case SpvExecutionModelGLCompute: return VK_SHADER_STAGE_COMPUTE_BIT;
        default:
            throw InternalError("shader '" + shader + "': execution model " + std::to_string(model) +
                                " has no Vulkan stage vkwater uses");
    }
}

// The descriptor type a resource of SPIRV-Cross's kind needs. Images and texel buffers are both
// OpTypeImage; the dimension tells them apart.
VkDescriptorType descriptor_type_of(spvc_resource_type kind, spvc_type type) {
    switch (kind) {
        case SPVC_RESOURCE_TYPE_UNIFORM_BUFFER: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case SPVC_RESOURCE_TYPE_STORAGE_BUFFER: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case SPVC_RESOURCE_TYPE_SAMPLED_IMAGE:
            return spvc_type_get_image_dimension(type) == SpvDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                                       : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case SPVC_RESOURCE_TYPE_SEPARATE_IMAGE:
            return spvc_type_get_image_dimension(type) == SpvDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                                       : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case SPVC_RESOURCE_TYPE_STORAGE_IMAGE:
            return spvc_type_get_image_dimension(type) == SpvDimBuffer ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                                                       : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS: return VK_DESCRIPTOR_TYPE_SAMPLER;
        case SPVC_RESOURCE_TYPE_SUBPASS_INPUT: return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
        case SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE: return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
        default: return VK_DESCRIPTOR_TYPE_MAX_ENUM;
    }
}

// Descriptors in a resource: the product of its array sizes. A size may be a specialization
// constant (its default value is what a pipeline without specialization info gets); a runtime
// array counts as 1, the least a layout must provide.
uint32_t descriptor_count_of(spvc_compiler compiler, spvc_type type) {
    uint32_t count = 1;
    for (unsigned i = 0; i < spvc_type_get_num_array_dimensions(type); ++i) {
        uint32_t size = spvc_type_get_array_dimension(type, i);
        if (!spvc_type_array_dimension_is_literal(type, i)) {
            size = spvc_constant_get_scalar_u32(spvc_compiler_get_constant_handle(compiler, size), 0, 0);
        }
        count *= std::max<uint32_t>(size, 1);
    }
    return count;
}

std::string stage_name(VkShaderStageFlags stage) {
    static const std::pair<VkShaderStageFlags, const char*> kNames[] = {
        {VK_SHADER_STAGE_VERTEX_BIT, "vertex"},
        {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, "tessellation control"},
        {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, "tessellation evaluation"},
        {VK_SHADER_STAGE_GEOMETRY_BIT, "geometry"},
        {VK_SHADER_STAGE_FRAGMENT_BIT, "fragment"},
        {VK_SHADER_STAGE_COMPUTE_BIT, "compute"},
    };
    if ((stage & VK_SHADER_STAGE_ALL) == VK_SHADER_STAGE_ALL) return "all";
    std::string text;
    for (const auto& [bit, name] : kNames) {
        if (stage & bit) text += (text.empty() ? "" : "|") + std::string(name);
    }
    return text.empty() ? "none" : text;
}

std::string binding_text(VkDescriptorType type, uint32_t count) {
    return descriptor_type_name(type) + " x" + std::to_string(count);
}

std::string declared_text(const PipelineLayoutDesc& declared) {
    std::vector<VkDescriptorSetLayoutBinding> bindings = declared.bindings;
    std::sort(bindings.begin(), bindings.end(), [](const auto& a, const auto& b) { return a.binding < b.binding; });
    std::string text = "declared set 0 {";
    for (size_t i = 0; i < bindings.size(); ++i) {
        text += (i ? ", " : "") + std::to_string(bindings[i].binding) + ": " +
                binding_text(bindings[i].descriptorType, bindings[i].descriptorCount) + " " +
                stage_name(bindings[i].stageFlags);
    }
    return text + "}, push " + std::to_string(declared.push_constant_bytes) + " bytes";
}

std::string reflected_text(const ReflectedStage& stage) {
    std::string text = "SPIR-V " + stage_name(stage.stage) + " uses {";
    for (size_t i = 0; i < stage.bindings.size(); ++i) {
        const ReflectedBinding& b = stage.bindings[i];
        text += (i ? ", " : "") + (b.set ? "set " + std::to_string(b.set) + " " : std::string()) +
                std::to_string(b.binding) + ": " + binding_text(b.type, b.count);
    }
    return text + "}, push " + std::to_string(stage.push_constant_bytes) + " bytes";
}

// Vulkan's correspondence of shader resources and descriptor types: an OpTypeImage that is
// sampled, or an OpTypeSampler, may be written as a combined image sampler (the descriptor's
// unused half is ignored). Every other resource takes exactly its own type.
bool type_serves(VkDescriptorType declared, VkDescriptorType used) {
    if (declared == used) return true;
    return declared == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER &&
           (used == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE || used == VK_DESCRIPTOR_TYPE_SAMPLER);
}

// The layout's entry for binding `number` (const or not), or its end.
template <class Bindings>
auto find_binding(Bindings& bindings, uint32_t number) {
    return std::find_if(bindings.begin(), bindings.end(),
                        [&](const VkDescriptorSetLayoutBinding& d) { return d.binding == number; });
}

std::string outside_set_zero(const ReflectedBinding& b) {
    return "set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) + " is " +
           binding_text(b.type, b.count);
}

std::mutex records_mutex;
std::map<std::string, LayoutCheckRecord>& records() {
    static std::map<std::string, LayoutCheckRecord> by_pass;
    return by_pass;
}

// Keeps a pipeline's figures for layout_check_records.
void record_layout(const std::string& pass, uint32_t push_bytes, const std::vector<ReflectedStage>& stages,
                   std::vector<VkDescriptorSetLayoutBinding> unused) {
    LayoutCheckRecord record;
    record.pass = pass;
    record.declared_push_bytes = push_bytes;
    for (const ReflectedStage& stage : stages) {
        record.shaders.push_back(stage.shader);
        record.shader_push_bytes.push_back(stage.push_constant_bytes);
    }
    record.unused = std::move(unused);
    std::lock_guard lock(records_mutex);
    records()[pass] = std::move(record);
}

}  // namespace

std::string descriptor_type_name(VkDescriptorType type) {
    switch (type) {
        case VK_DESCRIPTOR_TYPE_SAMPLER: return "sampler";
        case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "combined image sampler";
        case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "sampled image";
        case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
        case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER: return "uniform texel buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER: return "storage texel buffer";
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC: return "dynamic uniform buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC: return "dynamic storage buffer";
        case VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT: return "input attachment";
        case VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR: return "acceleration structure";
        default: return "descriptor type " + std::to_string(static_cast<int>(type));
    }
}

ReflectedStage reflect_spirv(const std::vector<uint32_t>& words, const std::string& shader) {
    SpvcContext context;
    const auto fail = [&](const char* what) {
        throw InternalError("shader '" + shader + "': SPIRV-Cross could not " + what +
                            (context.last_error.empty() ? "" : " (" + context.last_error + ")"));
    };
    spvc_parsed_ir ir = nullptr;
    if (spvc_context_parse_spirv(context.handle, words.data(), words.size(), &ir) != SPVC_SUCCESS) fail("parse it");
    spvc_compiler compiler = nullptr;
    if (spvc_context_create_compiler(context.handle, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) != SPVC_SUCCESS) {
        fail("reflect it");
    }

    ReflectedStage stage;
    stage.shader = shader;
    stage.stage = stage_of(spvc_compiler_get_execution_model(compiler), shader);

    if (stage.stage == VK_SHADER_STAGE_COMPUTE_BIT) {
        for (uint32_t axis = 0; axis < 3; ++axis) {
            stage.local_size[axis] =
                spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, axis);
        }
    }

    // Only what the entry point statically uses: that is what Vulkan requires the layout to
    // provide, and a variant that compiles a read out may still declare the binding.
    spvc_set active = nullptr;
    spvc_resources resources = nullptr;
    if (spvc_compiler_get_active_interface_variables(compiler, &active) != SPVC_SUCCESS ||
        spvc_compiler_create_shader_resources_for_active_variables(compiler, &resources, active) != SPVC_SUCCESS) {
        fail("list its resources");
    }
    static const spvc_resource_type kDescriptorKinds[] = {
        SPVC_RESOURCE_TYPE_UNIFORM_BUFFER,    SPVC_RESOURCE_TYPE_STORAGE_BUFFER,
        SPVC_RESOURCE_TYPE_SUBPASS_INPUT,     SPVC_RESOURCE_TYPE_STORAGE_IMAGE,
        SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,     SPVC_RESOURCE_TYPE_SEPARATE_IMAGE,
        SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE,
    };
    for (spvc_resource_type kind : kDescriptorKinds) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        if (spvc_resources_get_resource_list_for_type(resources, kind, &list, &count) != SPVC_SUCCESS) {
            fail("list its descriptors");
        }
        for (size_t i = 0; i < count; ++i) {
            const spvc_type type = spvc_compiler_get_type_handle(compiler, list[i].type_id);
            ReflectedBinding binding;
            binding.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
            binding.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
            binding.type = descriptor_type_of(kind, type);
            binding.count = descriptor_count_of(compiler, type);
            binding.name = list[i].name ? list[i].name : "";
            stage.bindings.push_back(binding);
        }
    }
    std::sort(stage.bindings.begin(), stage.bindings.end(),
              [](const auto& a, const auto& b) { return std::pair(a.set, a.binding) < std::pair(b.set, b.binding); });

    // The push-constant block as declared, read or not: its size is what the C++ struct must
    // match, in a variant that compiles its reads out too.
    spvc_resources declared = nullptr;
    const spvc_reflected_resource* push = nullptr;
    size_t push_count = 0;
    if (spvc_compiler_create_shader_resources(compiler, &declared) != SPVC_SUCCESS ||
        spvc_resources_get_resource_list_for_type(declared, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &push, &push_count) !=
            SPVC_SUCCESS) {
        fail("list its push constants");
    }
    if (push_count > 0) {
        // The declared size runs to the end of the last member (std430 offsets, no tail padding).
        const spvc_type block = spvc_compiler_get_type_handle(compiler, push[0].base_type_id);
        size_t size = 0;
        if (spvc_compiler_get_declared_struct_size(compiler, block, &size) != SPVC_SUCCESS) {
            fail("size its push-constant block");
        }
        stage.push_constant_bytes = static_cast<uint32_t>(size);
    }
    return stage;
}

// The rules, and why each holds for every pipeline Pipeline makes:
// - Only set 0 exists: Pipeline makes one push-descriptor set layout and nothing else, so a
//   binding in another set would be read with no descriptor behind it.
// - Every binding a stage statically uses must be declared in set 0, with a descriptor type that
//   can serve it (its own; or a combined image sampler for a separate sampled image or sampler,
//   as Vulkan's shader-resource/descriptor-type correspondence allows), a count no smaller than
//   the shader's array (the shader may index any element), and stageFlags that include the stage
//   (descriptors are visible only to the stages named). Any of these wrong is undefined
//   behaviour, caught today only when the validation layer runs.
// - No stage's push-constant block may be longer than push_constant_bytes: the pass pushes that
//   many bytes, so the rest would be read unset (and Vulkan requires the range to cover it).
// - The longest block of the pipeline's stages must be exactly push_constant_bytes: the bytes are
//   the pass's C++ struct, and a struct longer than every block means the two have drifted apart
//   (a member added on one side only, or tail padding in the struct, which would hide exactly
//   that drift the day a member is added to the GLSL). A stage may declare a shorter block, the
//   leading members it reads: water_surface.vert declares only the grid resolution, the first
//   4 bytes of the fragment shader's 64. Sizes alone miss a member moved inside the block: the
//   members' offsets are not compared.
// - Bindings declared but used by no stage are allowed: shader variants compile reads out while
//   the pass keeps one layout for all of them, and Vulkan allows a layout that is a superset.
//   They are returned, so that they can be counted.
std::vector<VkDescriptorSetLayoutBinding> check_pipeline_layout(const std::string& pass,
                                                                const PipelineLayoutDesc& declared,
                                                                const std::vector<ReflectedStage>& stages) {
    std::vector<bool> used(declared.bindings.size(), false);
    for (const ReflectedStage& stage : stages) {
        const auto fail = [&](const std::string& what) {
            throw InternalError("pipeline '" + pass + "' (" + stage.shader + "): " + what + " [" +
                                declared_text(declared) + "; " + reflected_text(stage) + "]");
        };
        for (const ReflectedBinding& b : stage.bindings) {
            const std::string shader_side = binding_text(b.type, b.count);
            if (b.set != 0) fail(outside_set_zero(b) + " in the shader but the declared layout has only set 0");
            const auto it = find_binding(declared.bindings, b.binding);
            const std::string name = "binding " + std::to_string(b.binding);
            if (it == declared.bindings.end()) {
                fail(name + " is " + shader_side + " in the shader but is not in the declared layout");
            }
            const std::string declared_side = binding_text(it->descriptorType, it->descriptorCount);
            if (!type_serves(it->descriptorType, b.type) || it->descriptorCount < b.count) {
                fail(name + " is " + shader_side + " in the shader but " + declared_side + " in the declared layout");
            }
            if ((it->stageFlags & stage.stage) == 0) {
                fail(name + " (" + shader_side + ") is used by the " + stage_name(stage.stage) +
                     " stage but the declared layout's stageFlags are " + stage_name(it->stageFlags));
            }
            used[static_cast<size_t>(it - declared.bindings.begin())] = true;
        }
        if (stage.push_constant_bytes > declared.push_constant_bytes) {
            fail("the push-constant block is " + std::to_string(stage.push_constant_bytes) +
                 " bytes in the shader but " + std::to_string(declared.push_constant_bytes) +
                 " bytes in the declared layout");
        }
    }
    const auto longest = std::max_element(stages.begin(), stages.end(), [](const auto& a, const auto& b) {
        return a.push_constant_bytes < b.push_constant_bytes;
    });
    const uint32_t longest_bytes = longest == stages.end() ? 0 : longest->push_constant_bytes;
    if (longest_bytes != declared.push_constant_bytes) {
        const std::string shader = longest == stages.end() ? std::string("no shader") : longest->shader;
        throw InternalError(
            "pipeline '" + pass + "' (" + shader + "): the push-constant block is " + std::to_string(longest_bytes) +
            " bytes in the shader" + (stages.size() > 1 ? " (the longest of the pipeline's stages)" : "") + " but " +
            std::to_string(declared.push_constant_bytes) + " bytes in the declared layout [" + declared_text(declared) +
            (longest == stages.end() ? "" : "; " + reflected_text(*longest)) + "]");
    }

    std::vector<VkDescriptorSetLayoutBinding> unused;
    for (size_t i = 0; i < declared.bindings.size(); ++i) {
        if (!used[i]) unused.push_back(declared.bindings[i]);
    }
    record_layout(pass, declared.push_constant_bytes, stages, unused);
    return unused;
}

PipelineLayoutDesc derive_pipeline_layout(const std::string& pass, const std::vector<ReflectedStage>& stages) {
    PipelineLayoutDesc layout;
    for (const ReflectedStage& stage : stages) {
        const auto fail = [&](const std::string& what) {
            throw InternalError("pipeline '" + pass + "' (" + stage.shader + "): " + what + " [" +
                                reflected_text(stage) + "]");
        };
        for (const ReflectedBinding& b : stage.bindings) {
            const std::string shader_side = binding_text(b.type, b.count);
            if (b.set != 0) fail(outside_set_zero(b) + ": a pipeline has one descriptor set, set 0");
            const auto it = find_binding(layout.bindings, b.binding);
            if (it == layout.bindings.end()) {
                layout.bindings.push_back({b.binding, b.type, b.count, static_cast<VkShaderStageFlags>(stage.stage)});
                continue;
            }
            if (it->descriptorType != b.type) {
                fail("binding " + std::to_string(b.binding) + " is " + shader_side + " in this stage but " +
                     binding_text(it->descriptorType, it->descriptorCount) + " in another");
            }
            it->descriptorCount = std::max(it->descriptorCount, b.count);
            it->stageFlags |= stage.stage;
        }
        layout.push_constant_bytes = std::max(layout.push_constant_bytes, stage.push_constant_bytes);
    }
    std::sort(layout.bindings.begin(), layout.bindings.end(),
              [](const auto& a, const auto& b) { return a.binding < b.binding; });
    record_layout(pass, layout.push_constant_bytes, stages, {});
    return layout;
}

std::vector<std::string> name_layout_bindings(const std::string& pass, const PipelineLayoutDesc& layout,
                                              const std::vector<ReflectedStage>& stages) {
    std::vector<std::string> names(layout.bindings.size());
    for (const ReflectedStage& stage : stages) {
        for (const ReflectedBinding& b : stage.bindings) {
            const auto it = find_binding(layout.bindings, b.binding);
            if (b.set != 0 || it == layout.bindings.end()) continue;  // refused by the layout's own check
            std::string& name = names[static_cast<size_t>(it - layout.bindings.begin())];
            if (!name.empty() && name != b.name) {
                throw InternalError("pipeline '" + pass + "' (" + stage.shader + "): binding " +
                                    std::to_string(b.binding) + " is '" + b.name + "' in this stage but '" + name +
                                    "' in another; a pass binds by name, so the stages must agree");
            }
            name = b.name;
        }
    }
    for (size_t i = 0; i < names.size(); ++i) {
        for (size_t j = i + 1; j < names.size(); ++j) {
            if (!names[i].empty() && names[i] == names[j]) {
                throw InternalError("pipeline '" + pass + "': bindings " + std::to_string(layout.bindings[i].binding) +
                                    " and " + std::to_string(layout.bindings[j].binding) + " are both named '" +
                                    names[i] + "'; a pass binds by name, so each binding needs its own");
            }
        }
    }
    return names;
}

std::vector<LayoutCheckRecord> layout_check_records() {
    std::lock_guard lock(records_mutex);
    std::vector<LayoutCheckRecord> all;
    for (const auto& [pass, record] : records()) all.push_back(record);
    return all;
}

}  // namespace vkw
