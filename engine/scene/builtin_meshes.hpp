// The built-in receiver shapes as meshes in object space, centred on the origin (the receiver's
// transform then places them, scene.hpp). Formulas and tessellation are documented in
// scenes/README.md ("receivers"); both renderers draw exactly these triangles.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "engine/scene/mesh.hpp"

namespace vkw {

// Sphere tessellation: longitude segments and latitude rings (poles included). Fine enough
// that the flat facets deviate from the sphere by r (1 - cos(pi / 48)) = 0.2% of the radius.
inline constexpr uint32_t kSphereSegments = 48;
inline constexpr uint32_t kSphereRings = 24;

// Horizontal rectangle y = 0, x in [-half_size.x, half_size.x], z in [-half_size.y, half_size.y],
// normal +y: two triangles.
Mesh make_plane_mesh(const glm::dvec2& half_size);

// Axis-aligned box with flat faces: 24 vertices (4 per face, normals outward), 12 triangles.
Mesh make_box_mesh(const glm::dvec3& half_size);

// UV sphere with smooth (radial) normals: (rings + 1) (segments + 1) vertices with a seam.
Mesh make_sphere_mesh(double radius);

// The procedural heightfield of a terrain receiver (scenes/README.md, "Terrain heightfield"):
//   h(x, z) = height * sum_{i=0..3} w_i sin(k_i (x cos(theta_i) + z sin(theta_i)) + phi_i)
// with w = (8, 4, 2, 1) / 15 (so |h| <= height), k_i = 2 pi 2^i / size, and theta_i, phi_i
// = 2 pi u_{2i}, 2 pi u_{2i+1}, u_j the j-th output of splitmix64 seeded with `seed`, mapped
// to [0, 1) by its top 53 bits.
struct TerrainShape {
    double size = 10.0;        // m, side of the square x, z in [-size/2, size/2]
    uint32_t resolution = 64;  // cells per side: (resolution + 1)^2 vertices
    double height = 1.0;       // m, amplitude bound: |h| <= height
    uint64_t seed = 1;
};

double terrain_height(const TerrainShape& shape, double x, double z);
glm::dvec2 terrain_slope(const TerrainShape& shape, double x, double z);  // (dh/dx, dh/dz), exact
// Grid mesh with exact normals normalize(-dh/dx, 1, -dh/dz) and uvs spanning [0, 1]^2.
Mesh make_terrain_mesh(const TerrainShape& shape);

}  // namespace vkw
