// The knobs the frame-time budget turns (vkwater render/view --budget-ms), and the candidate
// settings it chooses among. A setting is at most the scene's own: the budget only ever gives
// up quality to meet a time, never adds what the scene file did not ask for.
//
// The knobs, by what they save (docs/performance.md "The frame-time budget"):
//   render_scale     every per-pixel pass, as its square (passes/frame/upscale.hpp)
//   photon_grid      water.grid_resolution: the photons traced, the surface grid, the caustic map
//   mesh_resolution  water.mesh_resolution: the triangles the water and its stencil draw
//   godray_grid      effects.godrays.grid, the beams walked; 0 turns the godrays off
//   lookup_steps     effects.reflection/refraction.max_steps: each pixel's refinement or march
//                    steps through the scene views, where the water looks the scene up; at each
//                    steps, also one lookup off (effects.reflection.mode or refraction.mode: the one
//                    the scene's previews measured as losing less, quality.cpp), and at last both
//                    (the views' passes and each pixel's lookups; the rays keep the exact floor and
//                    sky and miss the receiver meshes)
//   caustic_kernel   effects.caustics.kernel: the bilinear tent's 4 taps a photon against the
//                    adaptive hat's 9 (and its 4 neighbours traced), where the light-space map is made
//   map_scale        effects.caustics.map_scale: the map's texels (clear, resolve, blur) and the
//                    hat's taps, which span the photons' spacing in texels
//   samples          --spp: the sub-frames of a box-filtered frame, each one every camera pass
//                    again (the photon map once); at most the samples the command asked for
//   second_layer     effects.refraction_second_layer: the refraction view's depth-peeled layer
//                    (its pass, and the water's refracted rays marched again through it), on or
//                    off where the needs run it
//   shadow_texels    sun.shadow_texels: the sun shadow map's texels per side, where receiver
//                    meshes cast into it
//   caustics         effects.caustics.mode: the surface caustics off (the photons, the map and its
//                    passes), offered only where the scene's previews found that turning them off
//                    changes no pixel visibly (the ocean, whose floor lies 30 m down in coastal
//                    water)
//   terrain_fraction the terrain receivers' cells per side over the file's (receivers[i].resolution):
//                    the triangles every view of the receivers draws (the camera's, the scene
//                    views', the sun shadow map's), where the scene has terrain
#pragma once

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkw::budget {

// What turning off an on/off knob adds to a scene's relMSE, measured on two small frames of the
// scene, the knob on and off (tools/vkwater/budget_previews.hpp): the relMSE of the second against
// the first. Below 0 where not measured; the error table's entry, the worst of the scenes it was
// measured on, stands in there.
struct MeasuredOffExcess {
    double reflection_lookup = -1.0;
    double refraction_lookup = -1.0;
    double second_layer = -1.0;
    double caustics = -1.0;
    // With the caustics off, the largest change of any preview pixel's channel, relative to its
    // value with them on (0 where both are 0; infinite where only the one with them is not).
    double caustics_largest_change = -1.0;
    bool operator==(const MeasuredOffExcess&) const = default;
};

struct Quality {
    double render_scale = 1.0;
    uint32_t photon_grid = 0;        // 0: the scene has no water
    uint32_t mesh_resolution = 0;    // 0: the scene has no water
    uint32_t godray_grid = 0;        // 0: no godrays (the scene's decision, or turned off)
    uint32_t lookup_steps = 0;       // 0: the water looks no scene view up
    bool reflection_lookup = false;  // the reflected rays look the scene up (the mirrored reflection view runs)
    bool refraction_lookup = false;  // the refracted rays look the scene up (the refraction view runs)
    CausticKernel caustic_kernel = CausticKernel::Adaptive;  // the light-space map's splat kernel
    double map_scale = 0.0;         // the light-space map's texels per water cell; 0: the frame makes no photon map
    uint32_t samples = 1;           // samples per pixel, k^2 (engine/scene/pixel_filter.hpp)
    bool second_layer = false;      // the refraction view's second layer runs (only where the needs run it)
    uint32_t shadow_texels = 0;     // the sun shadow map's texels per side; 0: the frame makes none
    double terrain_fraction = 0.0;  // the terrain receivers' cells per side over their own; 0: no terrain
    bool caustics = false;          // the surface caustics run (the scene's decision, or turned off)
    // Not a knob: the scene's caustic_visibility (below), the same in every candidate; the error
    // model scales the caustic knobs' terms by it.
    double caustic_visibility = 1.0;
    // Not a knob: the camera is under the mean water level, which orders the lookups' ladder
    // where the previews below did not measure it (quality.cpp, lookup_ladder).
    bool camera_in_water = false;
    // Not knobs: what turning off each on/off knob adds to this scene's relMSE, measured on small
    // frames of the scene itself, the same in every candidate.
    MeasuredOffExcess measured_off;
    bool operator==(const Quality&) const = default;
    uint32_t scene_lookups() const { return uint32_t(reflection_lookup) + uint32_t(refraction_lookup); }
};

// The scene's own settings at full resolution and `samples` per pixel (the command's --spp), for
// the effects `needs` decides to run (a scene without godrays or scene lookups has nothing to turn
// down there). Its lookup steps are the larger of reflection's and refraction's.
Quality scene_quality(const Scene& scene, const fg::FrameNeeds& needs, uint32_t samples = 1);

// At most the share of the sun's light that reaches a receiver under the water and comes back to
// the camera: exp(-sigma (d / cos_t + d_view)), sigma the medium's smallest extinction over its
// channels, d the shortest depth from the lowest trough down to the highest receiver point under
// it (the floor, or a mesh that reaches below the crests), cos_t the cosine of the sun refracted
// by the flat surface, d_view that depth again for a camera above the water (its own height over
// the receiver below it). 1 where a receiver reaches the troughs or the medium is clear; 3.4e-4
// for the ocean's floor, 30 m down in coastal water. What the caustics can change in a pixel
// scales with it.
double caustic_visibility(const Scene& scene);

// Every setting the budget may choose for a scene whose own settings are `top`: each knob at
// its own value or one of the lower steps below, all combinations. `top` is among them.
std::vector<Quality> quality_candidates(const Quality& top);

// The scene with `quality`'s knobs (the resolution scale and the samples are the renderer's
// options, not the scene's).
// Below the top's lookup steps both reflection and refraction take `quality.lookup_steps`; a
// lookup the top has and `quality` has not is turned off (its effect's mode).
void apply_quality(const Quality& quality, const Quality& top, Scene& scene);

// The scene fields that apply_quality may change, as a scene has them. The viewer applies each
// frame's setting to the scene it applied the last one to, and apply_quality sets only what lies
// below the top: the viewer puts these back first, so that a setting above the last one gets the
// scene's own values again (its mesh, its second layer, its shadow map, its lookups). The terrain's
// cells are set by apply_quality at every setting, the top's too.
struct SceneKnobFields {
    uint32_t grid_resolution = 0;
    std::optional<uint32_t> mesh_resolution, mesh_cell_pixels;
    uint32_t godray_grid = 0;
    EffectMode godrays = EffectMode::Auto, reflection = EffectMode::Auto, refraction = EffectMode::Auto,
               second_layer = EffectMode::Auto, caustics = EffectMode::Auto;
    int reflection_steps = 0, refraction_steps = 0;
    CausticKernel kernel = CausticKernel::Adaptive;
    double map_scale = 0.0;
    uint32_t shadow_texels = 0;
};
SceneKnobFields knob_fields(const Scene& scene);
void restore_knob_fields(const SceneKnobFields& fields, Scene& scene);

// The command-line options that give `quality` explicitly, relative to the scene's own settings
// `top`: "--render-scale 0.5 --set water.grid_resolution=256 ..." ("" when it is `top` at one
// sample per pixel; --spp whenever it is above one). Given to vkwater render, they reproduce the
// budget's image bit for bit. The terrain's cells are set per receiver ("--set
// receivers[0].resolution=32"), so `scene` (as loaded: its terrains' own cells) names them.
std::vector<std::string> quality_arguments(const Quality& quality, const Quality& top, const Scene& scene);
// The arguments as one line for a shell: a --set value with brackets is quoted.
std::string describe_arguments(const std::vector<std::string>& arguments);

// A short line for the overlay: "scale 0.5, photons 256^2, mesh 128, godrays 32^2" (", 4 spp" above one).
std::string describe_quality(const Quality& quality);

// The steps each knob may take (the error table, error_model.hpp, has a term for each).
inline constexpr double kRenderScales[] = {1.0, 0.75, 0.5, 0.35, 0.25};
inline constexpr double kPhotonGridFractions[] = {1.0, 0.5, 0.25, 0.125};
inline constexpr uint32_t kMeshResolutions[] = {256, 128, 64};
inline constexpr uint32_t kGodrayGrids[] = {64, 32, 16, 0};
inline constexpr uint32_t kLookupSteps[] = {16, 8};
inline constexpr double kMapScaleFractions[] = {1.0, 0.5};  // of the scene's, at least kMinMapScale
inline constexpr double kMinMapScale = 0.25;                // effects.caustics.map_scale's lower limit
inline constexpr uint32_t kSampleCounts[] = {16, 9, 4, 1};  // k^2 strata, at most the command's --spp
inline constexpr uint32_t kShadowTexels[] = {1024, 512, 256};
inline constexpr double kTerrainFractions[] = {1.0, 0.5, 0.25};

}  // namespace vkw::budget
