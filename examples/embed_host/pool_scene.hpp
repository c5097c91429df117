// scenes/pool.json built in code with <vkwater/scene.hpp>, field for field: the scene the sample
// writes (scene_in_code_main.cpp) and the library's tests load (tests/embed/world_test.cpp).
#pragma once

#include <vkwater/scene.hpp>

namespace embed_host {

inline vkwater::Scene pool_scene() {
    vkwater::Scene scene;
    scene.camera = {{0.0, 1.2, 4.0}, {0.0, -1.5, -2.0}, 60.0, 0.05, 500.0};
    scene.sun = {80.0, 30.0, {3.0, 3.0, 3.0}};  // elevation, azimuth (degrees), irradiance
    scene.sky.radiance = {0.3, 0.45, 0.7};
    scene.floor = {-1.5, {0.6, 0.6, 0.6}, 10.0};
    vkwater::Water water;
    water.grid_resolution = 1024;
    // amplitude, wavelength (m), direction, phase (degrees), steepness
    water.waves = {{0.017, 0.5, 0.0, 0.0, 0.0}, {0.017, 0.5, 90.0, 90.0, 0.0}};
    scene.water = water;
    scene.medium.preset = "pure";
    return scene;
}

}  // namespace embed_host
