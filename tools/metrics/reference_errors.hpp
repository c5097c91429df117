// Every error `vkwater bench` reports for one rendered frame against its reference: the four
// metrics at full resolution, the same at box-downsampled resolution, and the relMSE of the
// caustic and in-scatter layers when both images carry them. The reference's share of the work (its downsampled
// copy and both HDR-FLIP exposure ranges) is done once, for every frame compared with it.
#pragma once

#include <optional>
#include <string>

#include "engine/image/image.hpp"
#include "tools/metrics/flip/hdr_flip.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw::metrics {

// The layer holding the sun's irradiance on the receiver each pixel sees under the water
// (EXR channels caustic.R/G/B), written by `vkwater reference`.
inline constexpr const char* kCausticLayer = "caustic";
// The layer holding the single-scattered radiance of each pixel's primary path in the water alone
// (EXR channels inscatter.R/G/B): `vkwater reference` always, `vkwater render` where the godrays run.
inline constexpr const char* kInScatterLayer = "inscatter";

// A layer's relMSE, or why there is none.
struct LayerRelMse {
    std::optional<double> value;
    std::string missing_reason;  // set when value is empty
    // The number (%g-like, 6 significant digits), or "n/a" (with_reason: "n/a (<reason>)").
    std::string text(bool with_reason = false) const;
};

// relMSE of the layer `layer` of test against reference over the pixels `mask` selects
// (nullptr: all), or no value when either image lacks the layer or the reference's layer is
// black over those pixels (relMSE divides by its mean). Throws what rel_mse throws otherwise
// (a size mismatch, non-finite values).
LayerRelMse layer_rel_mse(const ImageRGBA32F& test, const ImageRGBA32F& reference, const std::string& layer,
                          const ImageRGBA32F* mask = nullptr);

struct FrameErrors {
    Metrics full;           // at the images' resolution
    Metrics downsampled;    // both images box-downsampled by the factor
    LayerRelMse caustic;    // the caustic layer's relMSE at full resolution
    LayerRelMse inscatter;  // the in-scatter layer's
};

class ReferenceErrors {
public:
    // Keeps a copy of `reference`. Throws UserError for a factor out of range (box_downsample).
    ReferenceErrors(ImageRGBA32F reference, int downsample_factor);

    FrameErrors measure(const ImageRGBA32F& test) const;
    int downsample_factor() const { return factor_; }
    const ImageRGBA32F& reference() const { return reference_; }

private:
    ImageRGBA32F reference_;
    int factor_;
    ImageRGBA32F reference_downsampled_;
    FlipExposureRange range_, range_downsampled_;  // each from its own reference
};

}  // namespace vkw::metrics
