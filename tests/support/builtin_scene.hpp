// A built-in scene file (scenes/<name>) with --set style overrides, for the rendering tests.
#pragma once

#include "engine/scene/scene_loader.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {

inline Scene builtin_scene(const char* name, const std::vector<std::string>& overrides = {}) {
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / name, overrides);
}

}  // namespace vkw::test
