// vkwater render --budget-ms (render_budget.hpp).
#include "tools/vkwater/render_budget.hpp"

#include "passes/frame/supersampled_frame.hpp"
#include "tools/vkwater/budget/budget_controller.hpp"
#include "tools/vkwater/budget_previews.hpp"
#include "tools/vkwater/console.hpp"

#include <cstdio>
#include <optional>

namespace vkw::cli {
namespace {

constexpr int kMostSettingsTried = 4;

}  // namespace

std::string BudgetedSettings::describe(double budget_ms) const {
    char text[1024];
    std::snprintf(text, sizeof text,
                  "budget %.4g ms: chose %s (measured %.1f ms%s, predicted %.1f ms; relMSE +%.3g over "
                  "the scene's own settings%s%s)",
                  budget_ms, budget::describe_arguments(arguments).c_str(), measured_ms,
                  fits ? "" : ", over the budget: the cheapest setting it tried", predicted_ms, error.excess,
                  error.dominant.empty() ? "" : ", mostly the ", error.dominant.c_str());
    return text;
}

BudgetedSettings choose_budgeted_settings(Renderer& renderer, Scene& scene, RenderOptions& options, double budget_ms,
                                          uint32_t samples) {
    const Scene original = scene;
    const uint32_t width = options.width, height = options.height;
    const budget::Quality top = measured_top(renderer, scene, width, height, samples);
    budget::BudgetController controller(
        budget_ms, top,
        [&original, width, height](const budget::Quality& q) {
            return budget::cost_drivers(original, q, width, height);
        },
        [height] { return double(height); });

    struct Tried {
        budget::Quality quality;
        double measured_ms;
        double predicted_ms;
    };
    std::vector<Tried> tried;
    budget::Quality next = top;
    for (int attempt = 0; attempt < kMostSettingsTried; ++attempt) {
        scene = original;
        budget::apply_quality(next, top, scene);
        options.render_scale = next.render_scale;
        const double predicted = attempt == 0 ? 0.0 : controller.describe(next).predicted_ms;
        (void)renderer.render(scene, options);  // warm-up: one sub-frame compiles what all of them use
        const RenderResult timed = render_filtered(renderer, scene, options, pixel_filter_from_spp(next.samples));
        controller.set_current(next);
        controller.add_timed_frame(timed.timing.passes, timed.timing.total_ms);
        tried.push_back({next, timed.timing.total_ms, predicted});
        if (verbose()) {
            std::printf("budget: tried %s: measured %.1f ms, predicted %.1f ms\n",
                        budget::describe_quality(next).c_str(), timed.timing.total_ms, predicted);
        }
        const budget::Choice plan = controller.plan();
        bool seen = false;
        for (const Tried& t : tried) seen = seen || t.quality == plan.quality;
        if (seen) break;  // the plan is a setting already measured
        next = plan.quality;
    }
    // The best-ranked setting measured within the budget; the cheapest measured if none is.
    std::optional<Tried> best;
    const Tried* cheapest = &tried.front();
    for (const Tried& t : tried) {
        if (t.measured_ms < cheapest->measured_ms) cheapest = &t;
        if (t.measured_ms > budget_ms) continue;
        if (!best || budget::predict_error(t.quality, top, height).excess <
                         budget::predict_error(best->quality, top, height).excess)
            best = t;
    }
    const Tried chosen = best ? *best : *cheapest;
    scene = original;
    budget::apply_quality(chosen.quality, top, scene);
    options.render_scale = chosen.quality.render_scale;

    BudgetedSettings settings;
    settings.quality = chosen.quality;
    settings.arguments = budget::quality_arguments(chosen.quality, top, original);
    settings.measured_ms = chosen.measured_ms;
    // The prediction made before it ran (the scene's own settings ran first, unpredicted).
    settings.predicted_ms = chosen.predicted_ms > 0.0 ? chosen.predicted_ms : chosen.measured_ms;
    settings.error = budget::predict_error(chosen.quality, top, height);
    settings.fits = chosen.measured_ms <= budget_ms;
    return settings;
}

}  // namespace vkw::cli
