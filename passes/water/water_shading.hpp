// The water surface drawn over the scene and shaded (shaders/water/water_surface.frag):
// exact Fresnel, the sky in reflection, the floor through refraction (both exact: the sky
// by direction, the floor as a plane), the medium along every path, from above and from
// below; with scene views (passes/scene_views/scene_view.hpp), reflected and refracted rays also meet
// the receiver meshes. Draws the mesh of passes/water/water_surface.hpp and recovers the exact
// surface per pixel from the wave table or the ocean's fields (water/surface_refinement.glsl);
// reads, when the camera-medium split published it before, keys::kCameraMedium (per-pixel camera
// medium); serves Effect::Water.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/scene/scene.hpp"
#include "passes/water/water_surface.hpp"

#include <optional>

namespace vkw::passes {

// How the water finds the receiver meshes along its rays; a view absent: that lookup is off.
struct WaterSceneLookups {
    std::optional<fg::ImageHandle> reflection_view, refraction_view;
    // The refraction view's second layer (passes/scene_views/scene_view.hpp): where the first layer's
    // lookup finds nothing, or a surface the ray passes behind, the lookup is tried again in it.
    std::optional<fg::ImageHandle> refraction_view_behind;
    SceneLookup reflection_method = SceneLookup::Projective, refraction_method = SceneLookup::Projective;
    int reflection_steps = 64, refraction_steps = 64;
    float scene_size = 100.0f;   // m: how far a screen-space march looks when no floor bounds it
    float shallow_blend = 0.0f;  // m: screen-space refraction blends to the direct view under this much water
};

// The surface's shading model (effects.water): the Fresnel form and Optical Phenomena c. 2008's depth colour.
struct WaterSurfaceShading {
    SurfaceFresnel fresnel = SurfaceFresnel::Exact;
    float fresnel_power = 4.5f;
    bool depth_blend = false;
    bool glitter = false;  // the sun's glitter lobe (shaders/water/sun_glitter.glsl)
    glm::vec3 water_colour{0.0f, 0.2f, 0.1f};
    float blend_k = 0.5f;
    // Newton steps per pixel from the mesh to the exact surface; 0 shades the mesh as drawn.
    uint32_t refine_steps = 4;
    // The per-frame camera medium (camera_eye_in_water): without the camera-medium split's per-pixel
    // mask every pixel shares it, and the shader is specialised for that side alone.
    bool eye_in_water = false;
};
// The scene's effects.water, and its per-frame camera medium.
WaterSurfaceShading water_surface_shading(const Scene& scene);

// caustic_layer: write the caustic layer (passes/caustics/caustic_layer.hpp), creating it when no
// pass before did. The scene depth too is created here when the water draws first
// (passes/common/scene_depth.hpp).
void add_water_shading_pass(fg::FrameGraph& graph, const WaterSurfaceBuffers& surface,
                            const WaterSceneLookups& lookups = {}, const WaterSurfaceShading& shading = {},
                            bool caustic_layer = false);

}  // namespace vkw::passes
