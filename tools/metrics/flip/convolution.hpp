// The one filtering primitive FLIP needs: a 1D kernel along x or y, edges clamped.
#pragma once

#include <span>

#include "tools/metrics/flip/plane.hpp"

namespace vkw::metrics::flip {

enum class Axis { X, Y };

// out(p) = sum_i kernel[i + r] * in(p + i * axis), i = -r..r, kernel.size() = 2r + 1, with
// coordinates outside the image clamped to the nearest edge pixel (the reference
// implementation's border mode too: a constant image stays constant up to the border).
// This is correlation, not convolution: for the antisymmetric edge kernel that flips the
// sign, which FLIP never sees because it uses only magnitudes. Sums are taken in double.
Plane correlate(const Plane& in, std::span<const double> kernel, Axis axis);

// The separable 2D filter kernel_x (along x) times kernel_y (along y).
Plane correlate_separable(const Plane& in, std::span<const double> kernel_x, std::span<const double> kernel_y);

}  // namespace vkw::metrics::flip
