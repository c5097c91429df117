// Per-frame constants, std140. Their C++ mirror is generated from common/shared_blocks.comp
// (vkw::glsl::shared_blocks_comp::FrameConstants, used as vkw::FrameConstants).
#ifndef VKWATER_FRAME_CONSTANTS_GLSL
#define VKWATER_FRAME_CONSTANTS_GLSL

layout(set = 0, binding = 0, std140) uniform FrameConstants {
    mat4 view_proj;           // world -> clip, reversed-Z (near plane at depth 1)
    mat4 inv_view_proj;       // clip -> world
    vec4 camera_position;     // xyz, metres
    vec4 sun_direction;       // xyz: unit direction the sunlight travels (downward); w: 1 if above the horizon
    vec4 sun_irradiance;      // rgb: W m^-2 on a plane normal to the beam
    vec4 sky_radiance;        // rgb: constant sky radiance, W m^-2 sr^-1 (sky model 0)
    vec4 sky_zenith;          // rgb: gradient sky straight up (sky model 1)
    vec4 sky_horizon;         // rgb: gradient sky at the horizon
    vec4 sky_ground;          // rgb: every direction below the horizon
    vec4 sky_params;          // x: model (0 constant, 1 gradient), y: gradient exponent
    vec4 sky_average;         // rgb: L_sky_avg (docs/model.md section 1), computed on the CPU
    vec4 sun_disk;            // x: cos of the disk's angular radius, y: its solid angle (sr)
    vec4 floor_plane;         // x: height y of the floor, y: half extent, z: tile side (0: no tiles), w: grout width
    vec4 floor_albedo;        // rgb
    vec4 viewport;            // xy: output size in pixels
    vec4 water;               // x: mean level y, y: index of refraction, z: half extent, w: 1 if the scene has water
    vec4 medium_sigma_t;      // rgb: extinction, 1/m
    vec4 medium_sigma_s;      // rgb: scattering, 1/m; w: Henyey-Greenstein g
    vec4 camera_medium;       // x: 1 if the camera is in the water (per frame, from the mean level; the fallback when
                              //    the stencil split is culled, see water/camera_medium.glsl); infinite water:
                              //    y: the water's bottom y, z: the far field's distance (water/water_bottom.glsl)
    vec4 camera_near;         // x: near-plane distance, m (the stencil split's clip depth)
    vec4 medium_options;      // x: 1 when the shading adds the analytic in-scatter of the sun's beam; 0 when the
                              //    godray passes supply the in-scatter instead (counted once, docs/model.md section 1)
    vec4 floor_grout;         // rgb: the grout's albedo, where floor_plane.z > 0 (receivers/floor_albedo.glsl)
    vec4 glitter;             // x: log of the first cutoff wavenumber, y: log step, z: 1 when the waves have slopes,
                              // w: the slopes' whole variance S_xx + S_zz
    vec4 unresolved_slopes[16];  // (S_xx, S_xz, S_zz, k_c): water/sun_glitter.glsl, engine/water/unresolved_slopes.hpp
    vec4 receiver_boxes;         // x: how many of the boxes below hold the receiver meshes (passes/common/receiver_boxes.hpp)
    vec4 receiver_box_min[8];    // xyz: world-space corners of boxes that together hold every receiver mesh
    vec4 receiver_box_max[8];
} frame;

// sigma_s for the analytic single scattering along view rays: zero when the godrays
// (volume caustics) are the frame's in-scatter of sunlight.
vec3 analytic_inscatter_sigma_s() { return frame.medium_sigma_s.rgb * frame.medium_options.x; }

#endif
