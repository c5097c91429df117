#include "tools/reference/water_transport.hpp"

#include "engine/core/errors.hpp"
#include "engine/scene/builtin_meshes.hpp"
#include "engine/scene/range.hpp"
#include "engine/water/sampled_ocean_surface.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/texture_lookup.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numbers>

namespace vkw::ref {
namespace {

// The floor is the first mesh of the BVH (the constructor puts it there).
constexpr uint32_t kFloorReceiver = 0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Ray origins are pushed off the surface they leave by this much (metres): far above
// double rounding at scene scale (1e-15 * 1e3 m), far below any feature of a scene.
constexpr double kOffset = 1e-9;
// Surface events along one path from the air: the camera's ray and up to three more reflections
// between the waves. Each costs at least the reflectance at its angle; past the fourth the ray
// takes what radiance_in_air sees.
constexpr int kMaxSurfaceBounces = 4;
constexpr double kSunDiskSolidAngle = 6.80e-5;  // docs/model.md section 1
constexpr double kSunDiskAngularRadiusDeg = 0.2666;

glm::dvec3 exp3(const glm::dvec3& x) { return {std::exp(x.x), std::exp(x.y), std::exp(x.z)}; }

}  // namespace

WaterTransport::~WaterTransport() = default;

WaterTransport::WaterTransport(const Scene& scene, const Quality& quality)
    : scene_(scene), estimate_caustic_resolution_(quality.estimate_caustic_resolution) {
    const bool wavy = scene.water && scene.water->waves.model != WaveModel::Flat;
    const bool ocean = wavy && scene.water->waves.model == WaveModel::FftOcean;
    // The floor joins the receivers as one more mesh, the first (kFloorReceiver).
    Mesh floor = make_plane_mesh({scene.floor.half_extent, scene.floor.half_extent});
    transform_mesh(floor, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, scene.floor.height, 0.0)));
    extra_meshes_.push_back(std::move(floor));
    std::vector<const Mesh*> meshes{&extra_meshes_[0]};
    albedo_parts_.push_back({{0, static_cast<uint32_t>(extra_meshes_[0].indices.size()), scene.floor.albedo}});
    for (const Receiver& receiver : scene.receivers) {
        meshes.push_back(&receiver.mesh);
        albedo_parts_.push_back(receiver_albedo_parts(receiver));
    }
    meshes_ = meshes;
    const bool cutouts =
        std::any_of(albedo_parts_.begin(), albedo_parts_.end(), [](const std::vector<MeshPart>& parts) {
            return std::any_of(parts.begin(), parts.end(),
                               [](const MeshPart& part) { return part.alpha_cutoff >= 0.0; });
        });
    TriangleBvh::CutOut cut_out_test;
    if (cutouts) {
        cut_out_test = [this](uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric) {
            return cut_out(receiver, triangle, barycentric);
        };
    }
    bvh_ = std::make_unique<TriangleBvh>(meshes, std::move(cut_out_test));

    has_water_ = scene.water.has_value();
    if (has_water_) {
        level_ = scene.water->level;
        half_extent_ = scene.water->half_extent;
        infinite_ = scene.water->infinite;
        bottom_ = water_bottom(scene);
        ior_ = scene.water->ior;
    }
    sun_up_ = scene.sun.direction.y < 0.0;
    const double cos_s = -scene.sun.direction.y;
    if (sun_up_) {
        refracted_sun_ = *refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / ior_);  // never TIR from air
        const double cos_t = -refracted_sun_.y;
        const double transmittance = 1.0 - fresnel_reflectance(cos_s, 1.0, ior_);
        e_perp0_ = scene.sun.irradiance * (cos_s * transmittance / cos_t);
    }
    if (infinite_) {
        approximations_.push_back(
            "infinite water: the waves out to " + format_number(kInfiniteWaterFarField) +
            " m from each ray's origin (horizontally), the flat mean level beyond; the photon beams and the "
            "in-scatter maps over the receivers' square (half side " +
            format_number(half_extent_) +
            " m); a ray in the water that meets no receiver runs to the water's bottom (y = " + format_number(bottom_) +
            " m), where nothing is lit, or to the far field if that is nearer");
    }
    if (ocean) {
        build_ocean(quality);
    } else if (wavy) {
        surface_ = make_surface(scene.water->waves, level_, scene.water->time);
        max_amplitude_ = surface_->max_amplitude();
        shortest_wavelength_ = std::numeric_limits<double>::infinity();
        for (const WaveComponent& wave : scene.water->waves.components) {
            if (wave.amplitude > 0.0) shortest_wavelength_ = std::min(shortest_wavelength_, wave.wavelength);
        }
        // The beam maps' surface cells per side grow as 1 / wavelength; their work and memory as its
        // square. Beyond kMaxBeamCells per side (a 1e-6 m wave asked for 6.4e8, a 35 GB map) the
        // reference refuses, naming the wave and the shortest wavelength it accepts.
        constexpr double kMaxBeamCells = 16384.0;
        const double densest = std::max(quality.cells_per_wavelength, quality.in_scatter_cells_per_wavelength);
        const double wanted = std::ceil(2.0 * half_extent_ / shortest_wavelength_ * densest);
        if (!(wanted <= kMaxBeamCells)) {
            char text[300];
            std::snprintf(text, sizeof text,
                          "%s: water.waves: the shortest wavelength, %g m, needs %.3g beam cells per side over the "
                          "water's %g m at %g cells per wavelength (accepted: at most %.0f, a wavelength of at least "
                          "%.3g m)",
                          scene.source.string().c_str(), shortest_wavelength_, wanted, 2.0 * half_extent_, densest,
                          kMaxBeamCells, 2.0 * half_extent_ * densest / kMaxBeamCells);
            throw UserError(text);
        }
        const auto cells =
            static_cast<uint32_t>(std::ceil(2.0 * half_extent_ / shortest_wavelength_ * quality.cells_per_wavelength));
        if (!quality.caustics) {
            // The view rays' geometry alone: no maps.
        } else if (meshes_under_water() || quality.caustics_over_footprints) {
            // Meshes under the waves, or caustics over footprints: every receiver (the floor
            // too, so that the meshes shadow it) takes the beams averaged over a patch the size
            // of the floor map's texel (or over the footprint its ray is given), at the floor
            // map's coarse cell density (memory: 56 bytes per vertex) and at half of it for the
            // error estimate (kept, over footprints, for the per-pixel one).
            const double patch = 2.0 * scene.floor.half_extent / quality.floor_texels;  // the floor map's texel
            beams_ = std::make_unique<BeamIrradiance>(scene, *surface_, cells, patch);
            auto coarser = std::make_unique<BeamIrradiance>(scene, *surface_, std::max(1u, cells / 2), patch);
            caustic_refinement_change_ = estimate_beam_refinement(*coarser);
            if (quality.caustics_over_footprints && quality.estimate_caustic_resolution)
                coarser_beams_ = std::move(coarser);
            approximations_.push_back(
                quality.caustics_over_footprints
                    ? "caustics under waves: the beams of " + std::to_string(cells) +
                          " surface cells per side averaged over each sample's share of its pixel's footprint on "
                          "the receiver (the parallelogram of the neighbouring strata's rays; over a " +
                          std::to_string(patch) + " m square for paths after a reflection)"
                    : "caustics under waves: the beams of " + std::to_string(cells) +
                          " surface cells per side averaged over a " + std::to_string(patch) + " m square");
        } else {
            RefinedFloorCaustics caustics = refine_floor_caustics(scene, *surface_, quality.floor_texels, cells);
            floor_caustics_ = std::move(caustics.map);
            caustic_refinement_change_ = caustics.relative_rms_change;
        }
    }
    if (wavy && (!quality.caustic_in_scatter || !quality.caustics)) {
        approximations_.push_back("in-scatter along view rays follows the flat surface's beam (no godray modulation)");
    } else if (wavy) {
        CausticInScatter::Settings godrays;
        godrays.levels = quality.in_scatter_levels;
        if (ocean) {
            godrays.texels_per_side = quality.ocean_in_scatter_texels;
            godrays.cells_per_side = quality.ocean_in_scatter_cells;
            godrays.period = static_cast<const SampledOceanSurface&>(*surface_).period();
        } else {
            godrays.texels_per_side = quality.in_scatter_texels;
            godrays.cells_per_side = static_cast<uint32_t>(
                std::ceil(2.0 * half_extent_ / shortest_wavelength_ * quality.in_scatter_cells_per_wavelength));
        }
        in_scatter_ = std::make_unique<CausticInScatter>(scene, *surface_, max_amplitude_, godrays);
        approximations_.push_back(
            "in-scatter under waves: the beam-mapped irradiance on " + std::to_string(godrays.levels) +
            " horizontal planes from the lowest trough to the floor (" + std::to_string(godrays.texels_per_side) +
            " texels, " + std::to_string(godrays.cells_per_side) +
            " surface cells per side), linear in depth between them, the top plane's above it; each beam's "
            "direction taken as the flat refracted one (E_perp = E_h / cos(theta_t), the phase function at t); "
            "not shadowed by meshes");
    }
    sky_average_ = sky_average_radiance(scene.sky);
    hemispherical_transmittance_ = hemispherical_transmittance(ior_);
    sun_disk_cos_ = std::cos(kSunDiskAngularRadiusDeg * std::numbers::pi / 180.0);
}

bool WaterTransport::meshes_under_water() const {
    return std::any_of(scene_.receivers.begin(), scene_.receivers.end(),
                       [&](const Receiver& r) { return r.mesh.bounds_min.y < level_ + max_amplitude_; });
}

void WaterTransport::build_ocean(const Quality& quality) {
    const WaveSettings& waves = scene_.water->waves;
    const FftOceanSpectrum spectrum = make_ocean_spectrum(waves.ocean, waves.seed);
    auto ocean = std::make_unique<SampledOceanSurface>(spectrum, waves.ocean.choppiness, level_, scene_.water->time,
                                                       quality.ocean_padding);
    max_amplitude_ = ocean->max_amplitude();
    shortest_wavelength_ = ocean->shortest_wavelength();
    // Between samples the slope may exceed the sampled maximum (by its interpolation error,
    // and by the true slope's own rise between samples P n / (patch / shortest wavelength)
    // >= 5 per shortest wave apart): 1.5 times the sampled maximum bounds it with room.
    crossing_slope_ = 1.5 * ocean->max_sample_slope();
    surface_height_error_bound_ = ocean->error_bound()[kOceanHeight];
    surface_slope_error_bound_ = std::max(ocean->error_bound()[kOceanSlopeX], ocean->error_bound()[kOceanSlopeZ]);
    const double period = ocean->period();
    surface_ = std::move(ocean);
    if (meshes_under_water()) {
        throw UserError(scene_.source.string() +
                        ": receivers: the reference renderer does not compute receiver meshes under an FFT ocean yet "
                        "(accepted: meshes entirely above y = " +
                        std::to_string(level_ + max_amplitude_) + ", the highest crest)");
    }
    if (quality.caustics_over_footprints) {
        throw UserError(scene_.source.string() +
                        ": water.waves.model: the reference averages the FFT ocean's caustics over its periodic floor "
                        "map's texels, not over pixel footprints (accepted: footprints under the model sum; for "
                        "fft, a finer map with --floor-texels)");
    }
    if (quality.caustics) {
        RefinedFloorCaustics caustics = refine_floor_caustics(scene_, *surface_, quality.ocean_floor_texels,
                                                              quality.ocean_cells_per_period, period);
        floor_caustics_ = std::move(caustics.map);
        caustic_refinement_change_ = caustics.relative_rms_change;
    }
    // Beams that reach the floor near the water's edge may have entered beyond it, where the
    // periodic map still counts a surface: within the largest sideways drift of a beam
    // (refracted at the steepest sampled slope) over the water's depth, plus the amplitude.
    approximations_.push_back(
        "FFT ocean: the surface is the zero-padded FFT samples (padding " + std::to_string(quality.ocean_padding) +
        ") with Hermite patches, error bound " + std::to_string(surface_height_error_bound_) + " m in height, " +
        std::to_string(surface_slope_error_bound_) + " in slope; the floor's caustics are one period's map repeated" +
        (infinite_ ? std::string() : ", also near the water's edge where some beams would have entered beyond it"));
}

BeamIrradiance::Visibility WaterTransport::beam_visibility() const {
    // Shadowed along the beam by objects under the water, then along the sun's direction
    // by objects above it.
    return [this](const glm::dvec3& point, const glm::dvec3& direction, double path, const glm::dvec3& entry) {
        return !bvh_->any_hit({point - kOffset * direction, -direction}, path - 2.0 * kOffset) &&
               !sun_blocked_in_air(entry + glm::dvec3(0.0, kOffset, 0.0));
    };
}

double WaterTransport::estimate_beam_refinement(const BeamIrradiance& coarse) const {
    // The receivers' triangle centres under the water, at most about 2000 of them spread
    // evenly over the meshes (the floor is the first), each lit by the fine and the coarse
    // beams: the relative RMS difference of the two over the points that receive light.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> points;  // position, normal
    const auto add_mesh = [&](const Mesh& mesh, size_t stride) {
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3 * stride) {
            const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
                c(mesh.positions[mesh.indices[t + 2]]);
            const glm::dvec3 centre = (a + b + c) / 3.0;
            glm::dvec3 normal = glm::cross(b - a, c - a);
            if (glm::length(normal) == 0.0 || !in_water(centre)) continue;
            normal = glm::normalize(normal);
            if (glm::dot(normal, -refracted_sun_) < 0.0) normal = -normal;  // the lit side
            points.emplace_back(centre, normal);
        }
    };
    size_t triangles = extra_meshes_[0].indices.size() / 3;
    for (const Receiver& receiver : scene_.receivers) triangles += receiver.mesh.indices.size() / 3;
    const size_t stride = std::max<size_t>(1, triangles / 2000);
    add_mesh(extra_meshes_[0], 1);  // the floor's two triangles
    for (const Receiver& receiver : scene_.receivers) add_mesh(receiver.mesh, stride);
    // Measured as the metrics measure images (tools/metrics: relMSE scales by the mean and
    // drops the worst 0.1% of values): point values near focal lines are integrable spikes
    // whose peaks move with the triangulation, and would otherwise dominate an RMS.
    std::vector<double> squared_differences;
    double sum = 0.0;
    for (const auto& [point, normal] : points) {
        const glm::dvec3 fine = beams_->irradiance(point, normal, beam_visibility());
        const glm::dvec3 rough = coarse.irradiance(point, normal, beam_visibility());
        squared_differences.push_back(glm::dot(fine - rough, fine - rough) / 3.0);
        sum += (fine.x + fine.y + fine.z) / 3.0;
    }
    if (points.empty() || sum <= 0.0) return 0.0;
    std::sort(squared_differences.begin(), squared_differences.end());
    const size_t kept = squared_differences.size() - std::max<size_t>(1, squared_differences.size() / 1000);
    double trimmed = 0.0;
    for (size_t i = 0; i < kept; ++i) trimmed += squared_differences[i];
    const double mean = sum / double(points.size());
    return std::sqrt(trimmed / double(std::max<size_t>(kept, 1))) / mean;
}

double WaterTransport::surface_height(double x, double z) const {
    return surface_ ? surface_->height_at(x, z) : level_;
}

std::optional<WaterTransport::WaterHit> WaterTransport::water_surface_hit(const Ray& ray) const {
    if (!has_water_) return std::nullopt;
    const double horizontal = std::hypot(ray.direction.x, ray.direction.z);
    // Infinite water's far field: a ray that crosses the mean level farther than the far field
    // (horizontally) meets it there, flat; the waves are searched no farther.
    double wave_reach = kInfinity;
    if (infinite_) {
        const double to_level = (level_ - ray.origin.y) / ray.direction.y;
        if (to_level > 0.0 && std::isfinite(to_level) && to_level * horizontal > kInfiniteWaterFarField) {
            return WaterHit{to_level, {0.0, 1.0, 0.0}};
        }
        if (horizontal > 0.0) wave_reach = kInfiniteWaterFarField / horizontal;
    }
    if (!surface_) {
        if (ray.direction.y == 0.0) return std::nullopt;
        const double t = (level_ - ray.origin.y) / ray.direction.y;
        if (t <= 0.0 || !over_water(ray.origin + t * ray.direction)) return std::nullopt;
        return WaterHit{t, {0.0, 1.0, 0.0}};
    }
    // The part of the ray inside the slab between the lowest trough and the highest crest.
    const double low = level_ - max_amplitude_, high = level_ + max_amplitude_;
    double t0 = 0.0, t1 = 0.0;
    if (ray.direction.y == 0.0) {
        if (ray.origin.y < low || ray.origin.y > high) return std::nullopt;
        t1 = 4.0 * half_extent_ + glm::length(ray.origin);  // long enough to leave the extent
    } else {
        const double a = (low - ray.origin.y) / ray.direction.y, b = (high - ray.origin.y) / ray.direction.y;
        t0 = std::max(0.0, std::min(a, b));
        t1 = std::max(a, b);
        if (t1 <= 0.0) return std::nullopt;
    }
    t1 = std::min(t1, wave_reach);
    if (t1 < t0) return std::nullopt;
    // f > 0 above the surface; the crossing is the first sign change along the ray.
    auto f = [&](double t) {
        const glm::dvec3 p = ray.origin + t * ray.direction;
        return p.y - surface_->height_at(p.x, p.z);
    };
    const double step = std::min((t1 - t0) / 4.0, shortest_wavelength_ / 64.0 / std::max(horizontal, 1e-12));
    // |df/dt| <= |d_y| + |d_h| max|grad h|: no crossing lies within |f| / that of a point.
    const double lipschitz = std::abs(ray.direction.y) + horizontal * crossing_slope_;
    const double start_sign = f(t0) > 0.0 ? 1.0 : -1.0;
    double previous = t0;
    for (double t = t0 + step; previous < t1;) {
        const double here = std::min(t, t1);
        const double f_here = f(here);
        if (f_here * start_sign <= 0.0) {
            double lo = previous, hi = here;
            for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
                const double mid = 0.5 * (lo + hi);
                (f(mid) * start_sign > 0.0 ? lo : hi) = mid;
            }
            const glm::dvec3 p = ray.origin + hi * ray.direction;
            if (!over_water(p)) return std::nullopt;
            const glm::dvec2 parameter = surface_->parameter_at(p.x, p.z);
            return WaterHit{hi, surface_->at_parameter(parameter.x, parameter.y).normal};
        }
        previous = here;
        t = here + (crossing_slope_ > 0.0 ? std::max(step, std::abs(f_here) / lipschitz) : step);
    }
    return std::nullopt;
}

bool WaterTransport::in_water(const glm::dvec3& p) const {
    // Height exactly at the level counts as above (the same tie-break as the stencil
    // split). The bottom is usually the floor itself, and a floor hit can round a hair
    // below it: points within kBottomTolerance of the bottom are in the water.
    constexpr double kBottomTolerance = 1e-6;
    return has_water_ && over_water(p) && p.y >= bottom_ - kBottomTolerance && p.y < surface_height(p.x, p.z);
}

bool WaterTransport::over_water(const glm::dvec3& p) const {
    return infinite_ || (std::abs(p.x) <= half_extent_ && std::abs(p.z) <= half_extent_);
}

std::optional<WaterTransport::SurfaceHit> WaterTransport::closest_receiver(const Ray& ray, double max_distance) const {
    const auto hit = bvh_->closest_hit(ray, max_distance);
    if (!hit) return std::nullopt;
    return SurfaceHit{hit->distance, glm::dvec3(base_color_at(hit->receiver, hit->triangle, hit->barycentric)),
                      hit->normal};
}

const MeshPart& WaterTransport::part_of(uint32_t receiver, uint32_t triangle) const {
    const std::vector<MeshPart>& parts = albedo_parts_[receiver];
    // The last part that starts at or before the triangle's first index (parts are in index order).
    const auto after = std::upper_bound(parts.begin(), parts.end(), 3 * triangle,
                                        [](uint32_t i, const MeshPart& part) { return i < part.first_index; });
    return after == parts.begin() ? parts.front() : *std::prev(after);
}

glm::dvec4 WaterTransport::base_color_at(uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric) const {
    const MeshPart& part = part_of(receiver, triangle);
    const Mesh& mesh = *meshes_[receiver];
    const uint32_t index = 3 * triangle;
    const std::array<uint32_t, 3> corner = {mesh.indices[index], mesh.indices[index + 1], mesh.indices[index + 2]};
    const std::array<double, 3> weight = {1.0 - barycentric.x - barycentric.y, barycentric.x, barycentric.y};
    if (receiver == kFloorReceiver && scene_.floor.tiles) {
        glm::dvec3 point(0.0);
        for (int k = 0; k < 3; ++k) point += weight[k] * glm::dvec3(mesh.positions[corner[k]]);
        return glm::dvec4(scene_.floor.albedo_at(point.x, point.z), 1.0);
    }
    glm::dvec4 color(part.base_color, part.alpha);
    if (part.texture >= 0) {
        glm::dvec2 uv(0.0);
        for (int k = 0; k < 3; ++k) uv += weight[k] * glm::dvec2(mesh.uvs[corner[k]]);
        color *= bilinear_base_color(mesh.textures[std::size_t(part.texture)], uv);
    }
    if (!mesh.colors.empty()) {
        glm::dvec4 vertex_color(0.0);
        for (int k = 0; k < 3; ++k) vertex_color += weight[k] * glm::dvec4(mesh.colors[corner[k]]);
        color *= vertex_color;
    }
    return color;
}

bool WaterTransport::cut_out(uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric) const {
    const double cutoff = part_of(receiver, triangle).alpha_cutoff;
    return cutoff >= 0.0 && base_color_at(receiver, triangle, barycentric).a < cutoff;
}

bool WaterTransport::sun_blocked_in_air(const glm::dvec3& point) const {
    return bvh_->any_hit({point, -scene_.sun.direction}, kInfinity);
}

glm::dvec3 WaterTransport::sun_irradiance_under_water(const glm::dvec3& point, const glm::dvec3& normal,
                                                      const BeamIrradiance::Patch* footprint) const {
    if (!sun_up_) return glm::dvec3(0.0);
    if (floor_caustics_) return floor_caustics_->irradiance(point.x, point.z);  // only the floor is under wavy water
    if (beams_ && footprint) return beams_->irradiance(point, normal, beam_visibility(), *footprint);
    if (beams_) return beams_->irradiance(point, normal, beam_visibility());
    const double cos_receiver = std::max(0.0, -glm::dot(refracted_sun_, normal));
    if (cos_receiver == 0.0) return glm::dvec3(0.0);
    // Shadowed along the refracted beam by objects under the water, then along the
    // sun's direction by objects above it.
    const double path = (level_ - point.y) / -refracted_sun_.y;
    const Ray up{point + kOffset * normal, -refracted_sun_};
    if (bvh_->any_hit(up, path)) return glm::dvec3(0.0);
    const glm::dvec3 entry = point - path * refracted_sun_;
    if (sun_blocked_in_air(entry + glm::dvec3(0.0, kOffset, 0.0))) return glm::dvec3(0.0);
    return e_perp0_ * cos_receiver * exp3(-scene_.medium.sigma_t() * path);
}

glm::dvec3 WaterTransport::sun_irradiance_one_level_coarser(const glm::dvec3& point, const glm::dvec3& normal,
                                                            const BeamIrradiance::Patch* footprint) const {
    if (!sun_up_) return glm::dvec3(0.0);
    if (floor_caustics_) return floor_caustics_->irradiance_over_double_texels(point.x, point.z);
    if (coarser_beams_) {
        return footprint ? coarser_beams_->irradiance(point, normal, beam_visibility(), *footprint)
                         : coarser_beams_->irradiance(point, normal, beam_visibility());
    }
    if (beams_) return beams_->irradiance(point, normal, beam_visibility(), 2.0 * beams_->patch());
    return sun_irradiance_under_water(point, normal);
}

std::string WaterTransport::coarser_caustics() const {
    if (floor_caustics_) return "the floor map's texel twice as wide";
    if (coarser_beams_) return "the beams from half the surface cells per side";
    if (beams_) return "the beams' patch twice as wide";
    return "";
}

double WaterTransport::caustic_texel() const {
    if (floor_caustics_) return floor_caustics_->texel_size();
    return beams_ ? beams_->patch() : 0.0;
}

glm::dvec3 WaterTransport::receiver_radiance(const glm::dvec3& point, const SurfaceHit& hit, PixelRadiance* primary,
                                             const BeamIrradiance::Patch* footprint) const {
    glm::dvec3 irradiance;
    if (in_water(point)) {
        const glm::dvec3 sun = sun_irradiance_under_water(point, hit.normal, primary ? footprint : nullptr);
        if (primary) {
            primary->caustic = sun;
            primary->caustic_point = point;
            primary->caustic_normal = hit.normal;
            if (estimate_caustic_resolution_)
                primary->caustic_coarser = sun_irradiance_one_level_coarser(point, hit.normal, footprint);
        }
        const double depth = level_ - point.y;
        irradiance = sun + std::numbers::pi * sky_average_ * hemispherical_transmittance_ *
                               exp3(-scene_.medium.sigma_t() * depth);
    } else {
        glm::dvec3 sun(0.0);
        if (sun_up_) {
            const double cos_sun = std::max(0.0, -glm::dot(scene_.sun.direction, hit.normal));
            if (cos_sun > 0.0 && !sun_blocked_in_air(point + kOffset * hit.normal))
                sun = scene_.sun.irradiance * cos_sun;
        }
        irradiance = sun + std::numbers::pi * sky_average_;
    }
    return hit.albedo * irradiance / std::numbers::pi;
}

glm::dvec3 WaterTransport::radiance_in_air(const Ray& ray) const {
    if (const auto hit = closest_receiver(ray, kInfinity)) {
        return receiver_radiance(ray.origin + hit->distance * ray.direction, *hit, nullptr);
    }
    glm::dvec3 radiance = sky_radiance(scene_.sky, ray.direction);
    if (sun_up_ && glm::dot(ray.direction, -scene_.sun.direction) >= sun_disk_cos_) {
        radiance += scene_.sun.irradiance / kSunDiskSolidAngle;
    }
    return radiance;
}

glm::dvec3 WaterTransport::radiance_reflected_into_air(const Ray& ray, int bounces) const {
    if (bounces < kMaxSurfaceBounces) {
        if (const std::optional<WaterHit> water = water_surface_hit(ray)) {
            if (!closest_receiver(ray, water->distance)) {
                return radiance_from_air_at_surface(ray.origin + water->distance * ray.direction, water->normal,
                                                    ray.direction, bounces + 1, nullptr, nullptr);
            }
        }
    }
    return radiance_in_air(ray);
}

glm::dvec3 WaterTransport::radiance_from_air_at_surface(const glm::dvec3& p, const glm::dvec3& up,
                                                        const glm::dvec3& direction, int bounces, PixelRadiance* pixel,
                                                        const BeamIrradiance::Patch* footprint) const {
    // A wave's back face seen from above: grazing incidence, all reflected.
    const double cos_i = std::max(0.0, -glm::dot(direction, up));
    const double reflectance = fresnel_reflectance(cos_i, 1.0, ior_);
    const glm::dvec3 l_reflected =
        radiance_reflected_into_air({p + kOffset * up, glm::reflect(direction, up)}, bounces);
    glm::dvec3 l_water(0.0), in_scatter(0.0);
    if (const auto refracted = refract(direction, up, 1.0 / ior_); refracted && cos_i > 0.0) {
        l_water = radiance_in_water_to_receiver({p - kOffset * up, *refracted}, pixel, pixel ? &in_scatter : nullptr,
                                                footprint);
    }
    if (pixel) pixel->in_scatter = (1.0 - reflectance) / (ior_ * ior_) * in_scatter;
    return reflectance * l_reflected + (1.0 - reflectance) / (ior_ * ior_) * l_water;
}

glm::dvec3 WaterTransport::in_water_segment(const glm::dvec3& origin, double length, const glm::dvec3& direction,
                                            const glm::dvec3& behind, glm::dvec3* in_scatter) const {
    if (in_scatter_) return in_scatter_->segment_radiance(origin, direction, length, behind, in_scatter);
    // A segment that starts in a crest above the mean level uses depth 0.
    const double z0 = std::max(0.0, level_ - origin.y);
    glm::dvec3 radiance;
    const glm::dvec3 sigma_t = scene_.medium.sigma_t();
    for (int c = 0; c < 3; ++c) {
        InScatterInput in{
            scene_.medium.sigma_s[c],    sigma_t[c], scene_.medium.g, z0, length, direction, refracted_sun_,
            sun_up_ ? e_perp0_[c] : 0.0, behind[c]};
        radiance[c] = water_path_radiance(in);
        if (in_scatter) {
            in.l_behind = 0.0;
            (*in_scatter)[c] = water_path_radiance(in);
        }
    }
    return radiance;
}

glm::dvec3 WaterTransport::radiance_in_water_to_receiver(const Ray& ray, PixelRadiance* primary, glm::dvec3* in_scatter,
                                                         const BeamIrradiance::Patch* footprint) const {
    const auto hit = closest_receiver(ray, kInfinity);
    // A ray that leaves the water body without meeting a receiver sees nothing (the scenes close
    // their water with a floor or walls). Under infinite water it runs on to the water's bottom,
    // where nothing is lit, but no farther than the far field from its origin, horizontally.
    const double length = hit ? hit->distance : run_to_bottom(ray);
    const glm::dvec3 behind =
        hit ? receiver_radiance(ray.origin + hit->distance * ray.direction, *hit, primary, footprint) : glm::dvec3(0.0);
    return in_water_segment(ray.origin, length, ray.direction, behind, in_scatter);
}

double WaterTransport::run_to_bottom(const Ray& ray) const {
    if (!infinite_ || !(ray.direction.y < 0.0)) return 0.0;
    const double to_bottom = (bottom_ - ray.origin.y) / ray.direction.y;
    const double horizontal = std::hypot(ray.direction.x, ray.direction.z);
    const double to_far_field = horizontal > 0.0 ? kInfiniteWaterFarField / horizontal : to_bottom;
    return std::max(std::min(to_bottom, to_far_field), 0.0);
}

PixelRadiance WaterTransport::trace_camera_ray(const Ray& ray, const BeamIrradiance::Patch* footprint) const {
    PixelRadiance pixel;
    const bool camera_in_water = in_water(ray.origin);
    const std::optional<WaterHit> water_hit = water_surface_hit(ray);
    const double to_surface = water_hit ? water_hit->distance : kInfinity;
    const glm::dvec3 surface_normal = water_hit ? water_hit->normal : glm::dvec3(0.0, 1.0, 0.0);
    const auto receiver = closest_receiver(ray, to_surface);

    if (!camera_in_water) {
        if (receiver || to_surface == kInfinity) {  // nothing but air on the way
            if (receiver) {
                pixel.radiance = receiver_radiance(ray.origin + receiver->distance * ray.direction, *receiver, &pixel);
            } else {
                pixel.radiance = radiance_in_air(ray);
            }
            return pixel;
        }
        // The surface from above: reflect into the air, refract into the water.
        pixel.radiance = radiance_from_air_at_surface(ray.origin + to_surface * ray.direction, surface_normal,
                                                      ray.direction, 1, &pixel, footprint);
        return pixel;
    }

    // Camera in the water.
    if (receiver) {
        const glm::dvec3 behind =
            receiver_radiance(ray.origin + receiver->distance * ray.direction, *receiver, &pixel, footprint);
        pixel.radiance = in_water_segment(ray.origin, receiver->distance, ray.direction, behind, &pixel.in_scatter);
        return pixel;
    }
    if (to_surface == kInfinity) {  // out through the side, or under infinite water to its bottom
        pixel.radiance =
            in_water_segment(ray.origin, run_to_bottom(ray), ray.direction, glm::dvec3(0.0), &pixel.in_scatter);
        return pixel;
    }
    // The surface from below: Snell's window, total internal reflection outside it.
    const glm::dvec3 p = ray.origin + to_surface * ray.direction;
    const glm::dvec3 down = -surface_normal;
    const double cos_i = std::max(0.0, glm::dot(ray.direction, surface_normal));
    const double reflectance = fresnel_reflectance(cos_i, ior_, 1.0);
    // The reflected path's in-scatter belongs to the layer too, weighted as in the pixel (by the
    // reflectance, 1 under total internal reflection, and the first segment's transmittance).
    glm::dvec3 reflected_in_scatter(0.0);
    glm::dvec3 at_surface =
        reflectance * radiance_in_water_to_receiver({p + kOffset * down, glm::reflect(ray.direction, down)}, nullptr,
                                                    &reflected_in_scatter);
    if (const auto refracted = refract(ray.direction, down, ior_)) {
        at_surface += (1.0 - reflectance) * ior_ * ior_ * radiance_in_air({p - kOffset * down, *refracted});
    }
    pixel.radiance = in_water_segment(ray.origin, to_surface, ray.direction, at_surface, &pixel.in_scatter);
    const glm::dvec3 first_segment = exp3(-scene_.medium.sigma_t() * to_surface);
    pixel.in_scatter += reflectance * first_segment * reflected_in_scatter;
    return pixel;
}

}  // namespace vkw::ref
