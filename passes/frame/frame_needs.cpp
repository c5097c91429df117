#include "passes/frame/frame_needs.hpp"

#include "engine/core/errors.hpp"
#include "engine/water/beam_modulation_bound.hpp"
#include "engine/water/surface.hpp"

#include <algorithm>
#include <charconv>
#include <concepts>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace vkw {
namespace {

// Appends a reason's text with its numbers, as snprintf would write it: std::to_chars is specified
// to write a number as printf's %.Ng and %.Nf do, at a fraction of snprintf's cost (the needs are
// decided every frame, and snprintf was an eighth of the frame's CPU share). The conversions the
// reasons use: %.Ng, %.Nf and %%.
void append_format(std::string& text, const char* pattern, std::initializer_list<double> values) {
    const double* value = values.begin();
    for (const char* c = pattern; *c != '\0'; ++c) {
        if (*c != '%') {
            text += *c;
        } else if (c[1] == '%') {
            text += '%';
            ++c;
        } else {
            const auto unsupported = [&] {
                return InternalError(std::string("needs reason: unsupported pattern '") + pattern + "'");
            };
            if (c[1] != '.') throw unsupported();
            int precision = 0;
            for (c += 2; *c >= '0' && *c <= '9'; ++c) precision = 10 * precision + (*c - '0');
            if ((*c != 'g' && *c != 'f') || value == values.end()) throw unsupported();
            char digits[400];  // %.0f of the largest double: 309 digits
            const std::to_chars_result end =
                std::to_chars(digits, digits + sizeof digits, *value++,
                              *c == 'g' ? std::chars_format::general : std::chars_format::fixed, precision);
            text.append(digits, end.ptr);
        }
    }
}

// True unless all eight corners of the box lie outside one clip plane (a conservative
// frustum test: it may keep a box that is just outside a corner of the frustum).
bool box_may_be_visible(const glm::dmat4& view_proj, const glm::dvec3& lo, const glm::dvec3& hi) {
    glm::dvec4 corners[8];
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        corners[i] = view_proj * glm::dvec4(p, 1.0);
    }
    // Clip space with reversed-Z in [0, 1]: -w <= x, y <= w and 0 <= z <= w.
    auto all_outside = [&](auto outside) { return std::all_of(std::begin(corners), std::end(corners), outside); };
    return !(all_outside([](const glm::dvec4& c) { return c.x < -c.w; }) ||
             all_outside([](const glm::dvec4& c) { return c.x > c.w; }) ||
             all_outside([](const glm::dvec4& c) { return c.y < -c.w; }) ||
             all_outside([](const glm::dvec4& c) { return c.y > c.w; }) ||
             all_outside([](const glm::dvec4& c) { return c.z < 0.0; }) ||
             all_outside([](const glm::dvec4& c) { return c.z > c.w; }));
}

// effects.<name>.mode: auto keeps the rule's decision, on/off force it. `write` appends the rule's
// reason to the string it is given: the decision's own, written in place (FrameNeeds::clear).
template <class Write>
requires std::invocable<Write&, std::string&>
void decide(fg::FrameNeeds& needs, const Scene& scene, Effect effect, bool rule, Write&& write) {
    const EffectMode mode = scene.effects[effect].mode;
    if (mode == EffectMode::Auto) {
        write(needs.decide_in_place(effect, rule));
        return;
    }
    std::string& reason = needs.decide_in_place(effect, mode == EffectMode::On, /*forced=*/true);
    reason += "effects.";
    reason += effect_name(effect);
    reason += mode == EffectMode::On ? ".mode = on" : ".mode = off";
    reason += " (the rule says: ";
    write(reason);
    reason += ')';
}

void decide(fg::FrameNeeds& needs, const Scene& scene, Effect effect, bool rule, std::string_view reason) {
    decide(needs, scene, effect, rule, [&](std::string& text) { text += reason; });
}

// A reason that is one pattern with its numbers (append_format).
void decide(fg::FrameNeeds& needs, const Scene& scene, Effect effect, bool rule, const char* pattern,
            std::initializer_list<double> values) {
    decide(needs, scene, effect, rule, [&](std::string& text) { append_format(text, pattern, values); });
}

// The vertical span of the receivers whose box overlaps the water's horizontal extent
// (over the water, they can be seen in it or through it); empty when none does.
struct ReceiverSpan {
    bool any = false;
    double lowest = 1e300, highest = -1e300;
};
// Whether the receiver's box overlaps the water's horizontal extent.
bool over_water(const Receiver& receiver, const WaterBounds& bounds) {
    const glm::dvec3& lo = receiver.mesh.bounds_min;
    const glm::dvec3& hi = receiver.mesh.bounds_max;
    return !(hi.x < bounds.lo.x || lo.x > bounds.hi.x || hi.z < bounds.lo.z || lo.z > bounds.hi.z);
}

ReceiverSpan receivers_over_water(const Scene& scene, const WaterBounds& bounds) {
    ReceiverSpan span;
    for (const Receiver& receiver : scene.receivers) {
        if (!over_water(receiver, bounds)) continue;
        const glm::dvec3& lo = receiver.mesh.bounds_min;
        const glm::dvec3& hi = receiver.mesh.bounds_max;
        span.any = true;
        span.lowest = std::min(span.lowest, lo.y);
        span.highest = std::max(span.highest, hi.y);
    }
    return span;
}

// The refraction view's second layer (passes/scene_views/scene_view.hpp): what the nearest receiver
// hides from the camera. Refracted rays bend away from the camera's straight rays, so they can pass
// under a receiver that floats in the water, or beyond a ridge of one, and meet what the camera
// cannot see; the first layer holds only what it sees. Something can be hidden only where the
// refracted rays' side holds two receiver meshes, or one that is not convex (a terrain, a glTF
// mesh): a convex mesh alone hides only its own back, which no ray from outside meets first.
void decide_refraction_second_layer(fg::FrameNeeds& needs, const Scene& scene, const WaterBounds& bounds, double trough,
                                    bool camera_may_be_above, bool camera_may_be_below) {
    const fg::EffectDecision* refraction = needs.find(Effect::Refraction);
    if (!refraction || !refraction->needed) {
        return decide(needs, scene, Effect::RefractionSecondLayer, false, "the refraction view is not drawn");
    }
    int meshes = 0;
    bool not_convex = false;
    for (const Receiver& receiver : scene.receivers) {
        if (!over_water(receiver, bounds)) continue;
        // The refracted rays' side: under the crests for a camera above, over the troughs for one below.
        const bool on_refracted_side = (camera_may_be_above && receiver.mesh.bounds_min.y < bounds.hi.y) ||
                                       (camera_may_be_below && receiver.mesh.bounds_max.y > trough);
        if (!on_refracted_side) continue;
        ++meshes;
        not_convex = not_convex || receiver.type == ReceiverType::Terrain || receiver.type == ReceiverType::Gltf;
    }
    const bool hidden = meshes >= 2 || not_convex;
    if (meshes >= 2) {
        return decide(needs, scene, Effect::RefractionSecondLayer, hidden,
                      "%.0f receiver meshes lie on the refracted rays' side: one can hide another", {double(meshes)});
    }
    decide(needs, scene, Effect::RefractionSecondLayer, hidden,
           not_convex    ? "a receiver mesh that is not convex (a terrain or a glTF mesh) can hide part of itself"
           : meshes == 1 ? "one convex receiver mesh on the refracted rays' side: it hides only its own back"
                         : "no receiver mesh on the refracted rays' side");
}

// Reflection and refraction of the scene's objects (passes/scene_views/scene_view.hpp). The floor and
// the sky are looked up exactly without them, so the views are needed only for receiver
// meshes on the side of the surface each ray goes to: reflected rays stay on the camera's
// side, refracted rays cross to the other. The camera's side may be either when the near
// plane reaches into the band of the waves.
void decide_scene_lookups(fg::FrameNeeds& needs, const Scene& scene, const WaterBounds& bounds, bool water_visible,
                          bool camera_may_be_above, bool camera_may_be_below) {
    const ReceiverSpan span = receivers_over_water(scene, bounds);
    const double trough = 2.0 * scene.water->level - bounds.hi.y;  // the surface's lowest point
    const bool objects_above = span.any && span.highest > trough;
    const bool objects_below = span.any && span.lowest < bounds.hi.y;
    const bool reflection =
        water_visible && ((camera_may_be_above && objects_above) || (camera_may_be_below && objects_below));
    const bool refraction =
        water_visible && ((camera_may_be_above && objects_below) || (camera_may_be_below && objects_above));
    // Both views' reasons: where the camera is, what lies over the water, and what that gives.
    const auto reason = [&](bool view, const char* rays) {
        return [&, view, rays](std::string& text) {
            if (!water_visible) {
                text += "the water is not in view";
                return;
            }
            text += camera_may_be_above && camera_may_be_below ? "the near plane reaches into the waves"
                    : camera_may_be_above                      ? "the camera is above the water"
                                                               : "the camera is in the water";
            text += "; ";
            if (!span.any) {
                text += "no receiver mesh lies over the water (the floor and the sky are looked up exactly)";
            } else {
                append_format(text,
                              "receiver meshes over the water span y = %.3g to %.3g m (surface from %.3g to %.3g m)",
                              {span.lowest, span.highest, trough, bounds.hi.y});
            }
            text += view ? ": some lie on the " : ": nothing but the floor and sky on the ";
            text += rays;
            text += " rays' side";
        };
    };
    decide(needs, scene, Effect::Reflection, reflection, reason(reflection, "reflected"));
    decide(needs, scene, Effect::Refraction, refraction, reason(refraction, "refracted"));
    decide_refraction_second_layer(needs, scene, bounds, trough, camera_may_be_above, camera_may_be_below);
}

// The waves' bound on the beams' modulation (engine/water/beam_modulation_bound.hpp) for a sum of
// sines and Gerstner waves. Its inputs are the waves' amplitude, slope and curvature bounds (kept
// while the waves stay: frame_shape_bounds), the sun, the water and its depth, none of which the
// clock moves, so it is kept, per thread, while they stay: a running clock then runs neither the
// surface's bounds nor this one. Right after a lavapipe frame the two were most of the needs' time,
// for the code they run more than for their work (docs/performance-log.md "The needs decided into
// the last frame's").
const BeamModulationBound& waves_beam_bound(const Scene& scene, double depth) {
    const Water& water = *scene.water;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    const ShapeBounds shape = frame_shape_bounds(water.waves, water.level, water.time);
    const BeamModulationInputs inputs{scene.sun.direction,
                                      water.ior,
                                      frame_amplitude_bound(water.waves, water.level, water.time),
                                      shape.slope,
                                      shape.curvature,
                                      depth,
                                      std::max({sigma_t.x, sigma_t.y, sigma_t.z})};
    thread_local std::optional<BeamModulationInputs> kept_inputs;
    thread_local BeamModulationBound kept_bound;
    if (kept_inputs != inputs) {
        kept_inputs.reset();  // until the new bound is made
        kept_bound = beam_modulation_bound(inputs);
        kept_inputs = inputs;
    }
    return kept_bound;
}

// Godrays (volume caustics): the sun's refracted beams scattered toward the camera, as lines
// (passes/godrays/godrays.hpp). They need a lit, scattering medium in view. Without them the shading
// adds the flat beams' analytic in-scatter (docs/model.md section 6), which differs from theirs by
// the waves' modulation m of the beams' irradiance, m - 1 of it at most: where
// engine/water/beam_modulation_bound.hpp bounds that change below kGodraysInvisibleChange of the
// in-scatter (and so of the pixel, whose other terms only add), the passes would change no
// pixel visibly and are left out. Flat water with nothing over it is the exact case (m = 1).
void decide_godrays(fg::FrameNeeds& needs, const Scene& scene, const WaterBounds& bounds, bool water_visible,
                    bool sun_up) {
    const glm::dvec3& sigma_s = scene.medium.sigma_s;
    const double most = std::max({sigma_s.x, sigma_s.y, sigma_s.z});
    const bool scatters = most > 0.0;
    const auto rule = [&](bool needed, const auto& write) {
        decide(needs, scene, Effect::VolumeCaustics, needed, write);
    };
    // The reason of a rule that keeps them: the light and the medium, then why.
    const auto lit = [&](std::string& text) {
        append_format(text, "the sun is up, the water is in view and scatters (sigma_s up to %.3g 1/m); ", {most});
    };
    if (!water_visible) return rule(false, "the water is not in view");
    if (!sun_up) return rule(false, "the sun is below the horizon");
    if (!scatters) return rule(false, "the medium does not scatter (sigma_s = 0 in every channel)");
    if (receivers_over_water(scene, bounds).any) {
        return rule(true, [&](std::string& text) {
            lit(text);
            text += "receiver meshes over the water shadow the beams";
        });
    }
    const Water& water = *scene.water;
    const double depth = water.level - water_bottom(scene);
    const std::optional<double>& max_depth = scene.effects.godrays.max_depth;
    if (max_depth && *max_depth < depth) {
        return rule(true, [&](std::string& text) {
            lit(text);
            append_format(text, "effects.godrays.max_depth = %.3g m stops the beams above the bottom", {*max_depth});
        });
    }
    if (bounds.hi.y == water.level) {
        return rule(false,
                    "the water is flat and no object over it shadows the beams: the analytic in-scatter is exact");
    }
    // The FFT ocean's CPU surface would cost its FFTs to build, and its fields have no slope bound.
    if (water.waves.model == WaveModel::FftOcean) {
        return rule(true, [&](std::string& text) {
            lit(text);
            text += "the waves' beams: the FFT ocean gives no bound on its slope or curvature";
        });
    }
    const BeamModulationBound& bound = waves_beam_bound(scene, depth);
    if (!bound.bounded) {
        return rule(true, [&](std::string& text) {
            lit(text);
            text += "the waves' beams: ";
            text += bound.unbounded_because;
        });
    }
    const double change = bound.largest_relative_change();
    const auto range = [&](std::string& text) {
        append_format(text,
                      "the waves keep the beams' irradiance within %.4g to %.4g of flat water's down to %.3g m, an "
                      "in-scatter change of at most %.3g%%",
                      {bound.low, bound.high, depth, 100.0 * change});
    };
    if (change <= kGodraysInvisibleChange) {
        return rule(false, [&](std::string& text) {
            range(text);
            append_format(text, " <= %.3g%% (no preview pixel moves by half a step): the analytic in-scatter stands in",
                          {100.0 * kGodraysInvisibleChange});
        });
    }
    rule(true, [&](std::string& text) {
        lit(text);
        range(text);
        append_format(text, " > %.3g%%", {100.0 * kGodraysInvisibleChange});
    });
}

}  // namespace

WaterBounds water_bounds(const Scene& scene) {
    const Water& water = *scene.water;
    const double amplitude = frame_amplitude_bound(water.waves, water.level, water.time);
    // Gerstner and choppy waves also move points sideways, by at most the amplitude
    // bound for the models here; widen the box by it too.
    // Infinite water: the square of all the camera can see.
    const double extent = water_drawn_half_extent(scene);
    return {{-extent - amplitude, std::min(water_bottom(scene), water.level - amplitude), -extent - amplitude},
            {extent + amplitude, water.level + amplitude, extent + amplitude}};
}

std::array<glm::dvec3, 4> near_plane_corners(const Camera& camera, double aspect) {
    const glm::dmat4 inverse = glm::inverse(projection_matrix(camera, aspect) * view_matrix(camera));
    std::array<glm::dvec3, 4> corners;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec4 p = inverse * glm::dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, 1.0, 1.0);  // z = 1: near
        corners[i] = glm::dvec3(p) / p.w;
    }
    return corners;
}

fg::FrameNeeds decide_frame_needs(const Scene& scene, double aspect) {
    fg::FrameNeeds needs;
    decide_frame_needs(scene, aspect, needs);
    return needs;
}

void decide_frame_needs(const Scene& scene, double aspect, fg::FrameNeeds& needs) {
    needs.clear();
    if (!scene.water) {
        decide(needs, scene, Effect::Water, false, "the scene has no water");
        decide(needs, scene, Effect::UnderwaterView, false, "the scene has no water");
        decide(needs, scene, Effect::SurfaceCaustics, false, "the scene has no water");
        decide(needs, scene, Effect::CausticBlur, false, "the scene has no water");
        decide(needs, scene, Effect::Reflection, false, "the scene has no water");
        decide(needs, scene, Effect::Refraction, false, "the scene has no water");
        decide(needs, scene, Effect::RefractionSecondLayer, false, "the scene has no water");
        decide(needs, scene, Effect::VolumeCaustics, false, "the scene has no water");
        return;
    }
    const WaterBounds bounds = water_bounds(scene);
    const glm::dmat4 view_proj = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera);
    const bool water_visible = box_may_be_visible(view_proj, bounds.lo, bounds.hi);
    if (water_visible) {
        decide(needs, scene, Effect::Water, true, "the water's box (y from %.3g to %.3g m) is in the view",
               {bounds.lo.y, bounds.hi.y});
    } else {
        decide(needs, scene, Effect::Water, false, "the water's box lies outside the view frustum");
    }

    // Some pixel's ray starts in the water only if the near-plane rectangle reaches
    // below the highest crest inside the water's extent (and above its bottom).
    double lowest = 1e300, highest = -1e300;
    bool over_water = false;
    for (const glm::dvec3& corner : near_plane_corners(scene.camera, aspect)) {
        lowest = std::min(lowest, corner.y);
        highest = std::max(highest, corner.y);
        over_water = over_water || (corner.x >= bounds.lo.x && corner.x <= bounds.hi.x && corner.z >= bounds.lo.z &&
                                    corner.z <= bounds.hi.z);
    }
    // Caustics: the sun must be up and a receiver the photons reach (the floor, or a mesh whose
    // box overlaps the water's extent) below the highest crest; without the water in view nothing
    // shows them.
    const bool sun_up = scene.sun.direction.y < 0.0;
    const bool floor_under = scene.floor.height < bounds.hi.y;
    const ReceiverSpan meshes = receivers_over_water(scene, bounds);
    const bool mesh_under = meshes.any && meshes.lowest < bounds.hi.y;
    // Flat water: the stand-in (with the sun shadow map along the refracted beam) is exact.
    const bool flat_stand_in = bounds.hi.y == scene.water->level && scene.effects.caustics.analytic_flat;
    decide(needs, scene, Effect::SurfaceCaustics,
           water_visible && sun_up && (floor_under || mesh_under) && !flat_stand_in, [&](std::string& text) {
               if (!water_visible) {
                   text += "the water is not in view";
               } else if (!sun_up) {
                   text += "the sun is below the horizon";
               } else if (!floor_under && !mesh_under) {
                   text += "the floor and every receiver mesh lie above the highest crest";
               } else if (flat_stand_in) {
                   text += "the water is flat: the flat-surface stand-in is exact (effects.caustics.analytic_flat)";
               } else if (floor_under) {
                   append_format(text, "the sun is up and the floor (y = %.3g m) lies under the water (crest %.3g m)",
                                 {scene.floor.height, bounds.hi.y});
               } else {
                   append_format(text,
                                 "the sun is up and receiver meshes reach under the water (down to y = %.3g m, crest "
                                 "%.3g m)",
                                 {meshes.lowest, bounds.hi.y});
               }
           });
    // The blur feeds nothing but the light-space caustic map: needed when the map is and its radius
    // is not 0.
    const fg::EffectDecision* caustics = needs.find(Effect::SurfaceCaustics);
    const bool caustics_run = caustics && caustics->needed;
    const double blur_radius = scene.effects.caustic_blur.radius;
    const bool camera_space = scene.effects.caustics.splat == CausticSplat::CameraSpace;
    decide(needs, scene, Effect::CausticBlur, caustics_run && !camera_space && blur_radius > 0.0,
           [&](std::string& text) {
               if (!caustics_run) {
                   text += "the caustic passes do not run";
               } else if (camera_space) {
                   text += "the caustics are splatted in camera space (effects.caustics.splat): no map to blur";
               } else if (blur_radius > 0.0) {
                   append_format(text, "the caustic map runs and caustic_blur.radius = %.3g texels", {blur_radius});
               } else {
                   text += "caustic_blur.radius = 0 (no blur)";
               }
           });
    decide_godrays(needs, scene, bounds, water_visible, sun_up);

    const bool underwater = over_water && lowest < bounds.hi.y && highest > bounds.lo.y;
    decide(needs, scene, Effect::UnderwaterView, underwater,
           underwater ? "the near plane reaches y = %.3g m, below the highest crest at %.3g m"
                      : "the near plane stays above y = %.3g m, over the highest crest at %.3g m",
           {lowest, bounds.hi.y});
    const double trough = 2.0 * scene.water->level - bounds.hi.y;
    decide_scene_lookups(needs, scene, bounds, water_visible, !over_water || highest >= trough, underwater);
}

}  // namespace vkw
