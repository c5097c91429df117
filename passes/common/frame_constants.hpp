// The per-frame constants block, std140, mirroring shaders/common/frame_constants.glsl
// field by field; and the function that fills it from a scene.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/unresolved_slopes.hpp"

#include <glm/glm.hpp>

#include <cstdint>

namespace vkw {

// Solid angle of the sun's disk as the model fixes it (docs/model.md section 1), and the
// angular radius it corresponds to: 2 pi (1 - cos r) = 6.80e-5 sr for r = 0.2666 deg.
inline constexpr double kSunDiskSolidAngle = 6.80e-5;
inline constexpr double kSunDiskAngularRadiusDeg = 0.2666;

struct alignas(16) FrameConstants {
    glm::mat4 view_proj;
    glm::mat4 inv_view_proj;
    glm::vec4 camera_position;
    glm::vec4 sun_direction;  // w: 1 if above the horizon
    glm::vec4 sun_irradiance;
    glm::vec4 sky_radiance;
    glm::vec4 sky_zenith;
    glm::vec4 sky_horizon;
    glm::vec4 sky_ground;
    glm::vec4 sky_params;  // x: model (0 constant, 1 gradient), y: exponent
    glm::vec4 sky_average;
    glm::vec4 sun_disk;     // x: cos(angular radius), y: solid angle
    glm::vec4 floor_plane;  // x: height, y: half extent, z: tile side (0: no tiles), w: grout width
    glm::vec4 floor_albedo;
    glm::vec4 viewport;  // xy: width, height in pixels
    glm::vec4 water;     // x: level, y: ior, z: half extent, w: has water
    glm::vec4 medium_sigma_t;
    glm::vec4 medium_sigma_s;  // w: g
    glm::vec4 camera_medium;   // x: camera in the water (per frame; the camera-medium split refines it per pixel)
    glm::vec4 camera_near;     // x: near-plane distance, m
    glm::vec4 medium_options;  // x: 1 when the shading adds the analytic in-scatter, 0 when the godrays supply it
    glm::vec4 floor_grout;     // rgb: the grout's albedo, where floor_plane.z > 0
    // The sun's glitter (engine/water/unresolved_slopes.hpp): x: log of the first cutoff
    // wavenumber, y: the log step between entries, z: 1 when the waves have slopes, w: the slopes'
    // whole variance (S_xx + S_zz).
    glm::vec4 glitter;
    glm::vec4 unresolved_slopes[kUnresolvedSlopeEntries];  // (S_xx, S_xz, S_zz, k_c) per cutoff
};
static_assert(sizeof(FrameConstants) % 16 == 0, "std140 blocks are a multiple of 16 bytes");

FrameConstants make_frame_constants(const Scene& scene, uint32_t width, uint32_t height);

// Whether the camera's eye is in the water, the per-frame camera medium (height exactly at the
// level counts as above). The camera-medium split refines it per pixel where the near plane crosses
// the surface.
bool camera_eye_in_water(const Scene& scene);

}  // namespace vkw
