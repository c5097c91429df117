// embed_host_scene_in_code OUT_JSON: writes scenes/pool.json's scene, built in code with
// <vkwater/scene.hpp>, as a scene file's JSON (vkwater::scene_json) to OUT_JSON. A host would pass the same
// vkwater::Scene to vkwater::World::load; the install test renders this file with the CLI and finds
// pool.json's image, bit for bit.
#include "pool_scene.hpp"

#include <vkwater/scene.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: embed_host_scene_in_code OUT_JSON\n", stderr);
        return 1;
    }
    const vkwater::Scene scene = embed_host::pool_scene();
    std::FILE* out = std::fopen(argv[1], "w");
    if (!out) {
        std::perror(argv[1]);
        return 1;
    }
    const bool written = std::fputs(vkwater::scene_json(scene).c_str(), out) >= 0;
    return std::fclose(out) == 0 && written ? 0 : 1;
}
