// A bounding volume hierarchy over the triangles of every receiver, in double
// precision, for the reference renderer's exact ray queries (closest hit and
// any-hit for shadows).
#pragma once

#include "engine/scene/mesh.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace vkw::ref {

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction;  // unit
};

struct TriangleHit {
    double distance;
    uint32_t receiver;  // index of the mesh it belongs to
    uint32_t triangle;  // its index in that mesh (indices 3 triangle .. 3 triangle + 2)
    glm::dvec3 normal;  // interpolated shading normal, unit, facing the ray
    // The hit's barycentric weights of the triangle's second and third vertices (the first's is
    // 1 - u - v): what per-vertex data (texture coordinates, colours) is interpolated with.
    glm::dvec2 barycentric{0.0};
};

class TriangleBvh {
public:
    // Whether the point at barycentric (u, v) of triangle `triangle` of mesh `receiver` is cut out
    // (a MASK material's alpha under its cutoff): rays pass through it.
    using CutOut = std::function<bool(uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric)>;

    // meshes[i] is receiver i; meshes are in world space. Without `cut_out`, every point is solid.
    explicit TriangleBvh(const std::vector<const Mesh*>& meshes, CutOut cut_out = {});

    std::optional<TriangleHit> closest_hit(const Ray& ray, double max_distance) const;
    bool any_hit(const Ray& ray, double max_distance) const;
    size_t triangle_count() const { return triangles_.size(); }

private:
    struct Triangle {
        glm::dvec3 a, b, c;     // positions
        glm::dvec3 na, nb, nc;  // vertex normals
        uint32_t receiver;
        uint32_t triangle;
    };
    struct Node {
        glm::dvec3 lo, hi;
        uint32_t first, count;  // leaf: triangles [first, first + count); inner: count == 0
        uint32_t left, right;
    };
    uint32_t build(uint32_t first, uint32_t count);
    template <class OnHit>
    void traverse(const Ray& ray, double& max_distance, OnHit&& on_hit) const;

    std::vector<Triangle> triangles_;
    std::vector<Node> nodes_;
    CutOut cut_out_;
};

}  // namespace vkw::ref
