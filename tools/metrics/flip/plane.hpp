// One float channel of an image, the unit FLIP's filters work on.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace vkw::metrics::flip {

struct Plane {
    int width = 0;
    int height = 0;
    std::vector<float> values;  // row-major, row 0 at the top

    Plane() = default;
    Plane(int w, int h) : width(w), height(h), values(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}

    std::size_t size() const { return values.size(); }
    float& operator[](std::size_t i) { return values[i]; }
    float operator[](std::size_t i) const { return values[i]; }
};

// Three planes of one colour space (linear RGB, YCxCz or Hunt-adjusted L*a*b*).
using Planes3 = std::array<Plane, 3>;

inline Planes3 make_planes3(int width, int height) {
    return {Plane(width, height), Plane(width, height), Plane(width, height)};
}

}  // namespace vkw::metrics::flip
