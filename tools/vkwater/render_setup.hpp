// What `vkwater render` shares between its one-frame form and its sequences (--frames): the
// options, the scene with them applied, the device and the renderer's options.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/vk/context.hpp"
#include "passes/frame/renderer.hpp"
#include "tools/vkwater/commands.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vkw::cli {

struct RenderArgs {
    std::string scene;
    std::string out;
    uint32_t width = 800;
    uint32_t height = 600;
    bool half = false;
    bool png = false;
    bool check_finite = false;
    bool no_caustic_layer = false;
    bool no_inscatter_layer = false;
    uint32_t repeat = 1;
    int64_t spp = 1;
    double render_scale = 1.0;  // RenderOptions::render_scale
    double budget_ms = 0.0;     // --budget-ms: 0 none; else the budget chooses the settings (render_budget.hpp)
    std::string recording = "dynamic";
    std::vector<std::string> overrides;
    bool allow_outside_paths = false;
    std::string reference;
    std::optional<double> exposure;  // the preview's, in place of the scene's camera.exposure
    DeviceOptions device;
    // A sequence: the frames, their rate and this process's share of them.
    std::string frames;  // "A:B[:STEP]"; empty: one frame
    double fps = 24.0;
    std::string shard;      // "I/N"; empty: every frame
    bool temporal = false;  // --temporal: accumulate over the sequence's frames (RenderOptions::temporal)
};

// The --set overrides with --exposure as the override camera.exposure, so that the EXR's record
// of the settings names it.
std::vector<std::string> applied_overrides(const RenderArgs& args);

RenderOptions render_options(const RenderArgs& args);

// The EXR's record of the resolution scale: "0.5: the scene rendered at 400x300, stretched to the
// image bilinearly"; empty at 1.
std::string render_scale_text(const RenderOptions& options);

// The Vulkan device the options name, with a line saying which and how long it took.
std::unique_ptr<Context> open_render_device(const DeviceOptions& options);

// On the CPU device (lavapipe), a note when `frames` frames of the scene will take long.
void note_slow_cpu_frames(const Context& context, const Scene& scene, const RenderArgs& args, uint32_t frames);

// vkwater render --frames (render_sequence.cpp).
int run_render_sequence(const RenderArgs& args);

}  // namespace vkw::cli
