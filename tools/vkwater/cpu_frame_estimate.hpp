// How long a frame takes on a CPU device (lavapipe on this project's 2-core machines), estimated
// before it runs from what drives its cost, so that a setting that runs for seconds a frame says so
// first (scenes/README.md "Limits"). The rates are the ones measured on pool at 800x600
// (docs/performance.md): 130 ns per caustic photon, 40 ns per godray beam per column of the
// godray image (a beam's walk is about as long as the image is wide), and 350 ns per output pixel
// for all the screen passes together. It counts neither the meshes' scene-view marches nor the FFT
// ocean's passes, so it reads low by up to 4x on the built-in scenes (lake 0.11 s against 0.41 s
// measured at 400x300, ocean 0.21 against 0.87, pool 0.21 against 0.28): it is there to flag the
// settings that run for seconds a frame (pool with 1024^2 godray beams: 8.6 s estimated, 8.7 s
// measured). On a GPU every figure is far smaller.
#pragma once

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene.hpp"

#include <cstdint>
#include <string>

namespace vkw::cli {

struct CpuFrameEstimate {
    uint64_t photons = 0;          // traced a frame (0 where the caustic passes do not run)
    uint64_t godray_beams = 0;     // walked a frame (0 where the godray lines do not run)
    uint32_t godray_width = 0;     // columns of the godray image
    double seconds = 0.0;          // the estimate
    std::string describe() const;  // "1048576 photons, 4096 godray beams over 400 columns, 480000 pixels: 0.37 s"
};

CpuFrameEstimate estimate_cpu_frame(const Scene& scene, const fg::FrameNeeds& needs, uint32_t width, uint32_t height);

// Above this a command prints the estimate as a note before it starts.
inline constexpr double kSlowCpuFrameSeconds = 5.0;
// The viewer's threshold: a frame a second is a slideshow, not a view.
inline constexpr double kSlowViewFrameSeconds = 1.0;

}  // namespace vkw::cli
