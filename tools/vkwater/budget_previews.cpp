// The budget's on/off knobs measured on small frames of the scene (budget_previews.hpp).
#include "tools/vkwater/budget_previews.hpp"

#include "engine/core/errors.hpp"
#include "passes/frame/frame_needs.hpp"
#include "tools/metrics/metrics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace vkw::cli {
namespace {

uint32_t preview_height(uint32_t output_width, uint32_t output_height) {
    if (output_width == 0 || output_height == 0) throw InternalError("budget previews: an empty output");
    const double height = std::round(double(kPreviewWidth) * double(output_height) / double(output_width));
    return uint32_t(std::clamp(height, 1.0, double(4 * kPreviewWidth)));
}

// relMSE of `off` against `on` over every pixel; 0 where `on` is black (metrics::rel_mse needs a
// reference with light in it).
double excess(const ImageRGBA32F& off, const ImageRGBA32F& on) {
    double sum = 0.0;
    for (size_t i = 0; i < on.rgba.size(); i += 4) sum += double(on.rgba[i]) + on.rgba[i + 1] + on.rgba[i + 2];
    if (!(sum > 0.0)) return 0.0;
    return metrics::rel_mse(metrics::rgb_view(off), metrics::rgb_view(on),
                            metrics::counted_pixels(on.width, on.height, nullptr));
}

// The largest change of any channel of `off` against `on`, relative to `on`'s value: 0 where both
// are 0, infinite where only `off`'s is not.
double largest_relative_change(const ImageRGBA32F& off, const ImageRGBA32F& on) {
    double largest = 0.0;
    for (size_t i = 0; i < on.rgba.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha carries no light
        const double change = std::abs(double(off.rgba[i]) - double(on.rgba[i]));
        if (change == 0.0) continue;
        largest = std::max(largest, on.rgba[i] != 0.0f ? change / std::abs(double(on.rgba[i]))
                                                       : std::numeric_limits<double>::infinity());
    }
    return largest;
}

}  // namespace

OffExcessPreviews measure_off_excess(Renderer& renderer, const Scene& scene, const budget::Quality& top,
                                     uint32_t output_width, uint32_t output_height) {
    OffExcessPreviews previews;
    if (!top.reflection_lookup && !top.refraction_lookup && !top.second_layer && !top.caustics) return previews;
    const auto start = std::chrono::steady_clock::now();
    previews.width = kPreviewWidth;
    previews.height = preview_height(output_width, output_height);
    // One copy of the scene for every preview: each sets its knobs over the scene's own, put back
    // first (apply_quality sets only what lies below the top, as for the viewer's frames).
    Scene preview = scene;
    const budget::SceneKnobFields own = budget::knob_fields(preview);
    RenderOptions options;
    options.width = previews.width;
    options.height = previews.height;
    options.timing = fg::TimingMode::None;
    const auto render = [&](const budget::Quality& quality) {
        ++previews.frames;
        budget::restore_knob_fields(own, preview);
        budget::apply_quality(quality, top, preview);
        return renderer.render(preview, options).image;
    };
    const ImageRGBA32F on = render(top);
    // The top with one knob off (a refraction lookup off takes the second layer with it).
    const auto without = [&](bool budget::Quality::*knob) {
        budget::Quality quality = top;
        quality.*knob = false;
        if (!quality.refraction_lookup) quality.second_layer = false;
        return render(quality);
    };
    budget::MeasuredOffExcess& measured = previews.measured;
    if (top.reflection_lookup) measured.reflection_lookup = excess(without(&budget::Quality::reflection_lookup), on);
    if (top.refraction_lookup) measured.refraction_lookup = excess(without(&budget::Quality::refraction_lookup), on);
    if (top.second_layer) measured.second_layer = excess(without(&budget::Quality::second_layer), on);
    if (top.caustics) {
        const ImageRGBA32F off = without(&budget::Quality::caustics);
        measured.caustics = excess(off, on);
        measured.caustics_largest_change = largest_relative_change(off, on);
    }
    previews.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return previews;
}

budget::Quality measured_top(Renderer& renderer, const Scene& scene, uint32_t output_width, uint32_t output_height,
                             uint32_t samples) {
    const fg::FrameNeeds needs = decide_frame_needs(scene, double(output_width) / double(output_height));
    budget::Quality top = budget::scene_quality(scene, needs, samples);
    const OffExcessPreviews previews = measure_off_excess(renderer, scene, top, output_width, output_height);
    top.measured_off = previews.measured;
    if (previews.frames > 0) std::printf("%s\n", describe(previews).c_str());
    return top;
}

std::string describe(const OffExcessPreviews& previews) {
    if (previews.frames == 0) return "";
    char text[512];
    int length =
        std::snprintf(text, sizeof text,
                      "budget: turned off in %ux%u previews (%d frames, %.1f s), the relMSE each adds:", previews.width,
                      previews.height, previews.frames, previews.seconds);
    const char* separator = "";
    const auto add = [&](double value, const char* name) {
        if (value < 0.0 || length >= int(sizeof text)) return;
        length += std::snprintf(text + length, sizeof text - size_t(length), "%s %s %.3g", separator, name, value);
        separator = ",";
    };
    const budget::MeasuredOffExcess& measured = previews.measured;
    add(measured.reflection_lookup, "the reflection lookup");
    add(measured.refraction_lookup, "the refraction lookup");
    add(measured.second_layer, "the refraction view's second layer");
    add(measured.caustics, "the caustics");
    if (measured.caustics_largest_change >= 0.0 && length < int(sizeof text)) {
        length +=
            std::snprintf(text + length, sizeof text - size_t(length),
                          " (the most a pixel changes without them: %.3g%%)", 100.0 * measured.caustics_largest_change);
    }
    return text;
}

}  // namespace vkw::cli
