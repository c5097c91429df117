// The reference tests' wavy scene: one sine along x (A sin(kx), wavelength 0.5 m) over water
// 2 m wide, the floor 1 m down and wide enough to catch every beam, clear water with a little
// absorption (or the given medium), a black sky and the sun toward +x.
#pragma once

#include "engine/scene/scene_loader.hpp"

#include <string>

namespace vkw::ref {

inline Scene sine_scene_with_amplitude(
    double amplitude, double sun_elevation_deg,
    const std::string& medium = R"({"sigma_a": [0.1, 0.2, 0.4], "sigma_s": [0, 0, 0], "g": 0})") {
    return parse_scene(R"({
      "camera": {"position": [0, 2, 3], "target": [0, 0, 0]},
      "sun": {"elevation_deg": )" +
                           std::to_string(sun_elevation_deg) + R"(, "azimuth_deg": 90, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -1, "half_extent": 4},
      "water": {"level": 0, "half_extent": 1, "ior": 1.333,
                "waves": {"model": "sum", "components": [{"amplitude": )" +
                           std::to_string(amplitude) +
                           R"(, "wavelength": 0.5, "direction_deg": 0}]}},
      "medium": )" + medium +
                           R"(
    })",
                       "sine.json");
}

}  // namespace vkw::ref
