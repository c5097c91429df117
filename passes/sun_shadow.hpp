// The sun's shadow map (PHYSICS.md section 1: above the water the direct sun is shadowed by
// objects): the receiver meshes' depth seen from the sun, orthographic along the sun direction s
// in the branchless basis of caustics_light_space.hpp (finite for an overhead sun), fitted on the
// CPU in double to the bounds of all receivers plus the floor square. D32_SFLOAT, reversed like
// the scene depth: 1 nearest the sun, 0 (the clear) farthest. Only the meshes occlude; the floor
// is a plane under everything and never shadows anything.
// Receivers read it through LightingInputs (bindings 6 and 7) with
// shaders/receivers/sun_shadow.glsl: a single depth compare with a slope-scaled bias.
// Published as keys::kSunShadow; the renderer adds it when the scene has receiver meshes and
// the sun is above the horizon.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/receiver_meshes.hpp"

#include <glm/glm.hpp>

#include <cstdint>

namespace vkw::passes {

struct SunShadowInputs {
    glm::dvec3 sun_direction{0.0, -1.0, 0.0};  // unit, the direction the sunlight travels
    glm::dvec3 bounds_lo{-1.0}, bounds_hi{1.0};  // world box the map must cover, m
    uint32_t size = 1024;                       // texels per side
};

// Mirrors struct SunShadowSpace of shaders/receivers/sun_shadow.glsl (std140 = std430 here).
struct SunShadowSpace {
    float light_from_world[16];  // column-major: world -> (x, y) in [-1, 1], z = 1 nearest the sun
    float params[4];             // x: texel size, m (the larger side); y: depth range, m; z: map size, texels
};
static_assert(sizeof(SunShadowSpace) == 80);

// Throws vkw::InternalError for a non-unit sun, an empty or non-finite box, or size outside 1..16384.
SunShadowSpace fit_sun_shadow(const SunShadowInputs& inputs);

struct SunShadowMap {
    fg::ImageHandle depth;  // D32_SFLOAT, size x size
    fg::BufferHandle space;  // uniform: SunShadowSpace
};

SunShadowMap add_sun_shadow_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes, const SunShadowInputs& inputs);

}  // namespace vkw::passes
