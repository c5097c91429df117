// Bounds and transforms of meshes (see mesh.hpp).
#include "engine/scene/mesh.hpp"

#include <algorithm>

namespace vkw {

void update_bounds(Mesh& mesh) {
    if (mesh.positions.empty()) {
        mesh.bounds_min = mesh.bounds_max = glm::dvec3(0.0);
        return;
    }
    mesh.bounds_min = mesh.bounds_max = glm::dvec3(mesh.positions.front());
    for (const glm::vec3& p : mesh.positions) {
        mesh.bounds_min = glm::min(mesh.bounds_min, glm::dvec3(p));
        mesh.bounds_max = glm::max(mesh.bounds_max, glm::dvec3(p));
    }
}

void transform_mesh(Mesh& mesh, const glm::dmat4& object_to_world) {
    // Normals are covectors: a non-uniform scale must use the inverse transpose.
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(object_to_world)));
    for (glm::vec3& p : mesh.positions) p = glm::vec3(object_to_world * glm::dvec4(glm::dvec3(p), 1.0));
    for (glm::vec3& n : mesh.normals) n = glm::vec3(glm::normalize(normal_matrix * glm::dvec3(n)));
    update_bounds(mesh);
}

}  // namespace vkw
