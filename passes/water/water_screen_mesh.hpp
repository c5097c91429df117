// The grid the water is drawn from when it follows the screen (a projected grid,
// shaders/water/water_surface_screen.vert): how far it must reach past the viewport's edges, and
// how many cells it has.
#pragma once

#include "engine/scene/scene.hpp"
#include "passes/water/water_surface.hpp"

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

namespace vkw::passes {

// The farthest the grid reaches past each edge of the viewport, in NDC: the grid then has up to
// (1 + kMaxScreenMeshMargin)^2 times the cells of the viewport's own.
inline constexpr double kMaxScreenMeshMargin = 1.0;

// The screen's grid for a camera over (or under) water of mean level `level` whose height stays
// within `amplitude` of it, with cells of `cell_pixels` (> 0). The margin bounds how far the
// waves can move a vertex on the screen: a vertex stands for a point of the mean level, and the
// surface point drawn there lies within sqrt(2) amplitude of it (at most the amplitude up or down
// and sideways), which moves it by at most (f + |ndc|) sqrt(2) amplitude / (depth - sqrt(2)
// amplitude) in NDC, f the projection's larger scale and depth the nearest view depth of the slab
// |y - level| <= amplitude inside the widened frustum. A camera within the slab gets the largest
// margin, kMaxScreenMeshMargin, which bounds nothing there (crests nearer than the near plane's
// corner can still pull the mesh's edge into view).
ScreenMesh screen_mesh(uint32_t cell_pixels, const Camera& camera, double aspect, double level, double amplitude);

// The grid the scene's water is drawn from: screen_mesh for its cell width (0: the uniform mesh),
// and for infinite water the square the camera can see (water_drawn_half_extent), the far field
// (kInfiniteWaterFarField) and the water's bottom. `amplitude` bounds |surface height - level|.
ScreenMesh water_screen_mesh(const Scene& scene, double aspect, double amplitude);

// Cells across and down an image of `extent` pixels (at least one each).
glm::uvec2 screen_mesh_cells(const ScreenMesh& mesh, VkExtent2D extent);

}  // namespace vkw::passes
