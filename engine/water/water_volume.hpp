// The closed mesh of the water body, for the stencil split of the scene into "above" and
// "under" the water (de la Fuente 2011 section 4.2: the volume's front and back faces are counted,
// so it must be watertight and consistently wound).
//
// Layout (R = grid_resolution, E = half_extent):
//   top:    (R + 1)^2 vertices at the surface's displaced points P(x0, z0) of the parameter
//           grid x0, z0 = -E + 2E i / R, two triangles per cell, facing up;
//   bottom: the same grid flattened to y = bottom_y (each vertex straight below its top
//           vertex), facing down; it is a valid planar triangulation wherever the surface's
//           horizontal map does not fold, and it shares its rim with the walls;
//   walls:  one vertical quad per rim edge, from the displaced rim of the top straight down
//           to the bottom, facing out.
// For heightfields the rim is the square [-E, E]^2; for displaced surfaces it follows the
// horizontal displacement of the edge parameters. The mesh is closed by construction and
// wound counter-clockwise seen from outside, so its signed volume is the water's volume.
#pragma once

#include <cstdint>

#include "engine/water/surface.hpp"
#include "engine/water/triangle_mesh.hpp"

namespace vkw {

// Throws vkw::UserError when bottom_y is not below every top vertex (the floor cuts the
// waves: the mesh would turn itself inside out), and vkw::InternalError for half_extent <= 0,
// grid_resolution 0 or above 16384, or non-finite arguments.
TriangleMesh build_water_volume(const WaterSurface& surface, double half_extent, uint32_t grid_resolution,
                                double bottom_y);

}  // namespace vkw
