// The water mesh's draw: reads, bindings and push constants (water_surface_draw.hpp).
#include "passes/water/water_surface_draw.hpp"

namespace vkw::passes {

WaterSurfacePush water_surface_push(const WaterSurfaceBuffers& surface, uint32_t refine_steps) {
    WaterSurfacePush push;
    push.mesh_resolution = surface.mesh_resolution;
    push.level = surface.model.level;
    push.half_extent = surface.model.half_extent;
    push.wave_count = surface.model.wave_count;
    push.ocean_n = surface.model.ocean_n;
    push.nodes_per_metre = surface.model.nodes_per_metre;
    push.refine_steps = refine_steps;
    push.mesh_sag = surface.model.mesh_sag;
    return push;
}

void WaterSurfaceReads::declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface) {
    constexpr VkPipelineStageFlags2 fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    mesh = builder.read_storage("Surface", surface.mesh, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | fragment);
    waves = builder.uniform_buffer("Waves", surface.waves, fragment);
    if (surface.ocean_fields) ocean_fields = builder.read_storage("Grids", *surface.ocean_fields, fragment);
    mesh_resolution = surface.mesh_resolution;
    // Flat water's mesh is its surface (every vertex exact, the triangles in its plane).
    surface_model = surface.model.ocean ? 2u : surface.model.wave_count > 0 ? 1u : 0u;
}

std::string WaterSurfaceReads::specialise(GraphicsPipelineDesc& desc, const std::string& key) const {
    desc.fragment_constants = {surface_model};
    static constexpr const char* kModelNames[] = {"/flat", "/sum", "/ocean"};
    return key + kModelNames[surface_model];
}

std::vector<fg::DescriptorBinding> WaterSurfaceReads::stand_ins(const fg::PassContext& context) const {
    // The refinement's shader declares the ocean's fields in every model; only the ocean reads them.
    if (ocean_fields) return {};
    return {context.storage_buffer("Grids", mesh)};
}

void WaterSurfaceReads::draw(fg::PassContext& context) const {
    vkCmdDraw(context.cmd(), 2 * (mesh_resolution + 1), mesh_resolution, 0, 0);
}

}  // namespace vkw::passes
