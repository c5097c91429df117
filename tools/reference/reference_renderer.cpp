#include "tools/reference/reference_renderer.hpp"

#include "tools/reference/water_transport.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
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

PixelRadiance pixel_radiance(const WaterTransport& transport, const Camera& camera, const ReferenceOptions& options,
                             uint32_t x, uint32_t y) {
    if (!options.filter.is_box()) {
        return transport.trace_camera_ray(camera_ray(camera, options.width, options.height, x + 0.5, y + 0.5));
    }
    // The box filter: the mean over the pixel's jittered strata, accumulated in double.
    PixelRadiance mean{};
    for (uint32_t i = 0; i < options.filter.samples; ++i) {
        const glm::dvec2 at = glm::dvec2(x, y) + 0.5 + options.filter.jittered_sample(x, y, i);
        const PixelRadiance sample =
            transport.trace_camera_ray(camera_ray(camera, options.width, options.height, at.x, at.y));
        mean.radiance += sample.radiance;
        mean.caustic += sample.caustic;
        mean.in_scatter += sample.in_scatter;
        mean.caustic_double_texels += sample.caustic_double_texels;
    }
    const double n = options.filter.samples;
    mean.radiance /= n;
    mean.caustic /= n;
    mean.in_scatter /= n;
    mean.caustic_double_texels /= n;
    return mean;
}

ImageRGBA32F render_reference(const Scene& scene, const ReferenceOptions& options, ReferenceReport* report) {
    const bool measure_texels = options.measure_texels && report;
    WaterTransport::Quality quality = options.quality;
    quality.estimate_texel_error = measure_texels;
    if (measure_texels) {
        WaterTransport::Quality geometry_only = quality;
        geometry_only.caustics = false;
        report->footprints = under_water_pixel_footprints(scene, WaterTransport(scene, geometry_only), options.width,
                                                          options.height, options.threads);
    }
    const WaterTransport transport(scene, quality);
    if (measure_texels) {
        report->caustic_texel = transport.caustic_texel();
        report->caustic_double_texels.assign(size_t{options.width} * options.height * 3, 0.0f);
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
                const PixelRadiance pixel = pixel_radiance(transport, scene.camera, options, x, y);
                float* out = image.pixel(static_cast<int>(x), static_cast<int>(y));
                const size_t index = size_t{y} * options.width + x;
                for (int c = 0; c < 3; ++c) {
                    out[c] = static_cast<float>(pixel.radiance[c]);
                    caustic.rgb[3 * index + c] = static_cast<float>(pixel.caustic[c]);
                    in_scatter.rgb[3 * index + c] = static_cast<float>(pixel.in_scatter[c]);
                    if (measure_texels)
                        report->caustic_double_texels[3 * index + c] =
                            static_cast<float>(pixel.caustic_double_texels[c]);
                }
                out[3] = 1.0f;
            }
            const uint32_t done = ++rows_done;
            if (reports_progress && options.progress) options.progress(double(done) / options.height);
        }
    };
    const unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned i = 1; i < threads; ++i) pool.emplace_back(worker, false);
    worker(true);  // the calling thread works too, and is the one that reports progress
    for (std::thread& thread : pool) thread.join();
    if (options.progress) options.progress(1.0);
    image.layers.push_back(std::move(caustic));
    image.layers.push_back(std::move(in_scatter));
    return image;
}

}  // namespace vkw::ref
