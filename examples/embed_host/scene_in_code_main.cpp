// embed_host_scene_in_code OUT_JSON: writes scenes/pool.json's scene, built in code with
// <vkwater/scene.hpp>, as a scene file's JSON (vkwater::scene_json) to OUT_JSON. A host would pass the same
// vkwater::Scene to vkwater::World::load; the install test renders this file with the CLI and finds
// pool.json's image, bit for bit.
#include <vkwater/scene.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: embed_host_scene_in_code OUT_JSON\n", stderr);
        return 1;
    }
    vkwater::Scene scene;
    scene.camera = {{0.0, 1.2, 4.0}, {0.0, -1.5, -2.0}, 60.0, 0.05, 500.0};
    scene.sun = {80.0, 30.0, {3.0, 3.0, 3.0}};
    scene.sky.radiance = {0.3, 0.45, 0.7};
    scene.floor = {-1.5, {0.6, 0.6, 0.6}, 10.0};
    vkwater::Water water;
    water.grid_resolution = 1024;
    water.waves = {{0.017, 0.5, 0.0, 0.0, 0.0},
                   {0.017, 0.5, 90.0, 90.0, 0.0}};  // amplitude, wavelength, direction, phase
    scene.water = water;
    std::FILE* out = std::fopen(argv[1], "w");
    if (!out) {
        std::perror(argv[1]);
        return 1;
    }
    const bool written = std::fputs(vkwater::scene_json(scene).c_str(), out) >= 0;
    return std::fclose(out) == 0 && written ? 0 : 1;
}
