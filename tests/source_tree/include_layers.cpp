#include "tests/source_tree/include_layers.hpp"

#include <algorithm>

namespace vkw::layers {

namespace {

std::vector<std::string_view> joined(std::initializer_list<std::vector<std::string_view>> lists) {
    std::vector<std::string_view> all;
    for (const auto& list : lists) all.insert(all.end(), list.begin(), list.end());
    return all;
}

}  // namespace

std::vector<Layer> layer_table() {
    std::vector<Layer> table = {
        // engine/: knows no pass and no tool. Its folders build on each other bottom-up.
        {"engine/core", {}},
        {"engine/vk", {"engine/core"}},
        {"engine/framegraph", {"engine/core", "engine/vk"}},
        {"engine/image", {"engine/core"}},
        {"engine/water", {"engine/core"}},
        {"engine/scene", {"engine/core", "engine/water"}},
        {"engine/window", {"engine/core", "engine/vk", "engine/image"}},
        // passes/frame: the frame's composition, on top of every technique; no tool.
        {"passes/frame", joined({kEngineForPasses, kPassGroups})},
        // library/: the embedding library's implementation, over the frame's composition; its public
        // headers (include/vkwater/, included with angle brackets) include only each other.
        {"library", joined({kEngineForPasses, kPassGroups, {"passes/frame"}})},
        // tools/: on top. The reference renderer shares no real-time code: it sees the scene, the
        // CPU water, the image I/O and the core only, so it stays an independent ground truth.
        {"tools/reference", {"engine/core", "engine/scene", "engine/water", "engine/image"}},
        {"tools/metrics", {"engine/core", "engine/image"}},
        {"tools/povray", {"engine/core", "engine/scene", "engine/water"}},
        // The build-time generator of the shaders' C++ block mirrors: SPIRV-Cross alone.
        {"tools/shader_structs", {}},
        {"tools/benchmarks", joined({kEngineForPasses, kPassGroups, {"passes/frame", "tools/metrics"}})},
        {"tools/vkwater", joined({kEngineForPasses,
                                  kPassGroups,
                                  {"engine/window", "passes/frame", "tools/reference", "tools/metrics", "tools/povray",
                                   "tools/benchmarks"}})},
        // examples/: programs built against an installed vkwater, on its public headers alone (angle
        // brackets); a test may share their code (the sample's scene built in code).
        {"examples", {}},
        // tests/: may include anything under test, and each other's support files.
        {"tests", joined({kEngineForPasses,
                          kPassGroups,
                          {"engine/window", "passes/frame", "library", "tools/reference", "tools/metrics",
                           "tools/povray", "tools/benchmarks", "tools/vkwater", "examples"}})},
    };
    for (std::string_view group : kPassGroups) table.push_back({group, joined({kEngineForPasses, kPassGroups})});
    return table;
}

std::string_view layer_of(const std::vector<Layer>& table, std::string_view path) {
    std::string_view best;
    for (const Layer& layer : table) {
        const bool prefix = path.size() > layer.name.size() && path.substr(0, layer.name.size()) == layer.name &&
                            path[layer.name.size()] == '/';
        if (prefix && layer.name.size() > best.size()) best = layer.name;
    }
    return best;
}

bool may_include(const std::vector<Layer>& table, std::string_view from, std::string_view to) {
    if (from == to) return true;
    for (const Layer& layer : table) {
        if (layer.name != from) continue;
        return std::find(layer.may_include.begin(), layer.may_include.end(), to) != layer.may_include.end();
    }
    return false;
}

}  // namespace vkw::layers
