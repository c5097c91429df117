// The scene the receiver tests shade in closed form: one receiver over water at y = 0 (floor 2 m
// down), seen from 5 m up, straight down, with a 30-degree field of view; the sun and the sky
// constant and coloured, so that L = rho (E_s cos(theta_s) + pi L_sky) / pi differs per channel.
#pragma once

#include "engine/scene/scene_loader.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {

inline Scene overhead_receiver_scene(const std::string& receiver, const std::filesystem::path& file,
                                     double camera_x = 0.0, const std::vector<std::string>& overrides = {}) {
    return parse_scene(R"({
      "camera": {"position": [)" +
                           std::to_string(camera_x) +
                           R"(, 5, 0], "direction": [0, -1, 0], "fov_y_deg": 30},
      "sun": {"elevation_deg": 50, "azimuth_deg": 20, "irradiance": [2, 3, 4]},
      "sky": {"radiance": [0.2, 0.3, 0.4]},
      "floor": {"height": -2, "half_extent": 10},
      "water": {"level": 0, "half_extent": 10},
      "receivers": [)" + receiver +
                           R"(]
    })",
                       file, overrides);
}

}  // namespace vkw::test
