// Real time against the reference where the reference image is locally uniform: there the colour
// depends on neither the real-time texture footprint nor where in the pixel a sample lies, so the
// two renderers must agree closely, and what differs is the shading itself. Used by the tests of
// textured, multi-material and cutout meshes.
#pragma once

#include "engine/image/image.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace vkw::test {

// Reference pixels count as uniform when every channel spans at most kFlat (relative) over the 5 x 5
// pixels around them: the real-time trilinear lookup at mip level lambda reads 2 x 2 texels of level
// ceil(lambda), each up to 2 pixels wide, so its footprint stays within 2 pixels of the centre.
// Pixels darker than kLitRadiance (a black floor, deep water) are left out: near 0 every colour is
// uniform and says nothing.
inline constexpr int kReach = 2;
inline constexpr double kFlat = 0.002;
inline constexpr float kLitRadiance = 0.02f;

// The real-time colour where the reference is uniform: within the neighbourhood's own spread
// (kFlat), an uploaded texel's half-float rounding (2^-11) and the fp32 shading's 1e-5 (the receiver
// tests').
inline constexpr double kUniformBound = kFlat + 1.0 / 2048.0 + 1e-5;

struct UniformAgreement {
    int uniform = 0;                // lit pixels whose reference neighbourhood is uniform
    int disagreeing = 0;            // of those, where the real-time colour differs by more than the bound
    std::set<std::string> colours;  // the distinct reference colours among them (quantised to 1/20)
    std::string examples;           // the first few disagreements
};

inline UniformAgreement compare_uniform(const ImageRGBA32F& real_time, const ImageRGBA32F& reference,
                                        double bound = kUniformBound) {
    UniformAgreement result;
    for (int y = kReach; y + kReach < reference.height; ++y) {
        for (int x = kReach; x + kReach < reference.width; ++x) {
            const float* centre = reference.pixel(x, y);
            if (std::max({centre[0], centre[1], centre[2]}) < kLitRadiance) continue;
            bool uniform = true;
            for (int dy = -kReach; dy <= kReach && uniform; ++dy) {
                for (int dx = -kReach; dx <= kReach && uniform; ++dx) {
                    for (int c = 0; c < 3; ++c) {
                        const double v = reference.pixel(x + dx, y + dy)[c];
                        uniform = uniform && std::abs(v - centre[c]) <= kFlat * std::max(1e-3, double(centre[c]));
                    }
                }
            }
            if (!uniform) continue;
            ++result.uniform;
            std::string key;
            for (int c = 0; c < 3; ++c) key += std::to_string(int(std::lround(centre[c] * 20.0))) + " ";
            result.colours.insert(key);
            for (int c = 0; c < 3; ++c) {
                const double difference = std::abs(real_time.pixel(x, y)[c] - centre[c]);
                if (difference <= bound * std::max(1e-3, double(centre[c]))) continue;
                if (++result.disagreeing <= 5) {
                    result.examples += " (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                                       std::to_string(c) + ": " + std::to_string(real_time.pixel(x, y)[c]) + " vs " +
                                       std::to_string(centre[c]);
                }
                break;
            }
        }
    }
    return result;
}

}  // namespace vkw::test
