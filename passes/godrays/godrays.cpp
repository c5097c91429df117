// add_godray_passes (godrays.hpp).
#include "passes/godrays/godrays.hpp"

#include "passes/godrays/godrays_beams.hpp"
#include "passes/godrays/godrays_blur.hpp"
#include "passes/godrays/godrays_composite.hpp"
#include "passes/godrays/godrays_depth.hpp"
#include "passes/godrays/godrays_lines.hpp"
#include "passes/godrays/godrays_march.hpp"
#include "passes/godrays/godrays_resolve.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::passes {
namespace {

// The frame graph's size of an output-relative image (FrameGraph::image_width): lround, at least 1.
uint32_t scaled(uint32_t size, float scale) { return std::max(1u, static_cast<uint32_t>(std::lround(scale * size))); }

}  // namespace

void add_godray_passes(fg::FrameGraph& graph, const GodrayInputs& inputs) {
    const GodraySettings& settings = inputs.settings;
    const auto scale = static_cast<float>(settings.resolution_scale);
    const double max_depth = settings.max_depth.value_or(1e30);
    const fg::ImageHandle view_depth = add_godray_depth_pass(graph, scale);
    if (settings.method == GodrayMethod::Marched) {
        const fg::ImageHandle radiance =
            add_godray_march_pass(graph, {view_depth, scale, settings.march_steps, inputs.max_amplitude, max_depth});
        add_godray_composite_pass(graph, radiance, view_depth, inputs.inscatter_layer);
        return;
    }
    const fg::BufferHandle beams =
        add_godray_beams_pass(graph, {inputs.surface, inputs.surface_resolution, settings.grid, max_depth});
    const uint32_t width = scaled(inputs.width, scale), height = scaled(inputs.height, scale);
    const fg::BufferHandle counters =
        add_godray_lines_passes(graph, {beams, settings.grid, view_depth, width, height, inputs.max_amplitude});
    const fg::ImageHandle radiance = add_godray_resolve_pass(graph, counters, view_depth, scale, width, height);
    add_godray_composite_pass(graph, add_godray_blur(graph, radiance, view_depth, scale), view_depth,
                              inputs.inscatter_layer);
}

}  // namespace vkw::passes
