// LDR-FLIP (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020):
// the per-pixel perceived difference of two images with linear RGB values in [0, 1].
#pragma once

#include <array>

#include "tools/metrics/flip/csf_filters.hpp"
#include "tools/metrics/flip/features.hpp"
#include "tools/metrics/flip/plane.hpp"

namespace vkw::metrics::flip {

// Everything that depends only on the viewing distance, built once.
struct LdrFlipFilters {
    std::array<CsfFilter, 3> csf;  // by OpponentChannel
    FeatureKernels features;
};
LdrFlipFilters ldr_flip_filters(double pixels_per_degree);

// What FLIP needs of one image: its CSF-filtered colour in Hunt-adjusted L*a*b* and its
// feature magnitudes. Computed once per image (and exposure), then compared.
struct PreparedImage {
    Planes3 hunt_lab;
    FeatureMagnitudes features;
};

// `linear_rgb` holds linear RGB; values outside [0, 1] are clamped (LDR-FLIP's domain).
// The paper's LDR-FLIP input is sRGB-encoded and decoded to linear first; this takes the
// linear values directly (HDR-FLIP's tone-mapped images are linear), which is the same.
PreparedImage prepare(const Planes3& linear_rgb, const LdrFlipFilters& filters);

// Delta E = Delta E_c ^ (1 - Delta E_f) per pixel, in [0, 1]; 0 wherever the prepared images
// agree exactly (so identical inputs give exactly 0).
Plane ldr_flip(const PreparedImage& test, const PreparedImage& reference);

}  // namespace vkw::metrics::flip
