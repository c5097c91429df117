#include "passes/frame/supersampled_frame.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <vector>

namespace vkw {

void add_sub_frame_times(fg::FrameReport& sum, const fg::FrameReport& sub) {
    for (const fg::PassTime& pass : sub.passes) {
        const auto same = std::find_if(sum.passes.begin(), sum.passes.end(),
                                       [&](const fg::PassTime& p) { return p.pass == pass.pass; });
        if (same != sum.passes.end()) {
            same->ms += pass.ms;
        } else {
            sum.passes.push_back(pass);
        }
    }
    sum.total_ms += sub.total_ms;
}

std::vector<glm::dvec2> sub_frame_shifts(const PixelFilter& filter, uint32_t width, uint32_t height) {
    std::vector<glm::dvec2> shifts;
    for (uint32_t i = 0; i < filter.samples; ++i) {
        shifts.push_back(image_shift_for_pixel_offset(filter.stratum_centre(i), width, height));
    }
    return shifts;
}

RenderResult render_filtered(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                             const PixelFilter& filter, const std::function<void(uint32_t done)>& after_sub_frame) {
    if (!filter.is_box()) {
        RenderResult result = renderer.render(scene, options);
        if (after_sub_frame) after_sub_frame(1);
        return result;
    }
    Scene shifted = scene;
    RenderOptions sub_options = options;
    sub_options.sub_frame_shifts = sub_frame_shifts(filter, options.width, options.height);
    RenderResult sum;
    std::vector<std::vector<float>> layers;  // the sums of the sub-frames' layers, as the first names them
    for (uint32_t i = 0; i < filter.samples; ++i) {
        shifted.camera.image_shift_ndc = sub_options.sub_frame_shifts[i];
        // The first sub-frame makes the caustic map for all of them; the others read it.
        sub_options.caustic_map_carry = i == 0 ? CausticMapCarry::Keep : CausticMapCarry::Reuse;
        RenderResult sub = renderer.render(shifted, sub_options);
        if (after_sub_frame) after_sub_frame(i + 1);
        if (i == 0) {
            sum = std::move(sub);
            for (const ExtraLayer& layer : sum.image.layers) layers.push_back(layer.rgb);
            continue;
        }
        if (sub.image.rgba.size() != sum.image.rgba.size() || sub.image.layers.size() != layers.size()) {
            throw InternalError("supersampling: the sub-frames differ in their images");
        }
        for (size_t k = 0; k < sum.image.rgba.size(); ++k) sum.image.rgba[k] += sub.image.rgba[k];
        for (size_t l = 0; l < layers.size(); ++l) {
            for (size_t k = 0; k < layers[l].size(); ++k) layers[l][k] += sub.image.layers[l].rgb[k];
        }
        add_sub_frame_times(sum.timing, sub.timing);
    }
    const float scale = 1.0f / static_cast<float>(filter.samples);
    for (float& value : sum.image.rgba) value *= scale;
    for (size_t l = 0; l < layers.size(); ++l) {
        for (size_t k = 0; k < layers[l].size(); ++k) sum.image.layers[l].rgb[k] = layers[l][k] * scale;
    }
    return sum;
}

}  // namespace vkw
