// What the frame-time budget's on/off knobs cost this scene in error, measured on the scene itself
// (vkwater render/view --budget-ms). The error table (budget/error_model.hpp) holds, for each knob,
// the worst loss of the scenes it was measured on; for a knob that turns a whole effect off that
// worst case says little about another scene: turning off the reflected rays' scene lookup adds
// relMSE 0.136 to box, whose red box is reflected in the water, and 0.0019 to lake, whose loss is
// in the refracted rays (0.128). So each such knob the scene runs is turned off in one small frame
// of the scene, and the relMSE of that frame against the same frame with the knob on is the knob's
// term (Quality::measured_off). Against the committed sweep (docs/sweeps/budget_error_terms.csv,
// 400x300 against the references) these previews at 160x120 measured 0.67 to 1.15 of the sweep's
// excess for every such term the sweep put above 0.0005, and 0 where it measured 0
// (tools/benchmarks/budget_previews.sh; docs/performance-log.md "The on/off knobs measured on the scene"): what these
// knobs lose is whole objects in the water, which a small frame resolves about as a large one does.
//
// The knobs: the reflected rays' and the refracted rays' scene lookups, the refraction view's
// second layer and the surface caustics, each where the scene's own settings run it. The previews cost one frame each at
// 160 pixels wide plus one with everything on, made at the view's start, at a reload, and again
// where the viewer's camera comes to rest after moving (what a knob loses depends on what is seen).
#pragma once

#include "passes/frame/renderer.hpp"
#include "tools/vkwater/budget/quality.hpp"

#include <string>

namespace vkw::cli {

// The previews' width; their height keeps the output's aspect.
inline constexpr uint32_t kPreviewWidth = 160;

struct OffExcessPreviews {
    budget::MeasuredOffExcess measured;
    uint32_t width = 0, height = 0;  // of each preview
    int frames = 0;                  // rendered (0: the scene runs none of the knobs)
    double seconds = 0.0;            // they took, pipelines made for them included
};

// Renders `scene` at the previews' size with `top`'s knobs and with each on/off knob of `top`
// turned off (budget::apply_quality) and returns what each adds: the relMSE of the frame with it
// off against the frame with everything on (0 where that frame is black: nothing to lose). Knobs
// `top` does not run stay unmeasured (below 0).
OffExcessPreviews measure_off_excess(Renderer& renderer, const Scene& scene, const budget::Quality& top,
                                     uint32_t output_width, uint32_t output_height);

// The budget's top for `scene` (the scene's own settings at `samples` per pixel, for the effects
// its needs at the output's aspect run), with its on/off knobs measured by the previews above; prints
// the previews' line. What `render --budget-ms` and the viewer start from.
budget::Quality measured_top(Renderer& renderer, const Scene& scene, uint32_t output_width, uint32_t output_height,
                             uint32_t samples);
// One line for the console: "budget: turned off in 160x120 previews (4 frames, 1.2 s), the relMSE
// each adds: the reflection lookup 0.138, ..." ("" when nothing was measured).
std::string describe(const OffExcessPreviews& previews);

}  // namespace vkw::cli
