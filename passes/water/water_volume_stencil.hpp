// The stencil split of the view into "ray starts above" and "ray starts under" the water
// (de la Fuente 2011 section 4.2): for every pixel, the medium of the camera ray's
// origin on the near plane, published as the mask keys::kCameraMedium (R8_UNORM, 1 in the
// water, 0 in the air) that the floor and water shading read per pixel. Serves
// Effect::UnderwaterView: culled when no ray can start in the water.
//
// Two graphics passes:
//   "water volume stencil"  draws the closed water volume (shaders/water/water_volume.vert:
//       the surface grid, walls down from its displaced rim to `bottom_y`, a bottom fan) into a
//       D32_SFLOAT_S8_UINT target with depth test and writes off, no colour, cull none; every
//       fragment inverts stencil bit 0. Counting is by parity, not z-pass or z-fail: a ray from
//       a point crosses a closed surface an odd number of times iff the point is inside, so the
//       parity of the crossings behind the near plane classifies the ray's near-plane point.
//       The near-plane clip removes exactly the crossings in front of it (the near-plane test
//       is done by clipping, no seed and no depth clamp needed); the far clip is disabled by
//       giving every vertex the clip depth z = n (depth n / w stays in (0, 1] for any point
//       beyond the near plane), so faces past the far plane still count. Parity needs no
//       consistent winding and ignores the scene's objects (no depth test).
//   "camera medium"  a full-screen triangle with the stencil test (bit 0 == 1) writes 1 into
//       the mask cleared to 0.
// Ties: a pixel whose near-plane point lies exactly on the boundary goes by the rasteriser's
// top-left rule on the clipped faces (either side); the CPU rule it is tested against
// (tests/render/stencil_split_test.cpp) counts a point exactly at the surface's height as above
// (y < h(x, z) is water), as the per-frame fallback does. Exact elsewhere.
// Assumes the water's grid is centred on x = z = 0 (as passes/water/water_surface.hpp lays it out) and
// `bottom_y` below every surface vertex (the floor must not cut the waves).
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

void add_water_volume_stencil_passes(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution,
                                     double bottom_y);

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// R8_UNORM, output size: 1 where the pixel's camera ray starts in the water (published only
// while the stencil split runs; passes/water/water_volume_stencil.hpp).
inline constexpr fg::BlackboardKey<fg::ImageHandle> kCameraMedium{"camera medium"};

}  // namespace vkw::keys
