// The godray lines (docs/model.md section 6; de la Fuente 2011 section 4.6): every beam
// of add_godray_beams_pass is walked over the godray pixels it crosses by a compute shader (a DDA
// along the line's major axis, shaders/godrays/godray_lines.comp), depositing the in-scattered
// radiance Delta L = Phi0 sigma_s p(cos alpha) exp(-sigma_t (d_in + s_w)) l_pix / A_pix in each,
// depth-tested against the scene (add_godray_depth_pass), in the three views of a point under the
// water: directly and mirrored in the surface for a camera in the water, and refracted through the
// flat surface at the mean level (times T(theta_v) / n^2) for a camera above it. With the stencil
// split's mask the views are chosen per pixel, else by the frame's camera medium.
// A beam is a tube as wide as its photon cell; it deposits at the level of a radiance pyramid where
// its width spans one to two pixels (near the camera a coarse one), which add_godray_resolve_pass
// sums back. The pyramids hold the radiance without the flat beam's phase function and the
// surface's weight (R or T / n^2), which the resolve applies per pixel, so that a coarse level
// never blurs the phase function's forward peak: one pyramid for the direct or refracted view, one
// for the mirrored. Deposits are rounded to 64-bit fixed point (shaders/godrays/godray_fixed_point.glsl)
// and added with integer atomics, so two runs are bit-identical.
// Two passes: "godray clear" (transfer) zeroes the counters, "godray lines" (compute) walks.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

struct GodrayLineInputs {
    fg::BufferHandle beams;          // add_godray_beams_pass's output
    uint32_t grid = 64;              // G: its beams per side
    fg::ImageHandle view_depth;      // add_godray_depth_pass's output
    uint32_t width = 0, height = 0;  // its size (the godray resolution)
    double max_amplitude = 0.0;      // m: a bound on the waves' height above the mean level
};

// The radiance pyramids (shaders/godrays/godray_pyramid.glsl): levels down to four to eight pixels
// on the longer side, max(1, floor(log2(max(width, height))) - 1) levels (at most 13 for 16384 px),
// and the size in bytes of the two.
uint32_t godray_pyramid_levels(uint32_t width, uint32_t height);
VkDeviceSize godray_pyramid_bytes(uint32_t width, uint32_t height);

// Returns the radiance pyramid's counters, in units of godray_lsb(). Reads the frame constants.
// Serves VolumeCaustics.
fg::BufferHandle add_godray_lines_passes(fg::FrameGraph& graph, const GodrayLineInputs& inputs);

}  // namespace vkw::passes
