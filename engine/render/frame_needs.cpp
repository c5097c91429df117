#include "engine/render/frame_needs.hpp"

#include "engine/water/surface.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace vkw {
namespace {

std::string format(const char* pattern, double a, double b) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
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

// effects.<name>.mode: auto keeps the rule's decision, on/off force it.
void decide(fg::FrameNeeds& needs, const Scene& scene, fg::Effect effect, bool rule, const std::string& reason) {
    switch (scene.effects[effect].mode) {
        case EffectMode::Auto: needs.decide(effect, rule, reason); break;
        case EffectMode::On: needs.decide(effect, true, "effects." + std::string(fg::effect_name(effect)) + ".mode = on (the rule says: " + reason + ")", true); break;
        case EffectMode::Off: needs.decide(effect, false, "effects." + std::string(fg::effect_name(effect)) + ".mode = off (the rule says: " + reason + ")", true); break;
    }
}

}  // namespace

WaterBounds water_bounds(const Scene& scene) {
    const Water& water = *scene.water;
    const double amplitude = make_surface(water.waves, water.level, water.time)->max_amplitude();
    // Gerstner and choppy waves also move points sideways, by at most the amplitude
    // bound for the models here; widen the box by it too.
    return {{-water.half_extent - amplitude, std::min(water_bottom(scene), water.level - amplitude),
             -water.half_extent - amplitude},
            {water.half_extent + amplitude, water.level + amplitude, water.half_extent + amplitude}};
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
    if (!scene.water) {
        decide(needs, scene, fg::Effect::Water, false, "the scene has no water");
        decide(needs, scene, fg::Effect::UnderwaterView, false, "the scene has no water");
        decide(needs, scene, fg::Effect::SurfaceCaustics, false, "the scene has no water");
        return needs;
    }
    const WaterBounds bounds = water_bounds(scene);
    const glm::dmat4 view_proj = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera);
    const bool water_visible = box_may_be_visible(view_proj, bounds.lo, bounds.hi);
    decide(needs, scene, fg::Effect::Water, water_visible,
           water_visible ? format("the water's box (y from %.3g to %.3g m) is in the view", bounds.lo.y, bounds.hi.y)
                         : "the water's box lies outside the view frustum");

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
    // Caustics: the sun must be up and the floor (the receiver the photons reach) under the
    // highest crest; without the water in view nothing shows them.
    const bool sun_up = scene.sun.direction.y < 0.0;
    const bool floor_under = scene.floor.height < bounds.hi.y;
    decide(needs, scene, fg::Effect::SurfaceCaustics, water_visible && sun_up && floor_under,
           !water_visible ? "the water is not in view"
           : !sun_up      ? "the sun is below the horizon"
           : !floor_under ? "the floor lies above the highest crest"
                          : format("the sun is up and the floor (y = %.3g m) lies under the water (crest %.3g m)",
                                   scene.floor.height, bounds.hi.y));

    const bool underwater = over_water && lowest < bounds.hi.y && highest > bounds.lo.y;
    decide(needs, scene, fg::Effect::UnderwaterView, underwater,
           underwater ? format("the near plane reaches y = %.3g m, below the highest crest at %.3g m", lowest,
                               bounds.hi.y)
                      : format("the near plane stays above y = %.3g m, over the highest crest at %.3g m", lowest,
                               bounds.hi.y));
    return needs;
}

}  // namespace vkw
