// How small a pixel is where it sees a receiver under the water: the caustics there are
// averaged over a texel (the floor map's) or a patch (the beams'), and a box-filtered
// reference should not carry that average as a second, wider filter. A pixel's footprint is
// the parallelogram spanned by the receiver points of the view rays through its centre and
// its right and lower neighbours' centres (through the water's surface as the image sees
// it); its width is the parallelogram's smallest extent, min(|a|, |b|, |a x b| / max(|a|, |b|)).
// Under waves the view rays focus as the sunlight does, so some pixels' footprints tend to 0:
// no finite texel resolves every pixel, and the widths are reported as a distribution.
#pragma once

#include "engine/scene/scene.hpp"
#include "tools/reference/water_transport.hpp"

#include <cstdint>
#include <vector>

namespace vkw::ref {

struct PixelFootprints {
    std::vector<double> widths;  // m, ascending, one per pixel whose three rays met receivers under the water

    double quantile(double q) const;               // 0 when no pixel was measured
    double fraction_at_least(double width) const;  // of the measured pixels
};

// `geometry`: a transport built with Quality::caustics off is enough (the rays' paths do not
// depend on the maps).
PixelFootprints under_water_pixel_footprints(const Scene& scene, const WaterTransport& geometry, uint32_t width,
                                             uint32_t height, unsigned threads = 0);

}  // namespace vkw::ref
