// The built-in receiver shapes (see builtin_meshes.hpp). Winding: every triangle is
// counter-clockwise seen from outside, i.e. cross(b - a, c - a) points along the normals.
#include "engine/scene/builtin_meshes.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace vkw {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::size_t kTerrainWaves = 4;

// Vertices of a (cells + 1)^2 grid over x in [-half.x, half.x], z in [-half.y, half.y], with
// y = height(x, z) and the given normal; uvs span [0, 1]^2. Triangles face +y.
template <class Height, class Normal>
Mesh grid_mesh(const glm::dvec2& half, uint32_t cells, Height&& height, Normal&& normal) {
    Mesh mesh;
    const uint32_t side = cells + 1;
    mesh.positions.reserve(std::size_t(side) * side);
    for (uint32_t i = 0; i < side; ++i) {
        for (uint32_t j = 0; j < side; ++j) {
            const double u = double(i) / cells, v = double(j) / cells;
            const double x = half.x * (2.0 * u - 1.0), z = half.y * (2.0 * v - 1.0);
            mesh.positions.emplace_back(glm::dvec3(x, height(x, z), z));
            mesh.normals.emplace_back(normal(x, z));
            mesh.uvs.emplace_back(u, v);
        }
    }
    mesh.indices.reserve(std::size_t(cells) * cells * 6);
    for (uint32_t i = 0; i < cells; ++i) {
        for (uint32_t j = 0; j < cells; ++j) {
            // (i, j), (i, j+1), (i+1, j+1), (i+1, j)
            const uint32_t a = i * side + j, b = a + 1, c = a + side + 1, d = a + side;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    }
    update_bounds(mesh);
    return mesh;
}

uint64_t splitmix64(uint64_t& state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

struct TerrainWave {
    double weight, k, cos_theta, sin_theta, phase;
};

std::array<TerrainWave, kTerrainWaves> terrain_waves(const TerrainShape& shape) {
    uint64_t state = shape.seed;
    std::array<TerrainWave, kTerrainWaves> waves{};
    for (std::size_t i = 0; i < kTerrainWaves; ++i) {
        const double theta = kTwoPi * double(splitmix64(state) >> 11) * 0x1p-53;
        const double phase = kTwoPi * double(splitmix64(state) >> 11) * 0x1p-53;
        waves[i] = {double(8 >> i) / 15.0, kTwoPi * double(1u << i) / shape.size, std::cos(theta), std::sin(theta),
                    phase};
    }
    return waves;
}

}  // namespace

Mesh make_plane_mesh(const glm::dvec2& half_size) {
    return grid_mesh(
        half_size, 1, [](double, double) { return 0.0; }, [](double, double) { return glm::vec3(0.0f, 1.0f, 0.0f); });
}

Mesh make_box_mesh(const glm::dvec3& half_size) {
    // Each face: centre n * h and edges u, v with cross(u, v) = n.
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const std::array<std::array<glm::dvec3, 3>, 6> faces = {{
        {x, y, z},
        {-x, z, y},
        {y, z, x},
        {-y, x, z},
        {z, x, y},
        {-z, y, x},
    }};
    Mesh mesh;
    for (const auto& [n, u_axis, v_axis] : faces) {
        const glm::dvec3 c = n * half_size, u = u_axis * half_size, v = v_axis * half_size;
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        const std::array<glm::dvec3, 4> corners = {c - u - v, c + u - v, c + u + v, c - u + v};
        const std::array<glm::vec2, 4> uvs = {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)};
        for (std::size_t k = 0; k < 4; ++k) {
            mesh.positions.emplace_back(corners[k]);
            mesh.normals.emplace_back(n);
            mesh.uvs.push_back(uvs[k]);
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    update_bounds(mesh);
    return mesh;
}

Mesh make_sphere_mesh(double radius) {
    Mesh mesh;
    const uint32_t side = kSphereSegments + 1;
    for (uint32_t i = 0; i <= kSphereRings; ++i) {
        const double theta = std::numbers::pi * i / kSphereRings;  // from +y down to -y
        for (uint32_t j = 0; j <= kSphereSegments; ++j) {
            const double phi = kTwoPi * j / kSphereSegments;
            // Exact poles: sin(pi) is 1.2e-16, not 0.
            const double s = (i == 0 || i == kSphereRings) ? 0.0 : std::sin(theta);
            const double c = i == 0 ? 1.0 : i == kSphereRings ? -1.0 : std::cos(theta);
            const glm::dvec3 n(s * std::cos(phi), c, s * std::sin(phi));
            mesh.positions.emplace_back(radius * n);
            mesh.normals.emplace_back(n);
            mesh.uvs.emplace_back(double(j) / kSphereSegments, double(i) / kSphereRings);
        }
    }
    for (uint32_t i = 0; i < kSphereRings; ++i) {
        for (uint32_t j = 0; j < kSphereSegments; ++j) {
            const uint32_t a = i * side + j, b = a + 1, c = a + side + 1, d = a + side;
            // (a, b, c) runs along d/dphi then d/dtheta: outward. Skip the degenerate
            // triangle of each pair at the poles, where a row collapses to one point.
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (i + 1 != kSphereRings) mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
    }
    update_bounds(mesh);
    return mesh;
}

double terrain_height(const TerrainShape& shape, double x, double z) {
    double h = 0.0;
    for (const TerrainWave& w : terrain_waves(shape)) {
        h += w.weight * std::sin(w.k * (x * w.cos_theta + z * w.sin_theta) + w.phase);
    }
    return shape.height * h;
}

glm::dvec2 terrain_slope(const TerrainShape& shape, double x, double z) {
    glm::dvec2 slope(0.0);
    for (const TerrainWave& w : terrain_waves(shape)) {
        const double d = w.weight * w.k * std::cos(w.k * (x * w.cos_theta + z * w.sin_theta) + w.phase);
        slope += d * glm::dvec2(w.cos_theta, w.sin_theta);
    }
    return shape.height * slope;
}

Mesh make_terrain_mesh(const TerrainShape& shape) {
    const double half = 0.5 * shape.size;
    return grid_mesh(
        glm::dvec2(half), shape.resolution, [&](double x, double z) { return terrain_height(shape, x, z); },
        [&](double x, double z) {
            const glm::dvec2 s = terrain_slope(shape, x, z);
            return glm::vec3(glm::normalize(glm::dvec3(-s.x, 1.0, -s.y)));
        });
}

}  // namespace vkw
