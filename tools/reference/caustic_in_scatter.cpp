#include "tools/reference/caustic_in_scatter.hpp"

#include "engine/core/parallel.hpp"
#include "tools/reference/optics.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace vkw::ref {

CausticInScatter::CausticInScatter(const Scene& scene, const WaterSurface& surface, double amplitude,
                                   const Settings& settings)
    : scene_(scene), level_(scene.water->level) {
    sun_up_ = scene.sun.direction.y < 0.0;
    const double ior = scene.water->ior;
    if (sun_up_) {
        refracted_sun_ = *refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / ior);
        const double cos_s = -scene.sun.direction.y, cos_t = -refracted_sun_.y;
        e_perp0_ = scene.sun.irradiance * (cos_s * (1.0 - fresnel_reflectance(cos_s, 1.0, ior)) / cos_t);
    }
    // Planes from just below the lowest trough (every beam has started) to the floor.
    const double top = amplitude * (1.0 + 1e-9) + 1e-9, bottom = std::max(top, level_ - scene.floor.height);
    const uint32_t levels = std::max(2u, settings.levels);
    for (uint32_t k = 0; k < levels; ++k) {
        depths_.push_back(top + (bottom - top) * k / (levels - 1));
        flat_.push_back(flat_horizontal_irradiance(depths_.back()));
    }
    maps_.resize(levels);
    // The planes are independent: built on every core, each by one thread.
    std::atomic<uint32_t> next{0};
    auto worker = [&] {
        for (uint32_t k = next++; k < levels; k = next++) {
            maps_[k] = std::make_unique<FloorCausticMap>(scene, surface, settings.texels_per_side,
                                                         settings.cells_per_side, settings.period, level_ - depths_[k]);
        }
    };
    run_on_threads(hardware_threads(), [&](unsigned) { worker(); });
    // Half a texel: each segment's midpoint samples the texel it mostly lies in.
    const double side = settings.period > 0.0 ? settings.period : 2.0 * scene.floor.half_extent;
    segment_length_ = 0.5 * side / settings.texels_per_side;
}

glm::dvec3 CausticInScatter::flat_horizontal_irradiance(double depth) const {
    const double cos_t = -refracted_sun_.y;
    const glm::dvec3 tau = scene_.medium.sigma_t() * (depth / cos_t);
    return e_perp0_ * cos_t * glm::dvec3(std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z));
}

glm::dvec3 CausticInScatter::modulation(const glm::dvec3& point) const {
    const double depth = std::clamp(level_ - point.y, depths_.front(), depths_.back());
    const size_t upper = std::min<size_t>(
        depths_.size() - 1, size_t(std::upper_bound(depths_.begin(), depths_.end(), depth) - depths_.begin()));
    const size_t lower = upper == 0 ? 0 : upper - 1;
    auto ratio = [&](size_t k) {
        const glm::dvec3 map = maps_[k]->irradiance(point.x, point.z);
        glm::dvec3 m(1.0);
        for (int c = 0; c < 3; ++c) {
            if (flat_[k][c] > 0.0) m[c] = map[c] / flat_[k][c];
        }
        return m;
    };
    if (lower == upper) return ratio(lower);
    const double w = (depth - depths_[lower]) / (depths_[upper] - depths_[lower]);
    return (1.0 - w) * ratio(lower) + w * ratio(upper);
}

glm::dvec3 CausticInScatter::segment_radiance(const glm::dvec3& origin, const glm::dvec3& direction, double length,
                                              const glm::dvec3& behind, glm::dvec3* in_scatter) const {
    const glm::dvec3 sigma_t = scene_.medium.sigma_t();
    glm::dvec3 radiance = behind * glm::dvec3(std::exp(-sigma_t.x * length), std::exp(-sigma_t.y * length),
                                              std::exp(-sigma_t.z * length));
    glm::dvec3 scattered(0.0);
    if (in_scatter) *in_scatter = scattered;
    if (!sun_up_ || length <= 0.0) return radiance;
    const auto segments = static_cast<uint64_t>(std::ceil(length / segment_length_));
    const double step = length / double(segments);
    for (uint64_t i = 0; i < segments; ++i) {
        const double start = i * step;
        const glm::dvec3 from = origin + start * direction;
        const glm::dvec3 m = modulation(origin + (start + 0.5 * step) * direction);
        for (int c = 0; c < 3; ++c) {
            // The segment's flat in-scatter seen from its start, carried to the ray's origin.
            const InScatterInput in{scene_.medium.sigma_s[c],
                                    sigma_t[c],
                                    scene_.medium.g,
                                    std::max(0.0, level_ - from.y),
                                    step,
                                    direction,
                                    refracted_sun_,
                                    e_perp0_[c],
                                    0.0};
            const double term = m[c] * std::exp(-sigma_t[c] * start) * water_path_radiance(in);
            radiance[c] += term;
            scattered[c] += term;
        }
    }
    if (in_scatter) *in_scatter = scattered;
    return radiance;
}

}  // namespace vkw::ref
