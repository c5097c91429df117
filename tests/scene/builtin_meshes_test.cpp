// The built-in receiver shapes: bounds, unit outward normals, winding that agrees with the
// normals, the terrain's documented formula, and receivers placed by their transform.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/scene/builtin_meshes.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

// Every triangle's geometric normal (from its winding) points the way of its vertex normals,
// and every normal is a unit vector.
void expect_consistent(const Mesh& mesh) {
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
            c(mesh.positions[mesh.indices[t + 2]]);
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        ASSERT_GT(glm::length(cross), 0.0) << "degenerate triangle " << t / 3;
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_GT(glm::dot(cross, glm::dvec3(mesh.normals[mesh.indices[t + k]])), 0.0) << "triangle " << t / 3;
        }
    }
}

// Outward: each vertex normal points away from `centre`.
void expect_outward(const Mesh& mesh, const glm::dvec3& centre) {
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        EXPECT_GT(glm::dot(glm::dvec3(mesh.normals[i]), glm::dvec3(mesh.positions[i]) - centre), 0.0) << "vertex " << i;
    }
}

TEST(scene_builtin_mesh, Plane) {
    const Mesh mesh = make_plane_mesh({2.0, 3.0});
    expect_consistent(mesh);
    EXPECT_EQ(mesh.indices.size(), 6u);
    EXPECT_EQ(mesh.bounds_min, glm::dvec3(-2.0, 0.0, -3.0));
    EXPECT_EQ(mesh.bounds_max, glm::dvec3(2.0, 0.0, 3.0));
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(scene_builtin_mesh, Box) {
    const Mesh mesh = make_box_mesh({1.0, 2.0, 3.0});
    expect_consistent(mesh);
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    EXPECT_EQ(mesh.bounds_min, glm::dvec3(-1.0, -2.0, -3.0));
    EXPECT_EQ(mesh.bounds_max, glm::dvec3(1.0, 2.0, 3.0));
    expect_outward(mesh, glm::dvec3(0.0));
    // Each face normal is an axis, and the face lies on the box's side along it.
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 n(mesh.normals[i]);
        EXPECT_EQ(glm::dot(glm::abs(n), glm::dvec3(1.0)), 1.0);
        EXPECT_EQ(glm::dot(glm::dvec3(mesh.positions[i]), n), glm::dot(glm::dvec3(1.0, 2.0, 3.0), glm::abs(n)));
    }
}

TEST(scene_builtin_mesh, Sphere) {
    const Mesh mesh = make_sphere_mesh(0.75);
    expect_consistent(mesh);
    EXPECT_EQ(mesh.positions.size(), std::size_t(kSphereRings + 1) * (kSphereSegments + 1));
    EXPECT_EQ(mesh.indices.size(), std::size_t(3) * 2 * kSphereSegments * (kSphereRings - 1));
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(mesh.bounds_min[axis], -0.75, 1e-7);
        EXPECT_NEAR(mesh.bounds_max[axis], 0.75, 1e-7);
    }
    expect_outward(mesh, glm::dvec3(0.0));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(glm::dvec3(mesh.positions[i])), 0.75, 1e-6);
        EXPECT_NEAR(glm::dot(glm::dvec3(mesh.normals[i]), glm::normalize(glm::dvec3(mesh.positions[i]))), 1.0, 1e-6);
    }
}

TEST(scene_builtin_mesh, TerrainFollowsItsFormula) {
    const TerrainShape shape{.size = 8.0, .resolution = 32, .height = 0.5, .seed = 7};
    const Mesh mesh = make_terrain_mesh(shape);
    expect_consistent(mesh);
    EXPECT_EQ(mesh.positions.size(), 33u * 33u);
    EXPECT_EQ(mesh.indices.size(), 32u * 32u * 6u);
    EXPECT_EQ(mesh.bounds_min.x, -4.0);
    EXPECT_EQ(mesh.bounds_max.z, 4.0);
    EXPECT_GE(mesh.bounds_min.y, -0.5);
    EXPECT_LE(mesh.bounds_max.y, 0.5);
    EXPECT_GT(mesh.bounds_max.y - mesh.bounds_min.y, 0.2);  // not flat
    for (const glm::vec3& p : mesh.positions) {
        EXPECT_NEAR(p.y, terrain_height(shape, p.x, p.z), 1e-6);
    }
    // The slope is the exact derivative of the height (central differences agree).
    const double h = 1e-5;
    for (const glm::dvec2 at : {glm::dvec2(0.3, -1.7), glm::dvec2(-2.2, 3.1), glm::dvec2(1.0, 1.0)}) {
        const glm::dvec2 slope = terrain_slope(shape, at.x, at.y);
        EXPECT_NEAR(slope.x, (terrain_height(shape, at.x + h, at.y) - terrain_height(shape, at.x - h, at.y)) / (2 * h),
                    1e-8);
        EXPECT_NEAR(slope.y, (terrain_height(shape, at.x, at.y + h) - terrain_height(shape, at.x, at.y - h)) / (2 * h),
                    1e-8);
    }
    // Deterministic in the seed, and the seed matters.
    EXPECT_EQ(terrain_height(shape, 1.234, -0.5), terrain_height(shape, 1.234, -0.5));
    TerrainShape other = shape;
    other.seed = 8;
    EXPECT_NE(terrain_height(shape, 1.234, -0.5), terrain_height(other, 1.234, -0.5));
}

TEST(scene_builtin_mesh, ReceiverTransformPlacesTheMeshInWorldSpace) {
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
        "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
        "receivers": [
          { "type": "box", "half_size": [1, 2, 3], "rotation_deg": [0, 90, 0], "scale": [2, 1, 1], "translation": [10, 0, 0] },
          { "name": "ball", "type": "sphere", "radius": 1, "translation": [0, -3, 0], "albedo": [0.1, 0.2, 0.3] },
          { "type": "plane", "half_size": [1, 1], "rotation_deg": [90, 0, 0] },
          { "type": "terrain", "size": 4, "height": 0.1 } ] })";
    const Scene scene = parse_scene(text, "receivers.json");
    ASSERT_EQ(scene.receivers.size(), 4u);
    // Scale first (x: 2), then a quarter turn about y (x -> -z, z -> x), then the translation.
    const Receiver& box = scene.receivers[0];
    EXPECT_EQ(box.type, ReceiverType::Box);
    EXPECT_EQ(box.name, "receivers[0]");
    EXPECT_EQ(box.albedo, glm::dvec3(0.5));
    EXPECT_EQ(box.mesh.bounds_min, glm::dvec3(7.0, -2.0, -2.0));
    EXPECT_EQ(box.mesh.bounds_max, glm::dvec3(13.0, 2.0, 2.0));
    expect_consistent(box.mesh);
    expect_outward(box.mesh, glm::dvec3(10.0, 0.0, 0.0));
    const Receiver& ball = scene.receivers[1];
    EXPECT_EQ(ball.name, "ball");
    EXPECT_EQ(ball.albedo, glm::dvec3(0.1, 0.2, 0.3));
    expect_outward(ball.mesh, glm::dvec3(0.0, -3.0, 0.0));
    // A quarter turn about x takes the plane's +y normal to +z.
    for (const glm::vec3& n : scene.receivers[2].mesh.normals) EXPECT_EQ(n, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(scene.receivers[3].mesh.positions.size(), 65u * 65u);  // default resolution 64
}

}  // namespace
}  // namespace vkw
