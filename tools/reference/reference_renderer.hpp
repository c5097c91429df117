// The CPU reference renderer: one ray through each pixel's centre (the real-time renderer also
// evaluates at pixel centres), or with a box filter the mean of k x k rays jittered within the
// pixel's strata by a hash of the pixel (engine/scene/pixel_filter.hpp; with
// Quality::caustics_over_footprints the strata's centres, their caustics integrated over their
// footprints), traced exactly through the model in double precision, on every core,
// deterministic. The image carries two layers: `caustic`, the sun's irradiance on the receiver
// each pixel sees under the water, 0 elsewhere; `inscatter`, the single-scattered radiance of
// the pixel's primary path in the water alone (PixelRadiance).
#pragma once

#include "engine/image/image.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/scene.hpp"
#include "tools/reference/bvh.hpp"
#include "tools/reference/pixel_footprint.hpp"
#include "tools/reference/water_transport.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vkw::ref {

struct ReferenceOptions {
    uint32_t width = 400;
    uint32_t height = 300;
    unsigned threads = 0;                  // 0: every hardware thread
    std::function<void(double)> progress;  // called with the finished fraction
    WaterTransport::Quality quality;       // wavy water's floor caustics (coarser: faster, for small tests)
    PixelFilter filter;                    // a pixel's samples: its centre, or k x k jittered strata
    // Measure the caustics' texels against the pixels that read them: the pixels' footprints
    // under the water and the caustic layer at twice the texel side (ReferenceReport).
    bool measure_texels = false;
};

// The primary ray through pixel (x, y)'s centre, row 0 at the top: the same camera
// convention as the real-time renderer (passes/common/frame_constants.cpp).
Ray camera_ray(const Camera& camera, uint32_t width, uint32_t height, double x, double y);

// What the reference knows of its own error.
struct ReferenceReport {
    double caustic_refinement_change = 0.0;   // relative RMS change of the floor caustics on refinement
    std::vector<std::string> approximations;  // what the image keeps approximate, one sentence each
    double surface_height_error_bound = 0.0;  // m: the FFT ocean's sampled series (0: exact surfaces)
    double surface_slope_error_bound = 0.0;
    // With ReferenceOptions::measure_texels: the caustics' texel (m, 0 for closed forms), the
    // pixels' footprint widths under the water, and the caustic layer (RGB, row-major) one
    // level coarser.
    double caustic_texel = 0.0;    // 0 also over footprints (Quality::caustics_over_footprints)
    std::string coarser_caustics;  // what caustic_coarser is (WaterTransport::coarser_caustics)
    PixelFootprints footprints;
    std::vector<float> caustic_coarser;
};

// Pixel (x, y)'s radiance and layers under options.filter: the ray through its centre, or the
// mean of its jittered strata's rays.
// `geometry` (a transport of the same scene with Quality::caustics off), when given, traces the
// rays that measure each sample's footprint for Quality::caustics_over_footprints.
PixelRadiance pixel_radiance(const WaterTransport& transport, const WaterTransport* geometry, const Camera& camera,
                             const ReferenceOptions& options, uint32_t x, uint32_t y);

ImageRGBA32F render_reference(const Scene& scene, const ReferenceOptions& options, ReferenceReport* report = nullptr);

}  // namespace vkw::ref
