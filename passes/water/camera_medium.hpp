// The split of the view into "ray starts above" and "ray starts under" the water, per pixel:
// the medium of the camera ray's origin on the near plane, published as the mask
// keys::kCameraMedium (R8_UNORM, 1 in the water, 0 in the air) that the floor, the sky, the
// godrays and the water shading read per pixel. Serves Effect::UnderwaterView: culled when no
// ray can start in the water (the shading then takes the per-frame medium of the frame
// constants).
//
// One full-screen pass ("camera medium", shaders/water/camera_medium_mask.frag) classifies each
// pixel's near-plane point q against the exact surface, the same wave sum or ocean fields the
// water's per-pixel refinement evaluates (docs/techniques/water_surface.md): q is in the water iff
// |q.x|, |q.z| <= E, q.y > bottom_y and q.y < the surface's height above (q.x, q.z), found by
// inverting the horizontal displacement with Newton's method from (q.x, q.z). A point exactly at
// the surface's height counts as above, as the per-frame fallback and the CPU rule
// (tests/render/stencil_split_test.cpp) count it.
//
// It replaces de la Fuente 2011's stencil split (section 4.2: the closed water volume drawn with
// stencil parity, then a stencil-tested full-screen pass), which classified by the drawn mesh:
// with the water drawn from a coarse mesh and refined per pixel, the mesh's chords would have
// misclassified a band of near-plane pixels several pixels wide, and drawing the volume from the
// photon grid cost the ocean 180 ms a frame on lavapipe (6.3 M vertices).
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "passes/water/water_surface.hpp"

namespace vkw::passes {

// `bottom_y`: the water volume's bottom (water_bottom); `amplitude`: a bound on the surface's
// height above or below its level (only near-plane points within it evaluate the surface).
void add_camera_medium_pass(fg::FrameGraph& graph, const WaterSurfaceBuffers& surface, double bottom_y,
                            double amplitude);

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// R8_UNORM, output size: 1 where the pixel's camera ray starts in the water (published only
// while the split runs; passes/water/camera_medium.hpp).
inline constexpr fg::BlackboardKey<fg::ImageHandle> kCameraMedium{"camera medium"};

}  // namespace vkw::keys
