// The flat water surface y = level: the identity case every other model reduces to when
// its amplitudes are zero.
#pragma once

#include "engine/water/surface.hpp"

namespace vkw {

class FlatSurface final : public WaterSurface {
public:
    explicit FlatSurface(double level);

    SurfacePoint at_parameter(double x0, double z0) const override;
    bool is_heightfield() const override { return true; }
    double max_amplitude() const override { return 0.0; }
    double max_slope() const override { return 0.0; }
    double max_curvature() const override { return 0.0; }

private:
    double level_;
};

}  // namespace vkw
