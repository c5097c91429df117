// The CPU device's frame time, estimated from the frame's counts (cpu_frame_estimate.hpp).
#include "tools/vkwater/cpu_frame_estimate.hpp"

#include <cmath>
#include <cstdio>

namespace vkw::cli {
namespace {

constexpr double kSecondsPerPhoton = 130e-9;
constexpr double kSecondsPerBeamColumn = 40e-9;
constexpr double kSecondsPerPixel = 350e-9;

}  // namespace

std::string CpuFrameEstimate::describe() const {
    char text[200];
    std::snprintf(text, sizeof text, "%llu photons, %llu godray beams over %u columns: about %.2g s a frame",
                  static_cast<unsigned long long>(photons), static_cast<unsigned long long>(godray_beams), godray_width,
                  seconds);
    return text;
}

CpuFrameEstimate estimate_cpu_frame(const Scene& scene, const fg::FrameNeeds& needs, uint32_t width, uint32_t height) {
    CpuFrameEstimate estimate;
    if (scene.water && needs.needs(Effect::SurfaceCaustics) &&
        scene.effects.caustics.method == CausticMethod::Photons) {
        const uint64_t side = uint64_t{scene.water->grid_resolution} * scene.effects.caustics.sub_photons;
        estimate.photons = side * side;
    }
    if (scene.water && needs.needs(Effect::VolumeCaustics) && scene.effects.godrays.method == GodrayMethod::Lines) {
        const uint64_t grid = scene.effects.godrays.grid;
        estimate.godray_beams = grid * grid;
        estimate.godray_width =
            std::max(1u, static_cast<uint32_t>(std::lround(scene.effects.godrays.resolution_scale * width)));
    }
    estimate.seconds = double(estimate.photons) * kSecondsPerPhoton +
                       double(estimate.godray_beams) * estimate.godray_width * kSecondsPerBeamColumn +
                       double(width) * height * kSecondsPerPixel;
    return estimate;
}

}  // namespace vkw::cli
