// The screen-following water mesh's margin and cells (water_screen_mesh.hpp).
#include "passes/water/water_screen_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vkw::passes {

ScreenMesh screen_mesh(uint32_t cell_pixels, const Camera& camera, double aspect, double level, double amplitude) {
    ScreenMesh mesh;
    mesh.cell_pixels = cell_pixels;
    mesh.amplitude = static_cast<float>(amplitude);
    // The uniform mesh needs no margin; flat water neither (every vertex is its own surface point).
    if (cell_pixels == 0 || !(amplitude > 0.0)) return mesh;
    const double tan_y = std::tan(camera.fov_y_deg * std::numbers::pi / 360.0), tan_x = tan_y * aspect;
    const double scale = 1.0 / std::min(tan_x, tan_y);  // NDC per unit of x / z or y / z, the larger
    const double widest = 1.0 + kMaxScreenMeshMargin;   // the widened grid's edge, NDC
    // The cosine between the view axis and the widened frustum's corner ray.
    const double cos_corner = 1.0 / std::sqrt(1.0 + (tan_x * tan_x + tan_y * tan_y) * widest * widest);
    const double displacement = std::sqrt(2.0) * amplitude;
    const double depth = (std::abs(camera.position.y - level) - amplitude) * cos_corner;
    double margin = kMaxScreenMeshMargin;
    if (depth > displacement) margin = (scale + widest) * displacement / (depth - displacement);
    mesh.margin = static_cast<float>(std::min(margin, kMaxScreenMeshMargin));
    return mesh;
}

ScreenMesh water_screen_mesh(const Scene& scene, double aspect, double amplitude) {
    const Water& water = *scene.water;
    ScreenMesh mesh = screen_mesh(water.screen_mesh_cell_pixels(), scene.camera, aspect, water.level, amplitude);
    if (water.infinite) {
        mesh.infinite = true;
        mesh.drawn_half_extent = static_cast<float>(water_drawn_half_extent(scene));
        mesh.far_field = static_cast<float>(kInfiniteWaterFarField);
        mesh.bottom_y = static_cast<float>(water_bottom(scene));
    }
    return mesh;
}

glm::uvec2 screen_mesh_cells(const ScreenMesh& mesh, VkExtent2D extent) {
    const double widened = 1.0 + mesh.margin;
    auto cells = [&](uint32_t pixels) {
        return std::max(1u, static_cast<uint32_t>(std::ceil(pixels * widened / mesh.cell_pixels)));
    };
    return {cells(extent.width), cells(extent.height)};
}

}  // namespace vkw::passes
