// The layers of the source tree and which may include which, as data: the table that
// include_layers_test.cpp holds every `#include "..."` edge of engine/, passes/, tools/ and
// tests/ against. Kept apart from the test so that the table reads as the architecture.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vkw::layers {

struct Layer {
    std::string_view name;                      // a folder, root-relative ("engine/scene")
    std::vector<std::string_view> may_include;  // layers (folders) this one may include besides itself
};

// The technique groups of passes/: they may use each other (the caustics read the receivers'
// meshes, the receivers read the caustic map), but none of them knows the frame's composition.
inline const std::vector<std::string_view> kPassGroups = {
    "passes/common",      "passes/sky",      "passes/water",   "passes/receivers",
    "passes/scene_views", "passes/caustics", "passes/godrays", "passes/present",
};

// What every pass may use of the engine: everything except the window.
inline const std::vector<std::string_view> kEngineForPasses = {
    "engine/core", "engine/vk", "engine/framegraph", "engine/image", "engine/scene", "engine/water",
};

std::vector<Layer> layer_table();

// The layer a root-relative path belongs to: the longest layer name that is a folder prefix of
// it; empty when none is.
std::string_view layer_of(const std::vector<Layer>& table, std::string_view path);

// Whether a file of layer `from` may include a file of layer `to`.
bool may_include(const std::vector<Layer>& table, std::string_view from, std::string_view to);

}  // namespace vkw::layers
