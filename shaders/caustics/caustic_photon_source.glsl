// What every photon kernel's push constants begin with: the map's light space, the flux each
// photon deposits and the water's extinction. Its C++ type is generated once, from
// common/shared_blocks.comp (CausticPhotonSourcePush in passes/caustics/caustics_photons.hpp).
#ifndef VKWATER_CAUSTIC_PHOTON_SOURCE_GLSL
#define VKWATER_CAUSTIC_PHOTON_SOURCE_GLSL

#include "caustics/caustic_light_space.glsl"

// std430 and std140 alike: six vec4.
struct CausticPhotonSource {
    CausticLightSpace space;
    vec4 deposit_scale;  // rgb: E_s / LSB per channel (0 for a sun at or below the horizon)
    vec4 sigma_t;        // rgb: extinction, 1/m
};

#endif
