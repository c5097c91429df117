// Watertightness and signed volume of a triangle mesh (triangle_mesh.hpp).
#include "engine/water/triangle_mesh.hpp"

#include <cstddef>
#include <unordered_map>

namespace vkw {

namespace {

struct EdgeUse {
    uint32_t forward = 0;   // used as low -> high index
    uint32_t backward = 0;  // used as high -> low index
};

uint64_t edge_key(uint32_t a, uint32_t b) {
    const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    return (uint64_t(lo) << 32) | hi;
}

void say(std::string* why, const std::string& text) {
    if (why != nullptr) {
        *why = text;
    }
}

}  // namespace

bool is_watertight(const TriangleMesh& mesh, std::string* why) {
    const std::vector<uint32_t>& idx = mesh.indices;
    if (idx.empty() || idx.size() % 3 != 0) {
        say(why, std::to_string(idx.size()) + " indices: not a positive multiple of 3");
        return false;
    }
    std::unordered_map<uint64_t, EdgeUse> edges;
    edges.reserve(idx.size());
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        const uint32_t v[3] = {idx[t], idx[t + 1], idx[t + 2]};
        for (int c = 0; c < 3; ++c) {
            if (v[c] >= mesh.positions.size()) {
                say(why, "triangle " + std::to_string(t / 3) + " uses vertex " + std::to_string(v[c]) + " of " +
                             std::to_string(mesh.positions.size()));
                return false;
            }
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            say(why, "triangle " + std::to_string(t / 3) + " repeats a vertex");
            return false;
        }
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = v[c], b = v[(c + 1) % 3];
            EdgeUse& use = edges[edge_key(a, b)];
            (a < b ? use.forward : use.backward) += 1;
        }
    }
    std::size_t bad = 0;
    std::string first;
    for (const auto& [key, use] : edges) {
        if (use.forward == 1 && use.backward == 1) {
            continue;
        }
        if (bad++ == 0) {
            first = "edge (" + std::to_string(key >> 32) + ", " + std::to_string(key & 0xffffffffu) + ") is used " +
                    std::to_string(use.forward) + " time(s) low->high and " + std::to_string(use.backward) +
                    " time(s) high->low";
        }
    }
    if (bad > 0) {
        say(why, first + " (" + std::to_string(bad) +
                     " bad edge(s) in all; each must be used "
                     "once in each direction)");
        return false;
    }
    return true;
}

double signed_volume(const TriangleMesh& mesh) {
    if (mesh.positions.empty()) {
        return 0.0;
    }
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3& p : mesh.positions) {
        centroid += p;
    }
    centroid /= double(mesh.positions.size());
    double six_volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 p0 = mesh.positions[mesh.indices[t]] - centroid;
        const glm::dvec3 p1 = mesh.positions[mesh.indices[t + 1]] - centroid;
        const glm::dvec3 p2 = mesh.positions[mesh.indices[t + 2]] - centroid;
        six_volume += glm::dot(p0, glm::cross(p1, p2));
    }
    return six_volume / 6.0;
}

}  // namespace vkw
