// Camera-space caustic splats (Ojeda & Susín 2013 section 4; effects.caustics.splat =
// camera-space): the photon grid of the light-space map, traced identically
// (shaders/caustics/caustic_grid_photon.glsl), splatted not into a map along the sun but onto the
// receivers the camera sees without the water (passes/caustics/caustics_camera_receivers.hpp), as gaussians
// lying in each receiver's tangent plane and sized by the photon density
// (shaders/caustics/caustic_camera_splats.comp has the rules: the depth test, the sizes, the taps),
// accumulated in 64-bit fixed point in the map's LSB (so bit-identical run to run), then resolved to
// irradiance on the receiver, E = Phi_pixel |v . N_r| / (s^2 Omega_pix)
// (shaders/caustics/caustic_camera_resolve.comp). A receiver point reads it at its own projection
// into the view (shaders/caustics/caustic_camera_lookup.glsl): where the camera sees the floor
// through the water, at the water-less projection of the refracted ray's hit. Points the camera
// does not see (hidden, off the view, or only in a reflection) get no splat and fall back to the
// flat-surface stand-in.
// Written by compute: rasterised points run at about 5 M/s on lavapipe against about 300 M/s for
// compute atomics (docs/lavapipe.md), so no rasterised variant.
// Memory: the view (RGBA32F, 16 B), its depth (4 B), the flux pyramid (3 x uint64, 24 B, times 1.33
// for the levels) and the irradiance (RGBA32F, 16 B) per pixel of the guard-banded view: about 68 B
// x 1.5^2 per output pixel.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_camera_receivers.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/receivers/sun_shadow.hpp"

namespace vkw::passes {

struct CameraCaustics {
    fg::ImageHandle receivers;   // the receivers' view: normal, distance
    fg::ImageHandle irradiance;  // RGBA32F: E on the receiver (rgb), its distance (a)
};

// The splats' flux pyramid (kCameraCausticLevels of shaders/caustics/caustic_camera_view.glsl):
// level L's pixels are 2^L x 2^L pixels of the view; a splat too wide for one level goes to a
// coarser one, and the resolve adds the levels up.
inline constexpr uint32_t kCameraCausticLevels = 4;
uint32_t camera_caustic_level_pixels(CameraCausticExtent extent);  // all levels together
// The flux buffer's bytes: the header (the lost flux), then three uint64 per pixel of every level.
VkDeviceSize camera_caustic_flux_bytes(CameraCausticExtent extent);

// Adds the flux clear, the splats (compute) and the resolve (compute). `receivers` is
// add_caustic_receivers_pass's view of `extent`; `shadow` as for add_caustic_photon_pass. Throws
// vkw::InputError when the flux buffer exceeds the device's storage binding, vkw::InternalError for
// inputs out of range.
CameraCaustics add_caustic_camera_splat_passes(fg::FrameGraph& graph, const CausticInputs& inputs,
                                               fg::ImageHandle receivers, CameraCausticExtent extent,
                                               const SunShadowMap* shadow = nullptr);

// The flux buffer the splats wrote, for tests that check the fixed point itself (the last
// add_caustic_camera_splat_passes of the graph).
inline constexpr const char* kCameraCausticFluxName = "camera caustic flux";

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// The camera-space splats instead of the map (effects.caustics.splat = camera-space): never both.
inline constexpr fg::BlackboardKey<passes::CameraCaustics> kCameraCaustics{"camera caustics"};

}  // namespace vkw::keys
