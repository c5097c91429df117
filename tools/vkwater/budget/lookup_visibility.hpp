// What the water's scene lookups bring into the picture: for the reflected and for the refracted
// rays, the share of the frame's light that comes back from a receiver mesh along them. A lookup
// turned off loses exactly that part of each pixel (its rays keep the exact floor and sky), so the
// error model scales each lookup's term by the scene's share, as it scales the caustic knobs' by
// the caustics' visibility (quality.hpp).
//
// Traced on the CPU through the flat surface, on a coarse grid of the camera's pixels, with the
// reference renderer's ray queries: each pixel whose camera ray meets the water before any receiver
// adds, for each lookup, the weight of its ray when that ray meets a receiver before the floor
// (nothing when it does not): the Fresnel reflectance or transmittance, times the medium's
// transmittance along the ray where it runs in the water (the least extinguished channel). The
// camera ray's own path is common to both and left out. The share is the sum over every sampled
// pixel, water or not, divided by their number.
#pragma once

#include "engine/scene/scene.hpp"

#include <cstdint>

namespace vkw::budget {

struct LookupVisibility {
    double reflection = 0.0;
    double refraction = 0.0;
};

// The camera's pixels sampled per side (kLookupVisibilityRows rows, as many columns as the aspect
// gives): about 3,000 rays for a 4:3 frame.
inline constexpr uint32_t kLookupVisibilityRows = 48;

LookupVisibility lookup_visibility(const Scene& scene, double aspect);

}  // namespace vkw::budget
