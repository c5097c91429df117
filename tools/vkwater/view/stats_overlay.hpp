// The viewer's statistics overlay (Dear ImGui): frame time and rate, the per-pass times of
// the last timing frame with the method that measured them, the photon count, the frame
// graph's living passes in execution order and the culled ones with their reasons, and the
// keys. The pass list is the graph compiled for this frame: a pass culled by a new setting
// leaves it at once, and the timing list follows at the next timing frame (scheduled for the
// frame after any change of the pass list, once the new passes have made their pipelines).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "tools/vkwater/view/camera_controller.hpp"
#include "tools/vkwater/view/frame_stats.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vkw::window {

struct OverlayInfo {
    std::string device;
    std::string present_mode;
    VkExtent2D extent{};
    const FrameStats* stats = nullptr;
    const fg::FrameGraph* graph = nullptr;  // the scene graph of this frame (compiled)
    uint64_t photons = 0;                   // 0 while the caustic photon pass is culled
    uint32_t photon_grid = 0;               // R: one photon per cell of the R x R surface grid
    size_t realize_count = 0;               // Renderer::realize_count
    std::string message;                    // a refused setting, shown until the next one
    CameraMode camera_mode = CameraMode::Orbit;
    glm::dvec3 camera_position{0.0};
    bool camera_in_water = false;
    bool paused = false;
    // With a frame-time budget: its status (budget, measured and predicted time, predicted error and
    // what dominates it) and the settings it chose; empty without one.
    std::vector<std::string> budget;
};

void draw_stats_overlay(const OverlayInfo& info);

// Keys and mouse of the viewer, one line each (the overlay and --help show them).
extern const char* const kViewerKeys;

}  // namespace vkw::window
