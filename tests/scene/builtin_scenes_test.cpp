// Every scene in scenes/ loads, and each one states what its description promises.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Scene load(const char* name) { return load_scene(test::kSourceDir / "scenes" / name); }

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

TEST(scene_builtin, EverySceneFileLoadsWithADescription) {
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::kSourceDir / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const Scene scene = load_scene(entry.path());
        EXPECT_GT(scene.description.size(), 40u);
        ++count;
    }
    EXPECT_GE(count, 5u);  // pool, calm, underwater, ocean, lake
}

TEST(scene_builtin, CalmIsFlatWithAConstantSkyAndA45DegreeView) {
    const Scene scene = load("calm.json");
    ASSERT_TRUE(scene.water);
    EXPECT_EQ(scene.water->waves.model, WaveModel::Flat);
    EXPECT_EQ(scene.sky.model, SkyModel::Constant);
    EXPECT_TRUE(scene.receivers.empty());
    EXPECT_GT(scene.camera.position.y, scene.water->level);
    const glm::dvec3 view = glm::normalize(scene.camera.target - scene.camera.position);
    EXPECT_NEAR(degrees(std::asin(-view.y)), 45.0, 1e-9);
    EXPECT_NE(scene.medium.g, 0.0);  // exercises Henyey-Greenstein with g != 0
}

TEST(scene_builtin, UnderwaterLooksUpFrom2MetresWithAWideField) {
    const Scene scene = load("underwater.json");
    ASSERT_TRUE(scene.water);
    EXPECT_EQ(scene.water->waves.model, WaveModel::Flat);
    EXPECT_EQ(scene.water->level - scene.camera.position.y, 2.0);
    EXPECT_EQ(glm::normalize(scene.camera.target - scene.camera.position), glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(scene.camera.fov_y_deg, 120.0);
    // docs/model.md section 7: the window's full cone (97.2 degrees) fits in the field of view, and the
    // radius measurement needs nothing but the transmitted sky.
    EXPECT_GT(scene.camera.fov_y_deg, 2.0 * degrees(std::asin(1.0 / scene.water->ior)));
    EXPECT_EQ(scene.floor.albedo, glm::dvec3(0.0));
    EXPECT_EQ(scene.sun.irradiance, glm::dvec3(0.0));
    EXPECT_EQ(scene.medium.sigma_s, glm::dvec3(0.0));
    EXPECT_EQ(scene.medium.preset, "");
    EXPECT_GT(water_bottom(scene), -1e9);
    EXPECT_LT(water_bottom(scene), scene.camera.position.y);
}

TEST(scene_builtin, OceanHasFftWavesCoastalWaterAndALowSun) {
    const Scene scene = load("ocean.json");
    ASSERT_TRUE(scene.water);
    EXPECT_EQ(scene.water->waves.model, WaveModel::FftOcean);
    EXPECT_EQ(scene.water->waves.ocean.spectrum, OceanSpectrum::Jonswap);
    EXPECT_EQ(scene.water->waves.ocean.resolution, 256u);
    EXPECT_EQ(scene.water->waves.seed, 42u);
    EXPECT_EQ(scene.medium.preset, "coastal");
    EXPECT_NEAR(degrees(std::asin(-scene.sun.direction.y)), 15.0, 1e-9);
    EXPECT_EQ(scene.sky.model, SkyModel::Gradient);
}

TEST(scene_builtin, LakeHasEveryReceiverType) {
    const Scene scene = load("lake.json");
    ASSERT_TRUE(scene.water);
    ASSERT_EQ(scene.receivers.size(), 5u);
    const auto find = [&](const std::string& name) -> const Receiver& {
        for (const Receiver& receiver : scene.receivers) {
            if (receiver.name == name) return receiver;
        }
        ADD_FAILURE() << "no receiver " << name;
        return scene.receivers.front();
    };
    const double level = scene.water->level;
    EXPECT_EQ(find("lake bed").type, ReceiverType::Terrain);
    EXPECT_LT(find("lake bed").mesh.bounds_max.y, level);
    const Receiver& post = find("post");
    EXPECT_EQ(post.type, ReceiverType::Box);
    EXPECT_LT(post.mesh.bounds_min.y, level);  // through the surface
    EXPECT_GT(post.mesh.bounds_max.y, level);
    EXPECT_GT(find("sphere above").mesh.bounds_min.y, level);
    const Receiver& below = find("sphere below");
    EXPECT_LT(below.mesh.bounds_max.y, level);
    EXPECT_GT(below.mesh.bounds_min.y, find("lake bed").mesh.bounds_max.y);  // clear of the bed
    const Receiver& rock = find("rock");
    EXPECT_EQ(rock.type, ReceiverType::Gltf);
    EXPECT_EQ(rock.mesh.positions.size(), 240u);  // 80 flat-shaded triangles
    EXPECT_EQ(rock.mesh.indices.size(), 240u);
    ASSERT_EQ(rock.mesh.parts.size(), 1u);  // the glTF material's base colour, applied once
    EXPECT_EQ(rock.mesh.parts[0].base_color, glm::dvec3(0.45 * 0.45, 0.4 * 0.4, 0.35 * 0.35));
    EXPECT_EQ(rock.mesh.parts[0].index_count, 240u);
    EXPECT_LT(rock.mesh.bounds_min.y, level);
    EXPECT_GT(rock.mesh.bounds_max.y, level);
    EXPECT_EQ(scene.effects[Effect::CausticBlur].mode, EffectMode::On);
}

}  // namespace
}  // namespace vkw
