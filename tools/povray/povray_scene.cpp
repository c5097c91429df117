#include "tools/povray/povray_scene.hpp"

#include "engine/core/errors.hpp"
#include "engine/water/surface.hpp"
#include "engine/water/water_volume.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace vkw::pov {
namespace {

// The water body's bottom lies this far under the floor: a bottom face coplanar with the
// floor would let photons meet either first and leave the water through it.
constexpr double kBottomUnderFloor = 0.01;
// The camera's height above the floor: inside the water body, so its rays cross this much
// absorbing media, a loss of exp(-sigma_t * 1e-3) (0.12% for the presets' red, the same for
// every pixel and every scene with the same medium; povray_camera_transmittance). Closer, at
// 1e-4 m, POV-Ray's minimum intersection distance hides the floor.
constexpr double kCameraAboveFloor = 1e-3;
// The sun's parallel light is placed this far back along its beam from the window's centre.
constexpr double kLightDistance = 100.0;

// Ten significant digits: positions to 1e-10 relative, far below any feature here.
std::string number(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 10);
    return std::string(text, result.ptr);
}

// A vkwater point or direction in POV-Ray's left-handed axes (z negated).
std::string pov_vector(const glm::dvec3& v) { return "<" + number(v.x) + "," + number(v.y) + "," + number(-v.z) + ">"; }

// Per-channel values as POV-Ray's <r, g, b>.
std::string triple(const glm::dvec3& c) { return "<" + number(c.x) + "," + number(c.y) + "," + number(c.z) + ">"; }

void require(bool ok, const Scene& scene, const std::string& field, const std::string& what) {
    if (!ok) throw UserError(scene.source.string() + ": " + field + ": " + what);
}

// The closed water body as a mesh2: the surface with its analytic normals (one per grid
// vertex, interpolated across each triangle: POV-Ray's smooth triangles) and the dielectric
// texture; the walls and the bottom with their flat face normals and an opaque black texture.
// The model's light reaches the water only through its surface: transparent walls would let
// the sun in sideways and light a band of the floor along them (up to d tan(theta) wide).
std::string water_mesh(const Scene& scene, uint32_t cells) {
    const Water& water = *scene.water;
    const std::unique_ptr<WaterSurface> surface = make_surface(water.waves, water.level, water.time);
    const TriangleMesh mesh =
        build_water_volume(*surface, water.half_extent, cells, scene.floor.height - kBottomUnderFloor);
    const uint32_t row = cells + 1, top_vertices = row * row;  // the top layer comes first (water_volume.hpp)

    std::vector<glm::dvec3> normals;
    normals.reserve(top_vertices + 1 + mesh.indices.size() / 3);
    for (uint32_t j = 0; j <= cells; ++j) {
        for (uint32_t i = 0; i <= cells; ++i) {
            // The grid parameters of build_water_volume's vertex (i, j).
            const double x0 = water.half_extent * (2.0 * i - cells) / cells;
            const double z0 = water.half_extent * (2.0 * j - cells) / cells;
            normals.push_back(surface->at_parameter(x0, z0).normal);
        }
    }
    const uint32_t down = static_cast<uint32_t>(normals.size());
    normals.push_back({0.0, -1.0, 0.0});
    std::string faces, normal_indices;
    const size_t face_count = mesh.indices.size() / 3;
    for (size_t f = 0; f < face_count; ++f) {
        const uint32_t* v = &mesh.indices[3 * f];
        const bool top = v[0] < top_vertices && v[1] < top_vertices && v[2] < top_vertices;
        const bool bottom = v[0] >= top_vertices && v[1] >= top_vertices && v[2] >= top_vertices;
        uint32_t n[3] = {down, down, down};
        if (top) {
            n[0] = v[0], n[1] = v[1], n[2] = v[2];
        } else if (!bottom) {  // a wall: its own flat normal
            const glm::dvec3& a = mesh.positions[v[0]];
            n[0] = n[1] = n[2] = static_cast<uint32_t>(normals.size());
            normals.push_back(glm::normalize(glm::cross(mesh.positions[v[1]] - a, mesh.positions[v[2]] - a)));
        }
        faces += "<" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + ">," +
                 (top ? "0\n" : "1\n");
        normal_indices += "<" + std::to_string(n[0]) + "," + std::to_string(n[1]) + "," + std::to_string(n[2]) + ">\n";
    }

    std::string text = "mesh2 {\n  vertex_vectors { " + std::to_string(mesh.positions.size()) + ",\n";
    for (const glm::dvec3& p : mesh.positions) text += pov_vector(p) + "\n";
    text += "  }\n  normal_vectors { " + std::to_string(normals.size()) + ",\n";
    for (const glm::dvec3& n : normals) text += pov_vector(n) + "\n";
    // Texture 0, the surface: a perfect dielectric; Fresnel reflection with conserve_energy
    // leaves photons T = 1 - R. Texture 1, walls and bottom: opaque, black.
    text +=
        "  }\n  texture_list { 2,\n    texture { pigment { rgbf 1 } finish { ambient 0 emission 0 diffuse 0 "
        "specular 0 reflection { 0, 1 fresnel on } conserve_energy } }\n    texture { pigment { rgb 0 } finish { "
        "ambient 0 emission 0 diffuse 0 specular 0 } }\n  }\n";
    text += "  face_indices { " + std::to_string(face_count) + ",\n" + faces + "  }\n";
    text += "  normal_indices { " + std::to_string(face_count) + ",\n" + normal_indices + "  }\n";
    // Closed: POV-Ray decides insideness (the camera's medium) along this direction.
    text += "  inside_vector <0, 1, 0>\n";
    return text;
}

}  // namespace

glm::dvec3 camera_transmittance(const Scene& scene) { return glm::exp(-scene.medium.sigma_t() * kCameraAboveFloor); }

FloorWindow lit_floor_window(const Scene& scene, double side) {
    const double depth = (scene.water ? scene.water->level : 0.0) - scene.floor.height;
    const double ior = scene.water ? scene.water->ior : 1.0;
    // Snell's law for the flat surface: the horizontal part of t is that of s over n, and
    // t_y = -sqrt(1 - |t_h|^2); with the sun below the horizon nothing is lit, so (0, 0).
    const glm::dvec2 t_h = glm::dvec2(scene.sun.direction.x, scene.sun.direction.z) / ior;
    const double t_y = std::sqrt(std::max(0.0, 1.0 - glm::dot(t_h, t_h)));
    const glm::dvec2 c = scene.sun.direction.y < 0.0 && t_y > 0.0 ? 0.5 * depth * t_h / t_y : glm::dvec2(0.0);
    return {c.x - 0.5 * side, c.y - 0.5 * side, c.x + 0.5 * side, c.y + 0.5 * side};
}

std::string povray_floor_scene(const Scene& scene, const PovrayOptions& options) {
    require(scene.water.has_value(), scene, "water", "the scene has no water (accepted: a scene with water)");
    const Water& water = *scene.water;
    require(!scene.water->infinite, scene, "water.half_extent",
            "\"infinite\": the cross-check closes its water in a mesh (accepted: a number)");
    require(scene.receivers.empty(), scene, "receivers",
            "receivers are not exported to POV-Ray (accepted: a scene without receivers)");
    require(water_bottom(scene) <= scene.floor.height, scene, "water.depth",
            "the water must reach the floor, whose irradiance is rendered (accepted: no depth, or depth >= " +
                number(water.level - scene.floor.height) + " m)");
    const FloorWindow& w = options.window;
    require(w.x0 < w.x1 && w.z0 < w.z1, scene, "floor window",
            "x0 < x1 and z0 < z1 are required (got x " + number(w.x0) + ".." + number(w.x1) + ", z " + number(w.z0) +
                ".." + number(w.z1) + ")");
    require(options.photon_spacing > 0.0, scene, "photon spacing", "accepted: > 0 m");
    require(options.gather_radius >= 0.0, scene, "gather radius", "accepted: >= 0 m (0: automatic)");
    const uint32_t cells = options.mesh_cells ? options.mesh_cells : water.grid_resolution;
    require(cells >= 1 && cells <= 4096, scene, "mesh cells", "accepted: 1 to 4096");

    const glm::dvec3 centre{0.5 * (w.x0 + w.x1), scene.floor.height, 0.5 * (w.z0 + w.z1)};
    std::string text = "// vkwater povray: the sun's irradiance on the floor of " + scene.source.string() +
                       ", seen straight down over x " + number(w.x0) + ".." + number(w.x1) + ", z " + number(w.z0) +
                       ".." + number(w.z1) + " m (tools/povray/povray_scene.hpp)\n#version 3.7;\n";
    text += "global_settings {\n  assumed_gamma 1.0\n  ambient_light 0\n  max_trace_level 10\n";
    text += "  photons {\n    spacing " + number(options.photon_spacing) + "\n    autostop 0\n";
    if (options.gather_radius > 0.0) {
        // A fixed radius: every photon within it counts (the max gather count never binds).
        text += "    radius " + number(options.gather_radius) + ", 1, " + number(options.gather_radius) + ", 1\n";
        text += "    gather 1, 1000000\n";
    }
    text += "  }\n}\n";
    text += "camera {\n  orthographic\n  location " + pov_vector(centre + glm::dvec3(0.0, kCameraAboveFloor, 0.0)) +
            "\n  direction <0, -1, 0>\n  right <" + number(w.x1 - w.x0) + ", 0, 0>\n  up <0, 0, " +
            number(w.z1 - w.z0) + ">\n}\n";
    const glm::dvec3 at{centre.x, water.level, centre.z};
    text += "light_source {\n  " + pov_vector(at - kLightDistance * scene.sun.direction) + "\n  color rgb " +
            triple(scene.sun.irradiance) + "\n  parallel\n  point_at " + pov_vector(at) +
            "\n  photons { refraction on reflection off }\n}\n";
    text += "plane {\n  y, " + number(scene.floor.height) +
            "\n  pigment { rgb 1 }\n  finish { ambient 0 emission 0 diffuse 1 specular 0 }\n}\n";
    text += water_mesh(scene, cells);
    text +=
        "  interior { ior " + number(water.ior) + " media { absorption " + triple(scene.medium.sigma_t()) + " } }\n";
    text += "  photons { target refraction on reflection off collect off }\n  hollow\n}\n";
    return text;
}

}  // namespace vkw::pov
