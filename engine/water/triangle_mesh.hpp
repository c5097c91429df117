// An indexed triangle mesh in double precision, and the two checks a closed mesh must pass
// before the stencil split may count its faces: combinatorial watertightness and a positive
// enclosed volume.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkw {

struct TriangleMesh {
    std::vector<glm::dvec3> positions;
    std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
};

// True when every undirected edge is used by exactly two triangles, once in each direction
// (a closed, consistently oriented 2-manifold-with-no-boundary, up to pinched vertices).
// Also false for index counts not a multiple of 3, indices out of range and triangles with a
// repeated index. Combinatorial only: coincident but distinct vertices do not join.
// On false, *why (if given) says which edge or triangle fails first and how many do.
bool is_watertight(const TriangleMesh& mesh, std::string* why = nullptr);

// Signed volume, sum over triangles of dot(p0, cross(p1, p2)) / 6 (positions taken relative
// to their centroid against cancellation): positive for a closed mesh wound outward.
// Meaningful only for closed meshes (it depends on the origin otherwise).
double signed_volume(const TriangleMesh& mesh);

}  // namespace vkw
