// The water mesh's draw: reads, bindings and push constants (water_surface_draw.hpp).
#include "passes/water/water_surface_draw.hpp"

#include "passes/water/water_screen_mesh.hpp"

namespace vkw::passes {

WaterSurfacePush water_surface_push(const WaterSurfaceBuffers& surface, uint32_t refine_steps) {
    WaterSurfacePush push;
    push.mesh_resolution = surface.mesh_resolution;
    push.level = surface.model.level;
    push.half_extent = surface.screen.infinite ? surface.screen.drawn_half_extent : surface.model.half_extent;
    push.far_field = surface.screen.far_field;
    push.bottom_y = surface.screen.bottom_y;
    push.wave_count = surface.model.wave_count;
    push.ocean_n = surface.model.ocean_n;
    push.nodes_per_metre = surface.model.nodes_per_metre;
    push.refine_steps = refine_steps;
    push.mesh_sag = surface.model.mesh_sag;
    push.sag_per_diagonal_squared = surface.model.sag_per_diagonal_squared;
    push.march_step = surface.model.march_step;
    push.slope_bound = surface.model.slope_bound;
    push.amplitude = surface.screen.amplitude;
    push.screen_margin = surface.screen.margin;
    return push;
}

void WaterSurfaceReads::declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface) {
    constexpr VkPipelineStageFlags2 vertex = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
    constexpr VkPipelineStageFlags2 fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    screen = surface.screen;
    const VkPipelineStageFlags2 surface_stages = screen.cell_pixels > 0 ? vertex | fragment : fragment;
    // The uniform mesh is drawn from its buffer; without an ocean the buffer also stands in
    // for the fields (the fragment stage's, and for the screen's grid the vertex stage's too).
    if (screen.cell_pixels == 0 || !surface.ocean_fields) {
        mesh = builder.read_storage("Surface", surface.mesh, vertex | fragment);
    }
    waves = builder.uniform_buffer("Waves", surface.waves, surface_stages);
    if (surface.ocean_fields) ocean_fields = builder.read_storage("Grids", *surface.ocean_fields, surface_stages);
    mesh_resolution = surface.mesh_resolution;
    // Flat water's mesh is its surface (every vertex exact, the triangles in its plane).
    surface_model = surface.model.ocean ? 2u : surface.model.wave_count > 0 ? 1u : 0u;
}

const char* WaterSurfaceReads::vertex_shader() const {
    return screen.cell_pixels > 0 ? "water/water_surface_screen.vert" : "water/water_surface.vert";
}

std::string WaterSurfaceReads::specialise(GraphicsPipelineDesc& desc, const std::string& key) const {
    const bool screen_grid = screen.cell_pixels > 0;
    // Constant 1: 0 the uniform mesh, 1 the screen's grid, 2 the screen's grid of infinite water.
    desc.specialization_constants = {surface_model, screen_grid ? (screen.infinite ? 2u : 1u) : 0u};
    static constexpr const char* kModelNames[] = {"/flat", "/sum", "/ocean"};
    return key + kModelNames[surface_model] + (screen_grid ? "/screen grid" : "") +
           (screen.infinite ? "/infinite" : "");
}

std::vector<fg::DescriptorBinding> WaterSurfaceReads::stand_ins(const fg::PassContext& context) const {
    // The refinement's shader declares the ocean's fields in every model; only the ocean reads them.
    if (ocean_fields) return {};
    return {context.storage_buffer("Grids", *mesh)};
}

void WaterSurfaceReads::draw(fg::PassContext& context, const Pipeline& pipeline, WaterSurfacePush push) const {
    glm::uvec2 cells(mesh_resolution);
    if (screen.cell_pixels > 0) {
        cells = screen_mesh_cells(screen, context.render_extent());
        push.screen_cells_x = cells.x;
        push.screen_cells_y = cells.y;
    }
    context.push_constants(pipeline, push);
    vkCmdDraw(context.cmd(), 2 * (cells.x + 1), cells.y, 0, 0);
}

}  // namespace vkw::passes
