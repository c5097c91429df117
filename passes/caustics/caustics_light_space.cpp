// The caustic map's light-space frame and fixed-point scale (caustics_light_space.hpp).
#include "passes/caustics/caustics_light_space.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vkw::passes {
namespace {

constexpr uint32_t kMaxMapSide = 16384;
constexpr uint32_t kMaxPhotonsPerSide = 65536;  // R S: photon indices stay within 32 bits
// A sun closer to the horizon than this projects the floor onto a sliver; the map's v extent is
// kept at least this fraction of its u extent so that A_ls (a divisor in the resolve) stays > 0.
constexpr double kMinAspect = 1e-6;

// Unpolarised Fresnel transmittance from air into the water (docs/model.md section 2), double.
double transmittance(double cos_i, double n, double& cos_t) {
    const double sin2_t = (1.0 - cos_i * cos_i) / (n * n);
    cos_t = std::sqrt(std::max(0.0, 1.0 - sin2_t));
    const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const double rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

void check(const CausticInputs& in) {
    const bool ok = in.grid_resolution >= 1 && in.sub_photons >= 1 &&
                    uint64_t{in.grid_resolution} * in.sub_photons <= kMaxPhotonsPerSide && in.map_width >= 3 &&
                    in.map_height >= 3 && in.map_width <= kMaxMapSide && in.map_height <= kMaxMapSide &&
                    std::abs(glm::length(in.sun_direction) - 1.0) < 1e-9 && in.ior >= 1.0 && in.ior <= 2.0 &&
                    in.half_extent > 0.0 && std::isfinite(in.half_extent) && std::isfinite(in.water_level) &&
                    std::isfinite(in.floor_height) && in.max_amplitude >= 0.0 && in.fit_margin >= 0.0 &&
                    std::isfinite(in.fit_margin) && in.sun_irradiance.x >= 0.0 && in.sun_irradiance.y >= 0.0 &&
                    in.sun_irradiance.z >= 0.0 && in.sigma_t.x >= 0.0 && in.sigma_t.y >= 0.0 && in.sigma_t.z >= 0.0;
    if (!ok) {
        throw InternalError("caustics: inputs out of range (accepted: 1 <= R, S and R S <= " +
                            std::to_string(kMaxPhotonsPerSide) + "; 3 <= W, H <= " + std::to_string(kMaxMapSide) +
                            "; a unit sun direction; 1 <= n <= 2; E > 0; finite heights; amplitude, margin, E_s, "
                            "sigma_t >= 0); got R = " +
                            std::to_string(in.grid_resolution) + ", S = " + std::to_string(in.sub_photons) +
                            ", W x H = " + std::to_string(in.map_width) + " x " + std::to_string(in.map_height) +
                            ", n = " + std::to_string(in.ior));
    }
}

}  // namespace

void branchless_basis(const glm::dvec3& s, glm::dvec3& u, glm::dvec3& v) {
    const double sign = std::copysign(1.0, s.z);
    const double a = -1.0 / (sign + s.z);
    const double b = s.x * s.y * a;
    u = {1.0 + sign * s.x * s.x * a, sign * b, -sign * s.x};
    v = {b, sign + s.y * s.y * a, -s.y};
}

CausticMapFrame fit_caustic_map(const CausticInputs& in) {
    check(in);
    CausticMapFrame f;
    f.s = in.sun_direction;
    f.sun_up = f.s.y < 0.0;

    // The projection direction: the flat-water refracted sun t (straight down when the sun is
    // not up: the map then only needs to be finite).
    double cos_t = 1.0, transmit = 0.0;
    f.direction = glm::dvec3(0.0, -1.0, 0.0);
    if (f.sun_up) {
        const double cos_i = -f.s.y;
        transmit = transmittance(cos_i, in.ior, cos_t);
        const double eta = 1.0 / in.ior;
        f.direction = glm::normalize(eta * f.s + (eta * cos_i - cos_t) * glm::dvec3(0.0, 1.0, 0.0));
        cos_t = -f.direction.y;
    }
    // A point's map position: where the line along t through it crosses the mean level,
    // (x, z) + (y - level) shear with shear = -t.xz / t.y (finite: t.y <= -sqrt(1 - 1 / n^2)
    // below the surface, and for n = 1 the sun is above the horizon).
    const glm::dvec2 shear(-f.direction.x / f.direction.y, -f.direction.z / f.direction.y);
    f.shear = shear;
    // Texels of the water grid's cell size (times W - 2 = R: one per photon, aligned with them),
    // and as many more as the crests' shift along t and the margin need on each side.
    const double texel = 2.0 * in.half_extent / double(in.map_width - 2);
    const glm::dvec2 reach = in.max_amplitude * glm::abs(shear) + glm::dvec2(in.fit_margin);
    // The adaptive kernel reaches up to kAdaptiveSplatReach texels from its photon, the bilinear
    // one a texel (the border below): the difference is added so edge photons keep all their taps.
    const uint32_t kernel_reach = in.kernel == CausticKernel::Bilinear   ? 0
                                  : in.kernel == CausticKernel::Adaptive ? kAdaptiveSplatReach - 1
                                                                         : kMaxFootprintTexels - 1;
    const glm::uvec2 extra(std::ceil(reach.x / texel - 1e-9) + kernel_reach,
                           std::ceil(reach.y / texel - 1e-9) + kernel_reach);
    f.width = in.map_width + 2 * extra.x;
    f.height = in.map_height + 2 * extra.y;
    if (f.width > kMaxMapSide || f.height > kMaxMapSide) {
        throw InternalError("caustics: the map with its margin for the waves (" + std::to_string(f.width) + " x " +
                            std::to_string(f.height) + " texels) exceeds " + std::to_string(kMaxMapSide) +
                            " texels per side");
    }
    f.texel = glm::dvec2(texel, 2.0 * in.half_extent / double(in.map_height - 2));
    // Texel coordinate 0 at one texel (plus the extra ones) before the water's corner.
    f.corner = glm::dvec2(-in.half_extent) - f.texel * (glm::dvec2(extra) + 1.0);
    // A texel's area normal to t: its horizontal area at the mean level times cos(theta_t).
    f.texel_area = f.texel.x * f.texel.y * cos_t;

    // Under flat water the beam's irradiance normal to t is E_s T cos(theta_s) / cos(theta_t)
    // (the flux through a horizontal area A cos(theta_s) crosses A cos(theta_t) normal to t).
    const double depth = std::max(0.0, in.water_level - in.floor_height);
    const double cos_s = f.sun_up ? -f.s.y : 0.0;
    const double projected_bound = 4.0 * in.half_extent * in.half_extent + 16.0 * in.half_extent * in.max_amplitude;
    for (int c = 0; c < 3; ++c) {
        const double es = in.sun_irradiance[c];
        f.flat_texel_flux[c] = es * transmit * cos_s / cos_t * std::exp(-in.sigma_t[c] * depth / cos_t) * f.texel_area;
        const double incoming = es * projected_bound;
        f.lsb[c] = std::max(1e-9 * f.flat_texel_flux[c], incoming / 0x1.0p62);
        if (!(f.lsb[c] > 0.0)) f.lsb[c] = 1.0;  // E_s,c = 0: nothing is deposited in this channel
    }
    f.held = {0, 0, f.width, f.height};
    if (in.hold_read_texels_only && in.read_texels) {
        const CausticTexelRect& r = in.read_texels->bounds;
        f.held = {std::min(r.x0, f.width), std::min(r.y0, f.height), std::min(r.x1, f.width), std::min(r.y1, f.height)};
        f.held.x1 = std::max(f.held.x1, f.held.x0);
        f.held.y1 = std::max(f.held.y1, f.held.y0);
    }
    return f;
}

CausticLightSpacePush caustic_light_space_push(const CausticMapFrame& f, const CausticInputs& in) {
    // coordinate = ((x, z) + (y - level) shear - corner) / texel: affine in P, so the shaders
    // take it as dot(P - origin, axis) with origin on the mean level.
    const glm::dvec3 origin(f.corner.x, in.water_level, f.corner.y);
    const glm::dvec3 u = glm::dvec3(1.0, f.shear.x, 0.0) / f.texel.x;
    const glm::dvec3 v = glm::dvec3(0.0, f.shear.y, 1.0) / f.texel.y;
    return {{float(origin.x), float(origin.y), float(origin.z), float(in.floor_height)},
            {float(u.x), float(u.y), float(u.z), float(f.width)},
            {float(v.x), float(v.y), float(v.z), float(f.height)},
            {float(f.s.x), float(f.s.y), float(f.s.z), float(in.ior)}};
}

std::vector<uint32_t> pack_caustic_read_rows(const std::vector<CausticTexelSpan>& spans) {
    std::vector<uint32_t> packed;
    packed.reserve(2 * spans.size());
    for (const CausticTexelSpan& span : spans) packed.push_back(span.x0 | span.x1 << 16);
    const int reach = static_cast<int>(kAdaptiveSplatReach), rows = static_cast<int>(spans.size());
    for (int row = 0; row < rows; ++row) {
        uint32_t x0 = 0xffffu, x1 = 0;
        for (int near = std::max(0, row - reach); near <= std::min(rows - 1, row + reach); ++near) {
            if (spans[near].x1 <= spans[near].x0) continue;
            x0 = std::min(x0, spans[near].x0 - std::min<uint32_t>(spans[near].x0, kAdaptiveSplatReach));
            x1 = std::max(x1, spans[near].x1 + kAdaptiveSplatReach);
        }
        packed.push_back(x1 > x0 ? x0 | std::min<uint32_t>(x1, 0xffffu) << 16 : 0u);
    }
    return packed;
}

}  // namespace vkw::passes
