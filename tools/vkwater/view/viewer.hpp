// `vkwater view`: the interactive window. Each frame: the window's events and the script's
// commands of that frame, the user interface (parameter panel, statistics overlay) and the
// camera, then one submission holding the scene's frame graph (the renderer's, ending with
// the hand-off of its HDR colour into the window's image instead of the readback) and the
// present graph of the acquired swapchain image (tonemap, overlay), waiting for the image and
// for the previous frame, and presenting. Every `timing_every` frames (and on the frame after
// the pass list changes) the scene graph runs alone instead, one pass per submission, for the
// per-pass times. With more than one sample per pixel the frame's earlier sub-frames run alone
// first, each adding its colour into the running sum that the last one's hand-off shows. With
// `frames` it stops after that many frames and prints the summary.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/window/swapchain.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vkw::window {

// The default frame-time budget on a CPU device (lavapipe): 15 frames a second.
inline constexpr double kCpuBudgetMs = 66.0;
// On a GPU when the window system does not say its refresh interval: 60 Hz.
inline constexpr double kGpuBudgetMs = 16.7;

struct ViewerOptions {
    std::filesystem::path scene;
    std::vector<std::string> overrides;  // --set, applied in order when loading the scene
    bool allow_outside_paths = false;    // --allow-outside-paths
    uint32_t width = 800, height = 600;  // the window's initial framebuffer size
    double render_scale = 1.0;           // RenderOptions::render_scale: the scene's fraction of the window per side
    // Samples per pixel (--spp, a square k^2): each frame shown is the mean of k^2 sub-frames, the
    // box filter vkwater render --spp takes, made on the device (passes/frame/accumulate.hpp).
    int64_t spp = 1;
    // --temporal: each frame jittered within its pixel and blended into the frames before it,
    // reprojected to the moved camera and clamped (RenderOptions::temporal).
    bool temporal = false;
    // The frame-time budget (tools/vkwater/budget/): nullopt for the default (the present interval
    // on a GPU, kCpuBudgetMs on a CPU device, none in scripted runs, with a render_scale or with
    // more than one sample per pixel); 0 none.
    std::optional<double> budget_ms;
    PresentMode present = PresentMode::Fifo;
    uint32_t frames = 0;                             // stop after this many frames; 0: when the window closes
    std::filesystem::path script;                    // empty: none (view_script.hpp)
    uint32_t timing_every = 30;                      // frames between per-pass timing frames; 0: never
    std::string screenshot_prefix = "vkwater-view";  // F12 writes <prefix>-<n>.exr and .png
    bool paused = false;                             // start with the water's clock stopped
    std::string device;                              // substring of the device name; empty: the best one
    bool validation = false;
    // On a CPU device, a line to print before the first frame when the scene would run slowly
    // there (empty: nothing to say); the command line fills it from its frame estimate.
    std::function<std::string(const Scene& scene, uint32_t width, uint32_t height)> cpu_frame_note;
};

// Runs the viewer; prints the device, each screenshot written and, at the end, the summary
// (frame time, per-pass times). Throws UserError / InternalError (exit codes 1 / 2), the
// latter also when validation reported anything.
void run_viewer(const ViewerOptions& options);

}  // namespace vkw::window
