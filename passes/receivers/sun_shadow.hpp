// The sun's shadow map (docs/model.md section 1: the sun is shadowed by objects): the receiver
// meshes' depth seen along a beam, orthographic in the branchless basis of
// caustics_light_space.hpp (finite for an overhead sun), fitted on the CPU in double. Two halves
// side by side in one D32_SFLOAT image, reversed like the scene depth (1 nearest the light, 0,
// the clear, farthest):
//   - left: along the sun direction s, every mesh, fitted to all receivers plus the floor square
//     (shadows above the water, and at the point where the refracted beam enters the water);
//   - right, for scenes with water: along the flat surface's refracted beam t, the meshes under
//     the water (clipped at the mean level), fitted to the part of the box below it (shadows
//     under the water: docs/model.md section 1 shadows the beam along t). Under waves the beam's
//     direction varies; the shadow follows the mean direction (an approximation).
// Only the meshes occlude; the floor is a plane under everything and never shadows anything.
// Receivers read it through LightingInputs (SunShadowReads) with
// shaders/receivers/sun_shadow.glsl: a single depth compare with a slope-scaled bias.
// Published as keys::kSunShadow; the renderer adds it when the scene has receiver meshes and
// the sun is above the horizon.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/receivers/receiver_meshes.hpp"

#include <glm/glm.hpp>
#include <shader_structs/common/shared_blocks.comp.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace vkw::passes {

// The beam under the water, for scenes with water.
struct UnderwaterBeam {
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit: the sun refracted by the flat surface
    double water_level = 0.0;              // m: meshes above it cast nothing along the beam
};

struct SunShadowInputs {
    glm::dvec3 sun_direction{0.0, -1.0, 0.0};    // unit, the direction the sunlight travels
    glm::dvec3 bounds_lo{-1.0}, bounds_hi{1.0};  // world box the map must cover, m
    uint32_t size = 1024;                        // texels per side of each half
    std::optional<UnderwaterBeam> beam;          // the right half: the scene has water
};

// One half's projection, struct ShadowProjection of shaders/receivers/sun_shadow.glsl, generated
// once from common/shared_blocks.comp: light_from_world, world -> (x, y) in [-1, 1], z = 1 nearest
// the light; params x: texel size, m (the larger side), y: depth range, m, z: size, texels, w: 1
// when the map has this half.
using ShadowProjection = glsl::shared_blocks_comp::ShadowProjection;

// The uniform block SunShadowSpace of the same file: `sun`, the left half, along s; `beam`, the
// right half, along t under the water (params.w = 0 without water).
using SunShadowSpace = glsl::shared_blocks_comp::SunShadowSpace;
static_assert(sizeof(SunShadowSpace) == 160);

// Throws vkw::InternalError for a non-unit direction, an empty or non-finite box, or size
// outside 1..16384.
ShadowProjection fit_shadow_projection(const glm::dvec3& direction, const glm::dvec3& bounds_lo,
                                       const glm::dvec3& bounds_hi, uint32_t size);
SunShadowSpace fit_sun_shadow(const SunShadowInputs& inputs);

struct SunShadowMap {
    fg::ImageHandle depth;   // D32_SFLOAT, (2 with water, else 1) x size wide, size high
    fg::BufferHandle space;  // uniform: SunShadowSpace
};

SunShadowMap add_sun_shadow_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes, const SunShadowInputs& inputs);

// A pass's reads of the sun shadow map, under the names every shader that includes
// shaders/receivers/sun_shadow.glsl gives them: `sun_shadow_map` (the depth, sampled nearest) and
// `SunShadowSpace`. Empty (declaring nothing) when the frame has no shadow map.
struct SunShadowReads {
    bool declared = false;

    // `stages` 0: the pass kind's shader stage (PassBuilder).
    void declare(fg::PassBuilder& builder, const SunShadowMap* map, VkPipelineStageFlags2 stages = 0);
    explicit operator bool() const { return declared; }
};

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// Published only while the scene has receiver meshes and the sun is up (passes/receivers/sun_shadow.hpp).
inline constexpr fg::BlackboardKey<passes::SunShadowMap> kSunShadow{"sun shadow map"};

}  // namespace vkw::keys
