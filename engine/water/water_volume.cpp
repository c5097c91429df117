// Builds the closed water-body mesh described in water_volume.hpp.
#include "engine/water/water_volume.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>

#include "engine/core/errors.hpp"

namespace vkw {

namespace {

constexpr uint32_t kMaxResolution = 16384;  // 2 (R + 1)^2 vertices must fit in uint32_t

std::string number(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

void add_triangle(TriangleMesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// The rim of an (R + 1) x (R + 1) vertex grid as one closed loop of vertex indices, in the
// direction the top triangles traverse their boundary edges: along z0 = -E toward -x, up
// x0 = -E toward +z, along z0 = +E toward +x, down x0 = +E toward -z.
std::vector<uint32_t> rim_loop(uint32_t r) {
    const uint32_t row = r + 1;
    std::vector<uint32_t> loop;
    loop.reserve(4 * r);
    for (uint32_t i = r; i > 0; --i) loop.push_back(0 * row + i);  // j = 0
    for (uint32_t j = 0; j < r; ++j) loop.push_back(j * row + 0);  // i = 0
    for (uint32_t i = 0; i < r; ++i) loop.push_back(r * row + i);  // j = R
    for (uint32_t j = r; j > 0; --j) loop.push_back(j * row + r);  // i = R
    return loop;
}

}  // namespace

TriangleMesh build_water_volume(const WaterSurface& surface, double half_extent, uint32_t grid_resolution,
                                double bottom_y) {
    if (!(half_extent > 0.0) || !std::isfinite(half_extent) || !std::isfinite(bottom_y) || grid_resolution == 0 ||
        grid_resolution > kMaxResolution) {
        throw InternalError("build_water_volume: half_extent = " + number(half_extent) + ", grid_resolution = " +
                            std::to_string(grid_resolution) + ", bottom_y = " + number(bottom_y) +
                            ": accepted half_extent > 0, 1 <= grid_resolution <= 16384, finite");
    }
    const uint32_t r = grid_resolution;
    const uint32_t row = r + 1;
    const uint32_t count = row * row;  // vertices per layer; bottom vertex = top vertex + count
    TriangleMesh mesh;
    mesh.positions.resize(2 * std::size_t(count));
    for (uint32_t j = 0; j <= r; ++j) {
        for (uint32_t i = 0; i <= r; ++i) {
            // -E + 2E i / R, exact at both ends so that opposite rims meet the square.
            const double x0 = half_extent * (2.0 * i - r) / r;
            const double z0 = half_extent * (2.0 * j - r) / r;
            const glm::dvec3 p = surface.at_parameter(x0, z0).position;
            if (!(p.y > bottom_y)) {
                throw UserError("water volume: the bottom y = " + number(bottom_y) +
                                " m is not below the water surface at x = " + number(p.x) + ", z = " + number(p.z) +
                                " (y = " + number(p.y) + " m); accepted: a floor below the lowest wave trough");
            }
            mesh.positions[j * row + i] = p;
            mesh.positions[count + j * row + i] = glm::dvec3(p.x, bottom_y, p.z);
        }
    }
    mesh.indices.reserve(6 * std::size_t(r) * r * 2 + 6 * 4 * std::size_t(r));
    for (uint32_t j = 0; j < r; ++j) {
        for (uint32_t i = 0; i < r; ++i) {
            const uint32_t v00 = j * row + i, v10 = v00 + 1, v01 = v00 + row, v11 = v01 + 1;
            // cross(v01 - v00, v10 - v00) = cross(+z, +x) = +y: the top faces up ...
            add_triangle(mesh, v00, v01, v10);
            add_triangle(mesh, v10, v01, v11);
            // ... and the bottom, wound the other way, faces down.
            add_triangle(mesh, count + v00, count + v10, count + v01);
            add_triangle(mesh, count + v10, count + v11, count + v01);
        }
    }
    // The top uses each rim edge a -> b in the loop's direction; the wall uses it b -> a, the
    // bottom a -> b on its own layer, so every edge is shared in opposite directions.
    const std::vector<uint32_t> loop = rim_loop(r);
    for (std::size_t e = 0; e < loop.size(); ++e) {
        const uint32_t a = loop[e], b = loop[(e + 1) % loop.size()];
        add_triangle(mesh, b, a, count + a);
        add_triangle(mesh, b, count + a, count + b);
    }
    return mesh;
}

}  // namespace vkw
