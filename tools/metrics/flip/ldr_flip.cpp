// LDR-FLIP: colour pipeline (YCxCz, CSF filtering, Hunt-adjusted L*a*b*, HyAB) and feature
// pipeline (edges and points of the achromatic channel), combined per pixel.
#include "tools/metrics/flip/ldr_flip.hpp"

#include <algorithm>
#include <cmath>

#include "tools/metrics/flip/colour_spaces.hpp"

namespace vkw::metrics::flip {

LdrFlipFilters ldr_flip_filters(double pixels_per_degree) {
    return LdrFlipFilters{{csf_filter(OpponentChannel::Achromatic, pixels_per_degree),
                           csf_filter(OpponentChannel::RedGreen, pixels_per_degree),
                           csf_filter(OpponentChannel::BlueYellow, pixels_per_degree)},
                          feature_kernels(pixels_per_degree)};
}

PreparedImage prepare(const Planes3& linear_rgb, const LdrFlipFilters& filters) {
    const int w = linear_rgb[0].width, h = linear_rgb[0].height;
    Planes3 ycxcz = make_planes3(w, h);
    Plane achromatic(w, h);
    for (std::size_t i = 0; i < achromatic.size(); ++i) {
        Vec3 rgb{};
        for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(static_cast<double>(linear_rgb[c][i]), 0.0, 1.0);
        const Vec3 o = linear_rgb_to_ycxcz(rgb);
        for (int c = 0; c < 3; ++c) ycxcz[c][i] = static_cast<float>(o[c]);
        achromatic[i] = static_cast<float>(normalised_achromatic(o[0]));
    }
    Planes3 filtered;
    for (int c = 0; c < 3; ++c) filtered[c] = apply_csf(ycxcz[c], filters.csf[c]);

    PreparedImage out{make_planes3(w, h), detect_features(achromatic, filters.features)};
    for (std::size_t i = 0; i < achromatic.size(); ++i) {
        const Vec3 rgb = ycxcz_to_linear_rgb({filtered[0][i], filtered[1][i], filtered[2][i]});
        const Vec3 lab = hunt_adjusted_lab(rgb);  // clamps to the RGB cube first
        for (int c = 0; c < 3; ++c) out.hunt_lab[c][i] = static_cast<float>(lab[c]);
    }
    return out;
}

Plane ldr_flip(const PreparedImage& test, const PreparedImage& reference) {
    const Plane& size = reference.features.edge;
    Plane out(size.width, size.height);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const Vec3 a{test.hunt_lab[0][i], test.hunt_lab[1][i], test.hunt_lab[2][i]};
        const Vec3 b{reference.hunt_lab[0][i], reference.hunt_lab[1][i], reference.hunt_lab[2][i]};
        const double colour = colour_error(hyab(a, b));
        const double feature = feature_error(test.features.edge[i], reference.features.edge[i], test.features.point[i],
                                             reference.features.point[i]);
        // The formula colour^(1 - feature), except that an exact colour match is no error: this
        // differs from it only where feature is exactly 1 and pow(0, 0) would give the maximum.
        out[i] = colour == 0.0 ? 0.0f : static_cast<float>(std::pow(colour, 1.0 - feature));
    }
    return out;
}

}  // namespace vkw::metrics::flip
