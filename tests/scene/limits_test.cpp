// The limits of scenes/README.md "Limits" for values that 32-bit floats must hold: each accepted at
// the limit and refused just past it, with one line naming the field, the value and the range.
#include <gtest/gtest.h>

#include "engine/scene/range.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

#include <string>
#include <vector>

namespace vkw {
namespace {

Scene with(const std::vector<std::string>& overrides) {
    return parse_scene(test::kMinimalScene, "min.json", overrides);
}

struct Limit {
    std::string at_limit, past_limit, message;
};

TEST(scene_limits, EachAcceptedAtItsLimitAndRefusedPastIt) {
    const std::string waves = R"(water.waves={"model": "sum", "components": [{"amplitude": 1, "wavelength": )";
    const std::string ocean = R"(water.waves={"model": "fft", "wind_speed": )";
    const std::vector<Limit> limits = {
        {"camera.position=[1e5, 1, 3]", "camera.position=[1.0001e5, 1, 3]",
         "camera.position[0]: 100010 is out of range (accepted: -1e+05 <= value <= 1e+05 m)"},
        {"floor.height=-1e5", "floor.height=-1.0001e5", "floor.height: -100010 is out of range"},
        {"water.half_extent=1e5", "water.half_extent=1.0001e5",
         "water.half_extent: 100010 is out of range (accepted: 0 < value <= 1e+05 m, or \"infinite\")"},
        {waves + "1e5}]}", waves + "1.0001e5}]}", "wavelength: 100010 is out of range"},
        {"sun.irradiance=[1e30, 0, 0]", "sun.irradiance=[1.0001e30, 0, 0]",
         "sun.irradiance[0]: 1.0001e+30 is out of range (accepted: 0 <= value <= 1e+30 W m^-2)"},
        {"sky.radiance=[0, 1e30, 0]", "sky.radiance=[0, 1.0001e30, 0]",
         "sky.radiance[1]: 1.0001e+30 is out of range (accepted: 0 <= value <= 1e+30 W m^-2 sr^-1)"},
        {"camera.exposure=1e30", "camera.exposure=1.0001e30", "camera.exposure: 1.0001e+30 is out of range"},
        {R"(medium={"sigma_a": [1e6, 0, 0], "sigma_s": [0, 0, 0], "g": 0})",
         R"(medium={"sigma_a": [1.0001e6, 0, 0], "sigma_s": [0, 0, 0], "g": 0})",
         "medium.sigma_a[0]: 1000100 is out of range (accepted: 0 <= value <= 1e+06 1/m)"},
        {ocean + "990}", ocean + "991}", "wind_speed: 991 is out of range (accepted: 0 < value <= 990 m/s)"},
        // A unit sphere scaled to reach exactly 1e5 m, then a little further.
        {R"(receivers=[{"type": "sphere", "radius": 1, "scale": [1e5, 1, 1]}])",
         R"(receivers=[{"type": "sphere", "radius": 1, "scale": [1e5, 1, 1], "translation": [1, 0, 0]}])",
         "receivers[0].scale: places the mesh 100001 m from the origin (accepted: every vertex within 1e+05 m of "
         "it)"},
    };
    for (const Limit& limit : limits) {
        SCOPED_TRACE(limit.past_limit);
        EXPECT_NO_THROW(with({limit.at_limit}));
        const std::string message = test::user_error_of([&] { with({limit.past_limit}); });
        EXPECT_NE(message.find(limit.message), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

}  // namespace
}  // namespace vkw
