// The budget's knobs and candidates (quality.hpp).
#include "tools/vkwater/budget/quality.hpp"

#include "engine/scene/range.hpp"
#include "passes/frame/frame_needs.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::budget {
namespace {

// Each knob's values for a scene whose own value is `own`: its own, then the steps below it (0
// alone where the scene has none of it).
template <size_t N>
std::vector<uint32_t> steps_below(uint32_t own, const uint32_t (&steps)[N]) {
    std::vector<uint32_t> values = {own};
    for (uint32_t step : steps) {
        if (own > 0 && step < own) values.push_back(step);
    }
    return values;
}

// The scene lookups' steps and which lookups run.
struct SceneLookups {
    uint32_t steps;
    bool reflection;
    bool refraction;
    bool operator==(const SceneLookups&) const = default;
};

// The lookups' ladder: at the top's steps and at each lower one, both of the top's lookups, and one
// of them off; then both off. A lookup's cost is mostly its own start, not its steps (lake's water
// pass costs about the same at 8 steps as at 1), so one lookup off at the scene's own steps can
// save more time than fewer steps, for less error where the previews measured it as cheap (lake's
// reflected rays' lookup: 0.0013, against 0.004 for 8 steps).
// The one turned off is the one whose loss the scene's previews measured as the smaller
// (Quality::measured_off). Where they measured neither, it is the one whose rays carry the smaller
// Fresnel weight on the camera's side of the surface: from above the water the reflected rays' (a
// few percent of the light), from below the refracted rays' (outside Snell's window the surface
// reflects everything). The error table cannot order them: its two terms are each the worst of
// the measured scenes and about equal (docs/sweeps/budget_error_terms.csv: box's reflection,
// lake's refraction). The sweep bears the camera's rule out on lake, the showcase pool and the
// lagoon; box, whose red box is reflected against a sky without red, is the exception that the
// previews get right.
std::vector<SceneLookups> lookup_ladder(const Quality& top) {
    std::vector<SceneLookups> ladder;
    const MeasuredOffExcess& measured = top.measured_off;
    const bool both_measured = measured.reflection_lookup >= 0.0 && measured.refraction_lookup >= 0.0;
    const bool keep_reflection = both_measured && measured.reflection_lookup != measured.refraction_lookup
                                     ? measured.reflection_lookup > measured.refraction_lookup
                                     : top.camera_in_water;
    for (uint32_t s : steps_below(top.lookup_steps, kLookupSteps)) {
        ladder.push_back({s, top.reflection_lookup, top.refraction_lookup});
        if (top.reflection_lookup && top.refraction_lookup) ladder.push_back({s, keep_reflection, !keep_reflection});
    }
    if (top.scene_lookups() > 0) ladder.push_back({0, false, false});
    return ladder;
}

// The caustics off are offered only where the scene's previews found they change no pixel visibly:
// no channel of any preview pixel moves by more than the needs rules' invisible change (kGodrays-
// InvisibleChange, passes/frame/frame_needs.hpp: half a step of the PNG preview at its steepest).
// Then the frame without them is the same picture for less time (no photons, no map): the ocean,
// whose floor lies 30 m down in coastal water. Where they show, even faintly (the showcase pool
// loses relMSE 0.005 without them, more than its fewest photons lose), they stay on at every
// candidate, and the candidates stay as many.
bool caustics_offered(const Quality& top) {
    const MeasuredOffExcess& measured = top.measured_off;
    return top.caustics && measured.caustics >= 0.0 && measured.caustics_largest_change >= 0.0 &&
           measured.caustics_largest_change <= kGodraysInvisibleChange;
}

}  // namespace

double caustic_visibility(const Scene& scene) {
    if (!scene.water) return 1.0;
    const double crest = water_bounds(scene).hi.y;
    const double trough = 2.0 * scene.water->level - crest;
    // The receivers the water can light: those that reach below the crests.
    double highest = scene.floor.height;
    for (const Receiver& receiver : scene.receivers) {
        if (receiver.mesh.bounds_min.y < crest) highest = std::max(highest, receiver.mesh.bounds_max.y);
    }
    const double depth = trough - highest;
    if (!(depth > 0.0)) return 1.0;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    const double sigma = std::min({sigma_t.r, sigma_t.g, sigma_t.b});
    const double sin_sun = std::sqrt(std::max(0.0, 1.0 - scene.sun.direction.y * scene.sun.direction.y));
    const double sin_t = std::min(1.0, sin_sun / scene.water->ior);
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    const double camera_depth = scene.camera.position.y - highest;
    const double view = scene.camera.position.y >= trough ? depth : std::max(0.0, camera_depth);
    return std::exp(-sigma * (depth / std::max(cos_t, 1e-6) + view));
}

Quality scene_quality(const Scene& scene, const fg::FrameNeeds& needs, uint32_t samples) {
    Quality quality;
    quality.samples = samples;
    quality.caustic_visibility = caustic_visibility(scene);
    quality.camera_in_water = scene.water && scene.camera.position.y < scene.water->level;
    if (scene.water) {
        quality.photon_grid = scene.water->grid_resolution;
        // Infinite water is drawn from the screen's grid at every setting: no uniform mesh to turn.
        quality.mesh_resolution = scene.water->infinite ? 0 : scene.water->drawn_mesh_resolution();
        const fg::EffectDecision* godrays = needs.find(Effect::VolumeCaustics);
        if (godrays && godrays->needed && scene.effects.godrays.method == GodrayMethod::Lines) {
            quality.godray_grid = scene.effects.godrays.grid;
        }
        for (Effect lookup : {Effect::Reflection, Effect::Refraction}) {
            const fg::EffectDecision* decision = needs.find(lookup);
            if (!decision || !decision->needed) continue;
            (lookup == Effect::Reflection ? quality.reflection_lookup : quality.refraction_lookup) = true;
            quality.lookup_steps = std::max<uint32_t>(quality.lookup_steps, scene.effects[lookup].max_steps);
        }
        const fg::EffectDecision* second_layer = needs.find(Effect::RefractionSecondLayer);
        quality.second_layer = second_layer && second_layer->needed;
        // The kernel and the map's scale are knobs only where photons are splatted into the
        // light-space map (not the procedural caustics, not the camera-space splats).
        const fg::EffectDecision* caustics = needs.find(Effect::SurfaceCaustics);
        quality.caustics = caustics && caustics->needed;
        const CausticSettings& settings = scene.effects.caustics;
        if (caustics && caustics->needed && settings.method == CausticMethod::Photons &&
            settings.splat == CausticSplat::LightSpace) {
            quality.caustic_kernel = settings.kernel;
            quality.map_scale = settings.map_scale;
        }
    }
    // The renderer makes the sun shadow map where receiver meshes can cast into it.
    if (!scene.receivers.empty() && scene.sun.direction.y < 0.0) quality.shadow_texels = scene.sun.shadow_texels;
    for (const Receiver& receiver : scene.receivers) {
        if (receiver.terrain) quality.terrain_fraction = 1.0;
    }
    return quality;
}

std::vector<Quality> quality_candidates(const Quality& top) {
    std::vector<uint32_t> grids = {top.photon_grid};
    if (top.photon_grid > 0) {
        for (double fraction : kPhotonGridFractions) {
            const auto grid = std::max<uint32_t>(2, static_cast<uint32_t>(std::lround(top.photon_grid * fraction)));
            if (grid < top.photon_grid) grids.push_back(grid);
        }
    }
    std::vector<CausticKernel> kernels = {top.caustic_kernel};
    std::vector<double> map_scales = {top.map_scale};
    if (top.map_scale > 0.0) {
        if (top.caustic_kernel != CausticKernel::Bilinear) kernels.push_back(CausticKernel::Bilinear);
        for (double fraction : kMapScaleFractions) {
            const double scale = std::max(kMinMapScale, top.map_scale * fraction);
            if (scale < top.map_scale) map_scales.push_back(scale);
        }
    }
    // Every combination, the first knob outermost: each knob in turn multiplies the list by its
    // values. Each knob sets only its own field, which is still the top's in every candidate when it
    // is varied, so candidates made from different ones differ where those did; only one candidate's
    // own variations can coincide (two grid fractions rounding alike, meshes clamped to the grid),
    // and those are the duplicates left out (a search of the whole list was quadratic: 0.35 s for
    // lake's 13,000 candidates).
    std::vector<Quality> candidates = {top};
    const auto vary = [&candidates](const auto& values, auto set) {
        std::vector<Quality> more;
        for (const Quality& candidate : candidates) {
            const size_t first = more.size();
            for (const auto& value : values) {
                Quality varied = candidate;
                set(varied, value);
                if (std::find(more.begin() + first, more.end(), varied) == more.end()) more.push_back(varied);
            }
        }
        candidates = std::move(more);
    };
    vary(steps_below(top.samples, kSampleCounts), [](Quality& q, uint32_t v) { q.samples = v; });
    vary(kRenderScales, [](Quality& q, double v) { q.render_scale = v; });
    vary(grids, [](Quality& q, uint32_t v) { q.photon_grid = v; });
    // The mesh is drawn from the surface grid: it has at most as many cells.
    vary(steps_below(top.mesh_resolution, kMeshResolutions),
         [](Quality& q, uint32_t v) { q.mesh_resolution = std::min(v, q.photon_grid); });
    vary(steps_below(top.godray_grid, kGodrayGrids), [](Quality& q, uint32_t v) { q.godray_grid = v; });
    vary(lookup_ladder(top), [](Quality& q, const SceneLookups& v) {
        q.lookup_steps = v.steps;
        q.reflection_lookup = v.reflection;
        q.refraction_lookup = v.refraction;
    });
    // The caustics off: a candidate's kernel and map scale stay the top's (no map to splat into).
    vary(caustics_offered(top) ? std::vector<bool>{true, false} : std::vector<bool>{top.caustics},
         [](Quality& q, bool v) { q.caustics = v; });
    vary(kernels, [&top](Quality& q, CausticKernel v) { q.caustic_kernel = q.caustics ? v : top.caustic_kernel; });
    vary(map_scales, [&top](Quality& q, double v) { q.map_scale = q.caustics ? v : top.map_scale; });
    vary(top.second_layer ? std::vector<bool>{true, false} : std::vector<bool>{false},
         [](Quality& q, bool v) { q.second_layer = v && q.refraction_lookup; });  // the layer is the refraction view's
    vary(steps_below(top.shadow_texels, kShadowTexels), [](Quality& q, uint32_t v) { q.shadow_texels = v; });
    vary(top.terrain_fraction > 0.0 ? std::vector<double>(std::begin(kTerrainFractions), std::end(kTerrainFractions))
                                    : std::vector<double>{0.0},
         [](Quality& q, double v) { q.terrain_fraction = v; });
    return candidates;
}

void apply_quality(const Quality& quality, const Quality& top, Scene& scene) {
    if (scene.water && quality.photon_grid > 0) {
        scene.water->grid_resolution = quality.photon_grid;
        // As quality_arguments says it: below the top, the uniform mesh the cost and error models
        // were fitted with; at the top, the scene's own mesh (the screen's grid where it asks).
        if (quality.mesh_resolution != 0 &&
            (quality.mesh_resolution != top.mesh_resolution || quality.photon_grid != top.photon_grid)) {
            scene.water->mesh_resolution = quality.mesh_resolution;
            scene.water->mesh_cell_pixels.reset();
        }
    }
    if (top.godray_grid > 0) {
        if (quality.godray_grid == 0) {
            scene.effects[Effect::VolumeCaustics].mode = EffectMode::Off;
        } else {
            scene.effects.godrays.grid = quality.godray_grid;
        }
    }
    if (quality.lookup_steps > 0 && quality.lookup_steps < top.lookup_steps) {
        for (Effect lookup : {Effect::Reflection, Effect::Refraction}) {
            scene.effects[lookup].max_steps = static_cast<int>(quality.lookup_steps);
        }
    }
    if (top.reflection_lookup && !quality.reflection_lookup) scene.effects[Effect::Reflection].mode = EffectMode::Off;
    if (top.refraction_lookup && !quality.refraction_lookup) scene.effects[Effect::Refraction].mode = EffectMode::Off;
    if (top.caustics && !quality.caustics) scene.effects[Effect::SurfaceCaustics].mode = EffectMode::Off;
    if (top.map_scale > 0.0) {
        scene.effects.caustics.kernel = quality.caustic_kernel;
        scene.effects.caustics.map_scale = quality.map_scale;
    }
    if (top.second_layer && !quality.second_layer) {
        scene.effects[Effect::RefractionSecondLayer].mode = EffectMode::Off;
    }
    if (quality.shadow_texels != top.shadow_texels) scene.sun.shadow_texels = quality.shadow_texels;
    // At the top too: the viewer applies every frame to the scene it applied the last setting to.
    if (top.terrain_fraction > 0.0) {
        for (Receiver& receiver : scene.receivers) set_terrain_detail(receiver, quality.terrain_fraction);
    }
}

namespace {

// Each field the budget turns, the scene's beside the kept one's, in one list for both directions:
// `copy(in_scene, kept)` reads or writes it (Scene and SceneKnobFields const as the direction asks).
template <class SceneT, class FieldsT, class Copy>
void each_knob_field(SceneT& scene, FieldsT& fields, Copy copy) {
    if (scene.water) {
        copy(scene.water->grid_resolution, fields.grid_resolution);
        copy(scene.water->mesh_resolution, fields.mesh_resolution);
        copy(scene.water->mesh_cell_pixels, fields.mesh_cell_pixels);
    }
    copy(scene.effects.godrays.grid, fields.godray_grid);
    copy(scene.effects[Effect::VolumeCaustics].mode, fields.godrays);
    copy(scene.effects[Effect::Reflection].mode, fields.reflection);
    copy(scene.effects[Effect::Refraction].mode, fields.refraction);
    copy(scene.effects[Effect::RefractionSecondLayer].mode, fields.second_layer);
    copy(scene.effects[Effect::SurfaceCaustics].mode, fields.caustics);
    copy(scene.effects[Effect::Reflection].max_steps, fields.reflection_steps);
    copy(scene.effects[Effect::Refraction].max_steps, fields.refraction_steps);
    copy(scene.effects.caustics.kernel, fields.kernel);
    copy(scene.effects.caustics.map_scale, fields.map_scale);
    copy(scene.sun.shadow_texels, fields.shadow_texels);
}

}  // namespace

SceneKnobFields knob_fields(const Scene& scene) {
    SceneKnobFields fields;
    each_knob_field(scene, fields, [](const auto& in_scene, auto& kept) { kept = in_scene; });
    return fields;
}

void restore_knob_fields(const SceneKnobFields& fields, Scene& scene) {
    each_knob_field(scene, fields, [](auto& in_scene, const auto& kept) { in_scene = kept; });
}

std::vector<std::string> quality_arguments(const Quality& quality, const Quality& top, const Scene& scene) {
    std::vector<std::string> arguments;
    if (quality.render_scale != top.render_scale)
        arguments.push_back("--render-scale " + format_number(quality.render_scale));
    // A command option, not the scene's: stated whenever it is not the command's default of one.
    if (quality.samples != 1) arguments.push_back("--spp " + std::to_string(quality.samples));
    if (quality.photon_grid != top.photon_grid) {
        arguments.push_back("--set water.grid_resolution=" + std::to_string(quality.photon_grid));
    }
    if (quality.mesh_resolution != top.mesh_resolution || quality.photon_grid != top.photon_grid) {
        if (quality.mesh_resolution != 0) {
            arguments.push_back("--set water.mesh_resolution=" + std::to_string(quality.mesh_resolution));
        }
    }
    if (quality.godray_grid != top.godray_grid) {
        arguments.push_back(quality.godray_grid == 0
                                ? "--set effects.godrays.mode=off"
                                : "--set effects.godrays.grid=" + std::to_string(quality.godray_grid));
    }
    if (quality.lookup_steps > 0 && quality.lookup_steps < top.lookup_steps) {
        for (const char* lookup : {"reflection", "refraction"}) {
            arguments.push_back(std::string("--set effects.") + lookup +
                                ".max_steps=" + std::to_string(quality.lookup_steps));
        }
    }
    if (top.reflection_lookup && !quality.reflection_lookup) arguments.push_back("--set effects.reflection.mode=off");
    if (top.refraction_lookup && !quality.refraction_lookup) arguments.push_back("--set effects.refraction.mode=off");
    if (top.caustics && !quality.caustics) arguments.push_back("--set effects.caustics.mode=off");
    if (quality.caustic_kernel != top.caustic_kernel) {
        arguments.push_back(std::string("--set effects.caustics.kernel=") +
                            caustic_kernel_name(quality.caustic_kernel));
    }
    if (quality.map_scale != top.map_scale) {
        arguments.push_back("--set effects.caustics.map_scale=" + format_number(quality.map_scale));
    }
    if (top.second_layer && !quality.second_layer) {
        arguments.push_back("--set effects.refraction_second_layer.mode=off");
    }
    if (quality.shadow_texels != top.shadow_texels) {
        arguments.push_back("--set sun.shadow_texels=" + std::to_string(quality.shadow_texels));
    }
    if (quality.terrain_fraction != top.terrain_fraction) {
        for (size_t i = 0; i < scene.receivers.size(); ++i) {
            const std::optional<TerrainShape>& terrain = scene.receivers[i].terrain;
            if (!terrain) continue;
            arguments.push_back("--set receivers[" + std::to_string(i) +
                                "].resolution=" + std::to_string(terrain_cells(*terrain, quality.terrain_fraction)));
        }
    }
    return arguments;
}

std::string describe_arguments(const std::vector<std::string>& arguments) {
    std::string text;
    for (const std::string& argument : arguments) {
        // "--set receivers[0].resolution=32": quoted, or a shell would take the brackets as a pattern.
        const size_t value = argument.find(' ') + 1;
        const bool quote = argument.rfind("--set ", 0) == 0 && argument.find('[') != std::string::npos;
        text += (text.empty() ? "" : " ") +
                (quote ? argument.substr(0, value) + "'" + argument.substr(value) + "'" : argument);
    }
    return text.empty() ? "the scene's own settings" : text;
}

std::string describe_quality(const Quality& quality) {
    std::string text = "scale " + format_number(quality.render_scale);
    if (quality.photon_grid > 0) {
        text +=
            ", photons " + std::to_string(quality.photon_grid) + "^2, mesh " + std::to_string(quality.mesh_resolution);
    }
    if (quality.godray_grid > 0) text += ", godrays " + std::to_string(quality.godray_grid) + "^2";
    if (quality.lookup_steps > 0) {
        text += ", lookup steps " + std::to_string(quality.lookup_steps);
        if (!quality.reflection_lookup) text += " (refraction only)";
        if (!quality.refraction_lookup) text += " (reflection only)";
    }
    if (quality.second_layer) text += ", second layer";
    if (quality.shadow_texels > 0) text += ", shadow map " + std::to_string(quality.shadow_texels) + "^2";
    if (quality.terrain_fraction > 0.0) text += ", terrain cells x" + format_number(quality.terrain_fraction);
    if (!quality.caustics && quality.photon_grid > 0) text += ", caustics off";
    if (quality.map_scale > 0.0 && quality.caustics) {
        text += std::string(", kernel ") + caustic_kernel_name(quality.caustic_kernel) + ", map scale " +
                format_number(quality.map_scale);
    }
    if (quality.samples > 1) text += ", " + std::to_string(quality.samples) + " spp";
    return text;
}

}  // namespace vkw::budget
