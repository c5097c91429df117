#include "tools/reference/reference_renderer.hpp"

#include "engine/core/parallel.hpp"
#include "tools/reference/water_transport.hpp"

#include <algorithm>
#include <atomic>
#include <optional>
#include <vector>

namespace vkw::ref {

Ray camera_ray(const Camera& camera, uint32_t width, uint32_t height, double x, double y) {
    const glm::dmat4 view = view_matrix(camera);
    const glm::dmat4 inverse = glm::inverse(projection_matrix(camera, double(width) / double(height)) * view);
    const glm::dvec2 ndc{2.0 * x / width - 1.0, 1.0 - 2.0 * y / height};
    const glm::dvec4 on_near_plane = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 point = glm::dvec3(on_near_plane) / on_near_plane.w;
    return {camera.position, glm::normalize(point - camera.position)};
}

namespace {

// The receiver footprint of the sample at `at` (pixels) standing for a square of `side`
// pixels: the parallelogram spanned by the central differences of the receiver points of the
// rays half a side to either side, in the receiver's tangent plane. None where a ray misses
// the water's receivers or the four do not see one surface (a silhouette: left to the texel).
std::optional<BeamIrradiance::Patch> sample_footprint(const WaterTransport& geometry, const Camera& camera,
                                                      const ReferenceOptions& options, glm::dvec2 at, double side) {
    auto seen = [&](glm::dvec2 offset) {
        const glm::dvec2 p = at + 0.5 * side * offset;
        return geometry.trace_camera_ray(camera_ray(camera, options.width, options.height, p.x, p.y));
    };
    const PixelRadiance left = seen({-1, 0}), right = seen({1, 0}), up = seen({0, -1}), down = seen({0, 1});
    if (!left.caustic_point || !right.caustic_point || !up.caustic_point || !down.caustic_point) return std::nullopt;
    const glm::dvec3 normal = left.caustic_normal;
    BeamIrradiance::Patch patch{*right.caustic_point - *left.caustic_point, *down.caustic_point - *up.caustic_point};
    for (glm::dvec3* edge : {&patch.u, &patch.v}) {
        const double off_plane = glm::dot(*edge, normal);
        // Across a crease of a mesh the points leave the plane by the crease's angle; across a
        // silhouette by as much as they move along it.
        if (std::abs(off_plane) > 0.5 * glm::length(*edge)) return std::nullopt;
        *edge -= off_plane * normal;
    }
    return patch;
}

}  // namespace

PixelRadiance pixel_radiance(const WaterTransport& transport, const WaterTransport* geometry, const Camera& camera,
                             const ReferenceOptions& options, uint32_t x, uint32_t y) {
    // One sample at `at`, standing for a square of `side` pixels around it.
    auto sample_at = [&](glm::dvec2 at, double side) {
        const Ray ray = camera_ray(camera, options.width, options.height, at.x, at.y);
        if (!geometry) return transport.trace_camera_ray(ray);
        const std::optional<BeamIrradiance::Patch> footprint = sample_footprint(*geometry, camera, options, at, side);
        return transport.trace_camera_ray(ray, footprint ? &*footprint : nullptr);
    };
    if (!options.filter.is_box()) return sample_at(glm::dvec2(x, y) + 0.5, 1.0);
    // The box filter: the mean over the pixel's jittered strata, accumulated in double. Over
    // footprints each stratum is sampled at its centre, so that the strata's footprints tile
    // the pixel's (a jittered one would overlap its neighbour's on one side and leave a gap on
    // the other, which near a focal line is a random error of the line's whole flux).
    PixelRadiance mean{};
    const double stratum = 1.0 / options.filter.side();
    for (uint32_t i = 0; i < options.filter.samples; ++i) {
        const glm::dvec2 offset = geometry ? options.filter.stratum_centre(i) : options.filter.jittered_sample(x, y, i);
        const PixelRadiance sample = sample_at(glm::dvec2(x, y) + 0.5 + offset, stratum);
        mean.radiance += sample.radiance;
        mean.caustic += sample.caustic;
        mean.in_scatter += sample.in_scatter;
        mean.caustic_coarser += sample.caustic_coarser;
    }
    const double n = options.filter.samples;
    mean.radiance /= n;
    mean.caustic /= n;
    mean.in_scatter /= n;
    mean.caustic_coarser /= n;
    return mean;
}

ImageRGBA32F render_reference(const Scene& scene, const ReferenceOptions& options, ReferenceReport* report) {
    const bool measure_texels = options.measure_texels && report;
    WaterTransport::Quality quality = options.quality;
    quality.estimate_caustic_resolution = measure_texels;
    WaterTransport::Quality geometry_only = quality;
    geometry_only.caustics = false;
    geometry_only.caustic_in_scatter = false;
    // The view rays' paths alone: for the footprints, measured or integrated over.
    std::optional<WaterTransport> geometry;
    if (measure_texels || quality.caustics_over_footprints) geometry.emplace(scene, geometry_only);
    if (measure_texels) {
        report->footprints =
            under_water_pixel_footprints(scene, *geometry, options.width, options.height, options.threads);
    }
    const WaterTransport* footprint_rays = quality.caustics_over_footprints ? &*geometry : nullptr;
    const WaterTransport transport(scene, quality);
    if (measure_texels) {
        // Over footprints each sample averages over its own share of its pixel instead.
        report->caustic_texel = quality.caustics_over_footprints ? 0.0 : transport.caustic_texel();
        report->coarser_caustics = transport.coarser_caustics();
        report->caustic_coarser.assign(size_t{options.width} * options.height * 3, 0.0f);
    }
    if (report) {
        report->caustic_refinement_change = transport.caustic_refinement_change();
        report->approximations = transport.approximations();
        report->surface_height_error_bound = transport.surface_height_error_bound();
        report->surface_slope_error_bound = transport.surface_slope_error_bound();
    }
    ImageRGBA32F image;
    image.width = static_cast<int>(options.width);
    image.height = static_cast<int>(options.height);
    image.rgba.assign(size_t{options.width} * options.height * 4, 0.0f);
    ExtraLayer caustic{"caustic", std::vector<float>(size_t{options.width} * options.height * 3, 0.0f)};
    ExtraLayer in_scatter{"inscatter", std::vector<float>(size_t{options.width} * options.height * 3, 0.0f)};

    // Rows are handed out one at a time; each pixel is a pure function of the scene,
    // so the image does not depend on the number of threads or their timing.
    std::atomic<uint32_t> next_row{0};
    std::atomic<uint32_t> rows_done{0};
    auto worker = [&](bool reports_progress) {
        for (uint32_t y = next_row++; y < options.height; y = next_row++) {
            for (uint32_t x = 0; x < options.width; ++x) {
                const PixelRadiance pixel = pixel_radiance(transport, footprint_rays, scene.camera, options, x, y);
                float* out = image.pixel(static_cast<int>(x), static_cast<int>(y));
                const size_t index = size_t{y} * options.width + x;
                for (int c = 0; c < 3; ++c) {
                    out[c] = static_cast<float>(pixel.radiance[c]);
                    caustic.rgb[3 * index + c] = static_cast<float>(pixel.caustic[c]);
                    in_scatter.rgb[3 * index + c] = static_cast<float>(pixel.in_scatter[c]);
                    if (measure_texels)
                        report->caustic_coarser[3 * index + c] = static_cast<float>(pixel.caustic_coarser[c]);
                }
                out[3] = 1.0f;
            }
            const uint32_t done = ++rows_done;
            if (reports_progress && options.progress) options.progress(double(done) / options.height);
        }
    };
    // The calling thread (index 0) works too, and is the one that reports progress.
    run_on_threads(options.threads ? options.threads : hardware_threads(), [&](unsigned index) { worker(index == 0); });
    if (options.progress) options.progress(1.0);
    image.layers.push_back(std::move(caustic));
    image.layers.push_back(std::move(in_scatter));
    return image;
}

}  // namespace vkw::ref
