// Scene views for the water's reflection and refraction of objects (de la Fuente 2011
// section 4.4, Optical Phenomena c. 2008 sections 3 and 5, Ojeda & Susín 2013 section 5): the receiver meshes on
// one side of the water plane, rendered offscreen with the field of view widened by a
// guard band (shaders/scene_views/scene_view.glsl), each texel holding the radiance that
// leaves the receiver toward the view's eye and its distance. The water's shader then
// follows its reflected and refracted rays through them (water/scene_lookup.glsl).
//   - reflection, projective: the mirror image of the camera's side (the mirrored camera);
//   - reflection, screen-space: the camera's side from the camera (Ojeda & Susín 2013's 'over');
//   - refraction, both methods: the other side from the camera (Ojeda & Susín 2013's 'below').
// The floor and the sky are not in the views: the lookups meet them exactly (the
// floor is a plane, the ray-plane intersection of de la Fuente 2011 section 4.4).
// The refraction view may have a second layer (Effect::RefractionSecondLayer; depth peeling, Everitt
// 2001): the same view with what the first layer shows peeled away, and the faces turned away from
// the eye, so that it shows what the nearest receiver hides. A refracted ray that passes under a
// floating receiver, or behind a ridge, meets what only that layer holds.
// The sides follow the camera's medium per frame (frame constants); the clip planes lie
// the waves' amplitude plus a millimetre beyond the mean level, so objects in the band of
// the waves are in both views.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "passes/receivers/receiver_meshes.hpp"

#include <optional>

namespace vkw::passes {

struct SceneViewSpec {
    const char* name;   // the pass's name; its target is "<name> target"
    bool mirrored;      // seen from the camera's mirror image in the mean water plane
    bool camera_side;   // keeps the camera's side of the surface (false: the other side)
    float clip_margin;  // m beyond the mean level
    // The other side's view only: also keep its caustic layer, published as
    // keys::kRefractionViewCaustic (passes/caustics/caustic_layer.hpp), or for a second layer as
    // keys::kRefractionViewBehindCaustic.
    bool caustic_layer = false;
    // A second layer: this view's first layer, whose surfaces (and what lies within
    // SCENE_VIEW_THICKNESS of them) it leaves out. The pass then serves Effect::RefractionSecondLayer.
    std::optional<fg::ImageHandle> behind{};
};

// Renders the view; returns its RGBA32F target (radiance, distance; 0 where empty), 1.5
// times the output size in each direction (the guard band at the camera's pixel density).
fg::ImageHandle add_scene_view_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes, const SceneViewSpec& spec);

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// RGBA32F, the refraction scene view's size: its caustic layer, while both are drawn.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kRefractionViewCaustic{"refraction view caustic layer"};
// The same for the refraction view's second layer.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kRefractionViewBehindCaustic{
    "refraction view second layer caustic layer"};

}  // namespace vkw::keys
