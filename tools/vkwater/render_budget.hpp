// vkwater render --budget-ms B: the settings the frame-time budget chooses for one image
// (tools/vkwater/budget/), at most the samples per pixel the command asked for (--spp N: a
// box-filtered frame of N sub-frames, each timed in full). A timed frame at the scene's own settings fits the cost model; the
// plan's candidate is rendered and timed in turn, until the plan stays or four settings have been
// tried; the answer is the best-ranked setting measured within the budget (the cheapest measured
// if none was). Each setting's first frame is a warm-up (llvmpipe compiles shader variants on first
// use) and its second the timed one: per-pass fence times on a CPU device, timestamps on a GPU.
#pragma once

#include "passes/frame/renderer.hpp"
#include "tools/vkwater/budget/error_model.hpp"
#include "tools/vkwater/budget/quality.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace vkw::cli {

struct BudgetedSettings {
    budget::Quality quality;
    std::vector<std::string> arguments;  // the options that give it explicitly
    double predicted_ms = 0.0;
    double measured_ms = 0.0;  // its timed frame
    budget::ErrorPrediction error;
    bool fits = false;  // measured within the budget
    // "budget 66 ms: chose --render-scale 0.5 ... (measured 61.0 ms, predicted 58.1 ms; relMSE +0.086
    // over the scene's own settings, mostly the resolution scale)".
    std::string describe(double budget_ms) const;
};

// Chooses, then leaves `scene` and `options.render_scale` at the choice (the scene's own
// settings are what `scene` holds on entry); the chosen samples per pixel are `quality.samples`, at
// most `samples`.
BudgetedSettings choose_budgeted_settings(Renderer& renderer, Scene& scene, RenderOptions& options, double budget_ms,
                                          uint32_t samples = 1);

}  // namespace vkw::cli
