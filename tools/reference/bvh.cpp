#include "tools/reference/bvh.hpp"

#include <utility>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vkw::ref {
namespace {

constexpr uint32_t kLeafSize = 4;

// Moller-Trumbore in double; returns the distance and barycentrics (u, v).
std::optional<glm::dvec3> intersect(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                    double max_distance) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return std::nullopt;
    const double inverse = 1.0 / det;
    const glm::dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) * inverse;
    if (t <= 0.0 || t >= max_distance) return std::nullopt;
    return glm::dvec3(t, u, v);
}

bool hits_box(const Ray& ray, const glm::dvec3& inverse_direction, const glm::dvec3& lo, const glm::dvec3& hi,
              double max_distance) {
    double t0 = 0.0, t1 = max_distance;
    for (int axis = 0; axis < 3; ++axis) {
        double near = (lo[axis] - ray.origin[axis]) * inverse_direction[axis];
        double far = (hi[axis] - ray.origin[axis]) * inverse_direction[axis];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const std::vector<const Mesh*>& meshes, CutOut cut_out) : cut_out_(std::move(cut_out)) {
    for (uint32_t receiver = 0; receiver < meshes.size(); ++receiver) {
        const Mesh& mesh = *meshes[receiver];
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const uint32_t ia = mesh.indices[i], ib = mesh.indices[i + 1], ic = mesh.indices[i + 2];
            triangles_.push_back({glm::dvec3(mesh.positions[ia]), glm::dvec3(mesh.positions[ib]),
                                  glm::dvec3(mesh.positions[ic]), glm::dvec3(mesh.normals[ia]),
                                  glm::dvec3(mesh.normals[ib]), glm::dvec3(mesh.normals[ic]), receiver,
                                  static_cast<uint32_t>(i / 3)});
        }
    }
    if (!triangles_.empty()) build(0, static_cast<uint32_t>(triangles_.size()));
}

uint32_t TriangleBvh::build(uint32_t first, uint32_t count) {
    Node node{};
    node.lo = glm::dvec3(std::numeric_limits<double>::max());
    node.hi = -node.lo;
    for (uint32_t i = first; i < first + count; ++i) {
        for (const glm::dvec3& p : {triangles_[i].a, triangles_[i].b, triangles_[i].c}) {
            node.lo = glm::min(node.lo, p);
            node.hi = glm::max(node.hi, p);
        }
    }
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back(node);
    if (count <= kLeafSize) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    // Median split along the longest axis of the box (deterministic: nth_element on a total order).
    const glm::dvec3 extent = node.hi - node.lo;
    const int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    auto centroid = [axis](const Triangle& t) { return t.a[axis] + t.b[axis] + t.c[axis]; };
    const uint32_t half = count / 2;
    std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half, triangles_.begin() + first + count,
                     [&](const Triangle& x, const Triangle& y) { return centroid(x) < centroid(y); });
    const uint32_t left = build(first, half);
    const uint32_t right = build(first + half, count - half);
    nodes_[index].count = 0;
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
}

template <class OnHit>
void TriangleBvh::traverse(const Ray& ray, double& max_distance, OnHit&& on_hit) const {
    if (nodes_.empty()) return;
    const glm::dvec3 inverse_direction = 1.0 / ray.direction;  // +-inf for zero components is fine here
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!hits_box(ray, inverse_direction, node.lo, node.hi, max_distance)) continue;
        if (node.count == 0) {
            stack[top++] = node.left;
            stack[top++] = node.right;
            continue;
        }
        for (uint32_t i = node.first; i < node.first + node.count; ++i) {
            const Triangle& tri = triangles_[i];
            if (auto hit = intersect(ray, tri.a, tri.b, tri.c, max_distance)) {
                if (cut_out_ && cut_out_(tri.receiver, tri.triangle, {hit->y, hit->z})) continue;  // not there
                if (on_hit(tri, *hit)) return;  // any-hit queries stop at the first
                max_distance = hit->x;
            }
        }
    }
}

std::optional<TriangleHit> TriangleBvh::closest_hit(const Ray& ray, double max_distance) const {
    std::optional<TriangleHit> best;
    traverse(ray, max_distance, [&](const Triangle& tri, const glm::dvec3& hit) {
        const double u = hit.y, v = hit.z;
        glm::dvec3 normal = glm::normalize((1.0 - u - v) * tri.na + u * tri.nb + v * tri.nc);
        if (glm::dot(normal, ray.direction) > 0.0) normal = -normal;
        best = TriangleHit{hit.x, tri.receiver, tri.triangle, normal, {u, v}};
        return false;
    });
    return best;
}

bool TriangleBvh::any_hit(const Ray& ray, double max_distance) const {
    bool found = false;
    traverse(ray, max_distance, [&](const Triangle&, const glm::dvec3&) { return found = true; });
    return found;
}

}  // namespace vkw::ref
