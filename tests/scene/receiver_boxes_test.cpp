// The boxes that hold the receiver meshes, which the water's shader tests a ray against before
// its scene-view lookups (engine/scene/receiver_boxes.hpp): every vertex of every receiver lies in
// a box; each receiver has its own box while they fit, and the rest share the last.
#include <gtest/gtest.h>

#include "engine/scene/receiver_boxes.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

#include <string>

namespace vkw {
namespace {

bool inside(const ReceiverBoxes& boxes, std::size_t box, const glm::dvec3& p) {
    return glm::all(glm::greaterThanEqual(p, boxes.lo[box])) && glm::all(glm::lessThanEqual(p, boxes.hi[box]));
}

// The box each vertex of `receiver` lies in must be `box`.
void expect_held_by(const ReceiverBoxes& boxes, std::size_t box, const Receiver& receiver) {
    for (const glm::vec3& p : receiver.mesh.positions) {
        ASSERT_TRUE(inside(boxes, box, glm::dvec3(p))) << receiver.name << ": a vertex outside box " << box;
    }
}

TEST(scene_receiver_boxes, EachOfLakesReceiversHasItsOwnTightBox) {
    const Scene lake = load_scene(test::kSourceDir / "scenes" / "lake.json");
    const ReceiverBoxes boxes = receiver_boxes(lake);
    ASSERT_EQ(boxes.count, lake.receivers.size());
    for (std::size_t i = 0; i < boxes.count; ++i) {
        expect_held_by(boxes, i, lake.receivers[i]);
        // Tight: the margin is 0.1 mm here (lake's coordinates are below 10 m, and 1e-5 of them is
        // under 0.1 mm), so each box is its mesh's bounds widened by 0.1 mm and no more.
        EXPECT_NEAR(boxes.hi[i].y, lake.receivers[i].mesh.bounds_max.y + 1e-4, 1e-12) << lake.receivers[i].name;
        EXPECT_NEAR(boxes.lo[i].x, lake.receivers[i].mesh.bounds_min.x - 1e-4, 1e-12) << lake.receivers[i].name;
    }
}

TEST(scene_receiver_boxes, ReceiversPastTheLastBoxShareIt) {
    // Ten spheres in a row: the first seven have their own boxes, the last three share the eighth.
    std::string receivers;
    for (int i = 0; i < 10; ++i) {
        receivers += std::string(i ? ", " : "") + R"({"type": "sphere", "radius": 0.25, "translation": [)" +
                     std::to_string(i) + ", -1, 0]}";
    }
    const Scene scene = load_scene(test::kSourceDir / "scenes" / "pool.json", {"receivers=[" + receivers + "]"});
    const ReceiverBoxes boxes = receiver_boxes(scene);
    ASSERT_EQ(boxes.count, kReceiverBoxes);
    for (std::size_t i = 0; i < 10; ++i) expect_held_by(boxes, std::min(i, kReceiverBoxes - 1), scene.receivers[i]);
    // The shared box spans spheres 7 to 9 (x from 6.75 to 9.25), give or take its margin.
    EXPECT_NEAR(boxes.lo[kReceiverBoxes - 1].x, 6.75, 2e-4);
    EXPECT_NEAR(boxes.hi[kReceiverBoxes - 1].x, 9.25, 2e-4);
}

TEST(scene_receiver_boxes, ASceneWithoutReceiversHasNoBox) {
    EXPECT_EQ(receiver_boxes(load_scene(test::kSourceDir / "scenes" / "pool.json")).count, 0u);
}

TEST(scene_receiver_boxes, TheMarginCoversFp32RoundingFarFromTheOrigin) {
    // A sphere 5 km out: the margin is 1e-5 of its coordinates (5 cm), far above fp32's rounding
    // there (about 0.5 mm), so the shader's box holds the mesh after both are rounded.
    const Scene scene = load_scene(test::kSourceDir / "scenes" / "pool.json",
                                   {R"(receivers=[{"type": "sphere", "radius": 1, "translation": [5000, -1, 0]}])"});
    const ReceiverBoxes boxes = receiver_boxes(scene);
    ASSERT_EQ(boxes.count, 1u);
    EXPECT_NEAR(boxes.hi[0].x - scene.receivers[0].mesh.bounds_max.x, 1e-5 * boxes.hi[0].x, 1e-3);
    for (const glm::vec3& p : scene.receivers[0].mesh.positions) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, glm::vec3(boxes.lo[0]))) &&
                    glm::all(glm::lessThanEqual(p, glm::vec3(boxes.hi[0]))));
    }
}

}  // namespace
}  // namespace vkw
