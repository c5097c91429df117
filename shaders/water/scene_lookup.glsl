// Following a ray reflected or refracted at the water surface through a scene view
// (passes/scene_views/scene_view.hpp, scene_views/scene_view.glsl) to the receiver mesh it meets.
// Two methods, chosen per scene (effects.reflection.method, effects.refraction.method):
//   - projective (de la Fuente 2011 and Optical Phenomena c. 2008): the hit is first estimated at the distance of what
//     the view shows straight behind the surface point (Optical Phenomena c. 2008 eq. 1), then refined by
//     fixed-point steps: look up where the estimate projects, move the estimate to the
//     distance of what is there, until it moves by less than 1e-4 of itself; where the steps
//     find nothing, the ray's crossing with what the view shows, bracketed and halved;
//   - screen-space (Ojeda & Susín 2013 section 5): march the ray through the view's distances in
//     steps of a few texels on the view, each no longer than the gap between the ray and
//     what the view shows there (so a step cannot pass through the surface under that
//     texel), then bisect the last step.
// Both return false where the view shows nothing along the ray or the ray leaves the view
// (the guard band); the caller then keeps its exact lookups of the floor and the sky.
// With the refraction view's second layer (REFRACTION_SECOND_LAYER), a refracted ray whose lookup
// finds nothing, or a surface it passes behind (behind a receiver that floats through the surface,
// behind a ridge), is marched again through the peeled view: the second layer where it shows
// something, else the first.
// Both end on one texel of the view; what the hit shows is then read between that texel and its
// neighbours on the same surface (filter_hit), not copied from the one texel.
#ifndef VKWATER_SCENE_LOOKUP_GLSL
#define VKWATER_SCENE_LOOKUP_GLSL

#include "scene_views/scene_view.glsl"

// The camera's side of the surface (reflected rays) and the other side (refracted rays).
layout(set = 0, binding = 8) uniform sampler2D reflection_view;
layout(set = 0, binding = 9) uniform sampler2D refraction_view;
// The refraction view's second layer (passes/scene_views/scene_view.hpp): what the first hides.
layout(set = 0, binding = 13) uniform sampler2D refraction_view_behind;
#ifdef VKWATER_CAUSTIC_LAYER
// The refraction view's caustic layers: the sun's irradiance on the receiver each texel holds.
layout(set = 0, binding = 10) uniform sampler2D refraction_view_caustic;
layout(set = 0, binding = 14) uniform sampler2D refraction_view_behind_caustic;
#endif
// 1: refracted rays also look in the second layer (passes/water/water_shading.cpp).
layout(constant_id = 8) const uint REFRACTION_SECOND_LAYER = 0u;

const uint SCENE_LOOKUP_OFF = 0u;
const uint SCENE_LOOKUP_PROJECTIVE = 1u;
const uint SCENE_LOOKUP_SCREEN_SPACE = 2u;
// How far one march step moves on the view, in texels: with the default 64 steps a ray
// is followed across 256 texels of the view (a quarter of a 800x600 frame's guard-banded
// view), further with more steps.
const float SCENE_LOOKUP_TEXELS_PER_STEP = 4.0;
// Bisection steps after the march: the hit to 2^-8 of the last step.
const int SCENE_LOOKUP_BISECTIONS = 8;

struct SceneHit {
    vec3 radiance;   // leaving the receiver toward the ray's origin
    float distance;  // from the ray's origin, m
    vec2 uv;         // the centre of the view's texel that holds it
    float shown;     // that texel's distance from the view's eye, m
    bool peeled;     // found in the peeled refraction view
    // The view's texels the radiance is read from (filter_hit): texel_base plus (0, 0), (1, 0),
    // (0, 1) and (1, 1), weighted by texel_weights (summing to 1).
    ivec2 texel_base;
    vec4 texel_weights;
};
// A hit on the view's texel at texel_uv, read from that texel alone (filter_hit widens it).
SceneHit texel_hit(vec3 radiance, float distance, vec2 texel_uv, float shown, bool peeled, ivec2 view_size) {
    const ivec2 texel = clamp(ivec2(texel_uv * vec2(view_size)), ivec2(0), view_size - 1);
    return SceneHit(radiance, distance, texel_uv, shown, peeled, texel, vec4(1.0, 0.0, 0.0, 0.0));
}
const SceneHit SCENE_NO_HIT = SceneHit(vec3(0.0), 0.0, vec2(0.0), 0.0, false, ivec2(0), vec4(0.0));

// The view's texel under uv (nearest: the distances must not blend across edges), and
// the uv of its centre.
vec4 scene_view_texel(sampler2D view, vec2 uv, out vec2 texel_uv) {
    ivec2 size = textureSize(view, 0);
    ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    texel_uv = (vec2(texel) + 0.5) / vec2(size);
    return texelFetch(view, texel, 0);
}

// The refraction view with its nearest receivers peeled away: the second layer where it shows
// something, else the first.
vec4 peeled_texel(vec2 uv, out vec2 texel_uv) {
    const vec4 behind = scene_view_texel(refraction_view_behind, uv, texel_uv);
    return behind.a > 0.0 ? behind : scene_view_texel(refraction_view, uv, texel_uv);
}

// The texel of `view`, or of the peeled refraction view.
vec4 view_texel(sampler2D view, bool peeled, vec2 uv, out vec2 texel_uv) {
    return peeled ? peeled_texel(uv, texel_uv) : scene_view_texel(view, uv, texel_uv);
}

// The estimate to start from: what the view shows straight behind p, or, where it shows nothing
// there, what it shows where the ray ends (max_distance along d). An object the ray reaches but
// the view's ray through p misses (one floating in the water, seen through the surface, which
// bends the rays toward it) is found from the second; with the first alone its image shrank to
// where both rays meet it, and shifted toward where it would be without the water.
bool projective_start(sampler2D view, bool peeled, bool mirrored, vec3 p, vec3 d, float max_distance, out float s) {
    s = 0.0;
    vec2 uv, texel_uv;
    if (!scene_view_uv(p, mirrored, uv)) return false;
    vec4 texel = view_texel(view, peeled, uv, texel_uv);
    if (texel.a > 0.0) {
        s = max(0.0, texel.a - distance(scene_view_eye(mirrored), p));
        return true;
    }
    if (!scene_view_uv(p + max_distance * d, mirrored, uv)) return false;
    texel = view_texel(view, peeled, uv, texel_uv);
    if (texel.a <= 0.0) return false;  // nothing on either: no estimate to start from
    s = max(0.0, dot(scene_view_point(texel_uv, texel.a, mirrored) - p, d));
    return true;
}

bool fixed_point_lookup(sampler2D view, bool peeled, bool mirrored, vec3 p, vec3 d, float max_distance, int max_steps,
                        out SceneHit hit) {
    hit = SCENE_NO_HIT;
    vec2 uv, texel_uv;
    vec4 texel = vec4(0.0);
    float s;
    if (!projective_start(view, peeled, mirrored, p, d, max_distance, s)) return false;
    // The previous step's texel, its centre and the estimate it gave, and the centre of the texel
    // two steps back. A ray that meets a receiver at a slant can alternate between two texels and
    // never converge (about a sixth of lake's refracted rays did, each running all max_steps
    // steps). Once a step's texel is the one of two steps before, every later step repeats the
    // pair and none converges, so the texel the last of the max_steps steps would end on is known
    // and taken at once: the same hit, bit for bit, without the steps.
    vec4 previous_texel = vec4(0.0);
    vec2 previous_uv = vec2(-1.0), uv_two_back = vec2(-1.0);
    float previous_s = 0.0;
    for (int i = 0; i < max_steps; ++i) {
        if (!scene_view_uv(p + s * d, mirrored, uv)) return false;
        texel = view_texel(view, peeled, uv, texel_uv);
        if (texel.a <= 0.0) return false;
        float next = max(0.0, dot(scene_view_point(texel_uv, texel.a, mirrored) - p, d));
        bool converged = abs(next - s) <= 1e-4 * next;
        if (!converged && texel_uv == uv_two_back) {
            const bool ends_on_previous = (max_steps - 1 - i) % 2 == 1;
            texel = ends_on_previous ? previous_texel : texel;
            texel_uv = ends_on_previous ? previous_uv : texel_uv;
            s = ends_on_previous ? previous_s : next;
            break;
        }
        uv_two_back = previous_uv;
        previous_texel = texel;
        previous_uv = texel_uv;
        previous_s = next;
        s = next;
        if (converged) break;
    }
    hit = texel_hit(texel.rgb, s, texel_uv, texel.a, peeled, textureSize(view, 0));
    return true;
}

// Halvings of the ray in the bracketed lookup: a ray of a few metres to about a millimetre, below
// a texel of the view at any distance it is used at. (9 halvings ran slower on llvmpipe than 12.)
const int SCENE_LOOKUP_BRACKET_HALVINGS = 12;

// Where the fixed-point steps find nothing to converge on, the ray's crossing with what the view
// shows, bracketed and halved: p lies in front of it, the ray's end (max_distance along d) must
// lie behind what the view shows there, and each halving keeps the half whose ends are in front
// and behind. A view seen at a grazing angle needs it: its straight rays through the far part of
// a surface can pass beyond everything (lake's far shore), so the steps, which start from what
// lies straight behind p, land on texels that show nothing, while the refracted rays, bent down,
// meet the bed. The bracket is kept only where it closed on one surface: the texels either side of
// it show that surface at about the same distance. Across a silhouette they do not (the far side
// shows something farther, or nothing), and the hit, hidden in the view, is not known.
bool bracketed_lookup(sampler2D view, bool peeled, bool mirrored, vec3 p, vec3 d, float max_distance, out SceneHit hit) {
    hit = SCENE_NO_HIT;
    const vec3 eye = scene_view_eye(mirrored);
    vec2 uv, texel_uv;
    if (!scene_view_uv(p + max_distance * d, mirrored, uv)) return false;
    vec4 texel = view_texel(view, peeled, uv, texel_uv);
    if (!(texel.a > 0.0) || distance(eye, p + max_distance * d) < texel.a) return false;
    float front = 0.0, behind = max_distance;
    vec4 front_texel = vec4(0.0), behind_texel = texel;
    vec2 behind_uv = texel_uv;
    for (int i = 0; i < SCENE_LOOKUP_BRACKET_HALVINGS; ++i) {
        const float middle = 0.5 * (front + behind);
        const vec3 q = p + middle * d;
        if (!scene_view_uv(q, mirrored, uv)) return false;
        texel = view_texel(view, peeled, uv, texel_uv);
        if (texel.a > 0.0 && distance(eye, q) >= texel.a) {
            behind = middle;
            behind_texel = texel;
            behind_uv = texel_uv;
        } else {
            front = middle;
            front_texel = texel;
        }
    }
    if (!(front_texel.a > 0.0) || abs(front_texel.a - behind_texel.a) > SCENE_VIEW_THICKNESS * behind_texel.a) {
        return false;
    }
    hit = texel_hit(behind_texel.rgb, behind, behind_uv, behind_texel.a, peeled, textureSize(view, 0));
    return true;
}

bool projective_lookup(sampler2D view, bool peeled, bool mirrored, vec3 p, vec3 d, float max_distance, int max_steps,
                       out SceneHit hit) {
    return fixed_point_lookup(view, peeled, mirrored, p, d, max_distance, max_steps, hit) ||
           bracketed_lookup(view, peeled, mirrored, p, d, max_distance, hit);
}

// The length along d from h that moves h's image in the view by about
// SCENE_LOOKUP_TEXELS_PER_STEP texels (measured over a trial step of 1% of h's distance).
float screen_space_step(vec3 h, vec3 d, vec2 view_size) {
    float trial = 0.01 * max(distance(frame.camera_position.xyz, h), 1e-3);
    vec4 a = scene_view_clip(h, false), b = scene_view_clip(h + trial * d, false);
    if (a.w <= 0.0 || b.w <= 0.0) return trial * SCENE_LOOKUP_TEXELS_PER_STEP;
    float moved = length((b.xy / b.w - a.xy / a.w) * 0.5 * view_size);
    return trial * SCENE_LOOKUP_TEXELS_PER_STEP / max(moved, 0.01);
}

// max_distance: how far along the ray to look (the floor's distance, or the scene's size).
bool screen_space_lookup(sampler2D view, bool peeled, vec3 p, vec3 d, float max_distance, int max_steps, out SceneHit hit) {
    hit = SCENE_NO_HIT;
    vec3 eye = frame.camera_position.xyz;
    vec2 view_size = vec2(textureSize(view, 0));
    float s = 0.0, previous = 0.0;
    vec2 uv, texel_uv;
    for (int i = 0; i <= max_steps && s <= max_distance; ++i) {
        if (!scene_view_uv(p + s * d, false, uv)) return false;
        vec4 texel = view_texel(view, peeled, uv, texel_uv);
        float ray_distance = distance(eye, p + s * d);
        float gap = texel.a - ray_distance;
        // Behind what the view shows, and by no more than the last step plus the
        // thickness objects are assumed to have: the ray went through that surface
        // (further behind, it passed behind an object: go on).
        if (texel.a > 0.0 && gap <= 0.0 && -gap <= s - previous + SCENE_VIEW_THICKNESS * texel.a) {
            float lo = previous, hi = s;
            for (int b = 0; b < SCENE_LOOKUP_BISECTIONS; ++b) {
                float mid = 0.5 * (lo + hi);
                scene_view_uv(p + mid * d, false, uv);
                vec4 at_mid = view_texel(view, peeled, uv, texel_uv);
                bool behind = at_mid.a > 0.0 && distance(eye, p + mid * d) >= at_mid.a;
                if (behind) hi = mid; else lo = mid;
            }
            scene_view_uv(p + hi * d, false, uv);
            const vec4 at_hit = view_texel(view, peeled, uv, texel_uv);
            // In the peeled view a step can enter a first-layer receiver's silhouette from empty
            // texels while far behind that receiver; the halving then closes on the silhouette, not
            // on a surface the ray meets, and the march goes on.
            const bool on_surface = distance(eye, p + hi * d) <= at_hit.a * (1.0 + SCENE_VIEW_THICKNESS);
            if (!peeled || on_surface) {
                hit = texel_hit(at_hit.rgb, hi, texel_uv, at_hit.a, peeled, textureSize(view, 0));
                return true;
            }
        }
        previous = s;
        // Steps of a few texels on screen; in front of a surface, no longer than the gap
        // to it: a step along d changes the distance from the eye by at most its length,
        // so it cannot cross the surface under this texel.
        float screen_step = screen_space_step(p + s * d, d, view_size);
        s += gap > 0.0 ? clamp(gap, 0.25 * screen_step, screen_step) : screen_step;
    }
    return false;
}

// Whether the refraction view's second layer shows something at the texel of uv.
bool in_second_layer(vec2 uv) {
    return texelFetch(refraction_view_behind, ivec2(uv * vec2(textureSize(refraction_view_behind, 0))), 0).a > 0.0;
}

// Whether a refracted ray's hit lies more than the views' thickness behind the surface its texel
// shows: the ray passed behind that surface (under it, beyond it) and the hit is not what it meets.
bool passes_behind(SceneHit hit, vec3 p, vec3 d) {
    return distance(frame.camera_position.xyz, p + hit.distance * d) > hit.shown * (1.0 + SCENE_VIEW_THICKNESS);
}

// The lookup of `method` in `view` (or in the peeled refraction view).
bool lookup_in(sampler2D view, bool peeled, uint method, bool mirrored, vec3 p, vec3 d, float max_distance,
               int max_steps, out SceneHit hit) {
    hit = SCENE_NO_HIT;
    if (method == SCENE_LOOKUP_PROJECTIVE) {
        return projective_lookup(view, peeled, mirrored, p, d, max_distance, max_steps, hit);
    }
    if (method == SCENE_LOOKUP_SCREEN_SPACE) return screen_space_lookup(view, peeled, p, d, max_distance, max_steps, hit);
    return false;
}

// Whether the ray from p along d meets, before max_distance, one of the boxes that together hold
// every receiver mesh (the frame constants', engine/scene/receiver_boxes.hpp). The views hold the
// receiver meshes alone, so a ray that meets none of the boxes can find nothing in them: its lookup
// is left out, and with it the lookup's false hits beside a silhouette. (In lake most reflected rays
// rise past the few objects over the water. A GPU warp whose rays all miss skips the lookup; llvmpipe
// runs it masked all the same, docs/performance-log.md "Lookups only for rays that can meet a receiver".)
bool ray_meets_receiver_box(vec3 p, vec3 d, float max_distance) {
    // A zero component of d would make 0 * inf = NaN on a face: 1e-30 in its place gives the slab
    // of a ray parallel to it (all of it, or none, by where p lies), whatever its sign.
    const vec3 inverse = 1.0 / mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    for (int i = 0; i < int(frame.receiver_boxes.x); ++i) {
        const vec3 a = (frame.receiver_box_min[i].xyz - p) * inverse;
        const vec3 b = (frame.receiver_box_max[i].xyz - p) * inverse;
        const vec3 enter = min(a, b), leave = max(a, b);
        if (max(max(enter.x, enter.y), max(enter.z, 0.0)) <= min(min(leave.x, leave.y), min(leave.z, max_distance))) {
            return true;
        }
    }
    return false;
}

// A refracted ray's lookup in the refraction view, and where the view's second layer runs, in it.
bool refracted_lookup(uint method, vec3 p, vec3 d, float max_distance, int max_steps, out SceneHit hit) {
    const bool found = lookup_in(refraction_view, false, method, false, p, d, max_distance, max_steps, hit);
    if (REFRACTION_SECOND_LAYER == 0u || (found && !passes_behind(hit, p, d))) return found;
    // The march, whatever the method: in the peeled view the ray passes behind the first layer's
    // receivers where nothing lies behind them (the view falls back to the first layer there),
    // which the projective method's estimates cannot pass, and the march steps over.
    // Only what the second layer holds is taken: what the first holds, its lookup would have found
    // (a march through the first layer alone meets false crossings where grazing rays pass under the
    // far edge of a surface, within the thickness, which grows with the distance).
    // A ray that found nothing is marched only where the second layer shows something where its end
    // projects: there a receiver hides what lies around the end. (At lake's far shore many rays find
    // nothing in the first layer, and marching them all doubled its water pass.)
    vec2 end_uv;
    if (!found && (!scene_view_uv(p + max_distance * d, false, end_uv) || !in_second_layer(end_uv))) return false;
    // A quarter of the steps: what a receiver hides lies close behind it on the view (lake's retried
    // rays find the same hits in 16 steps as in 64).
    SceneHit peeled_hit;
    if (!screen_space_lookup(refraction_view, true, p, d, max_distance, max_steps / 4, peeled_hit) ||
        !in_second_layer(peeled_hit.uv)) {
        return found;
    }
    hit = peeled_hit;
    return true;
}

// `texels` bilinearly at uv over the four texels around it that show the surface seen at distance
// `shown` (a distance from the eye within SCENE_VIEW_THICKNESS of it), their weights renormalised:
// texels base plus (0, 0), (1, 0), (0, 1) and (1, 1) with `weights`, and the radiance (rgb) and
// distance (a) they give. False where none of the four shows that surface.
bool read_surface_between_texels(sampler2D texels, vec2 uv, float shown, out ivec2 base, out vec4 weights,
                                 out vec4 value) {
    const ivec2 size = textureSize(texels, 0);
    const vec2 position = uv * vec2(size) - 0.5;  // in texels, from the first texel's centre
    base = ivec2(floor(position));
    const vec2 t = position - vec2(base);
    weights = vec4((1.0 - t.x) * (1.0 - t.y), t.x * (1.0 - t.y), (1.0 - t.x) * t.y, t.x * t.y);
    value = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        const vec4 texel = texelFetch(texels, clamp(base + ivec2(i & 1, i >> 1), ivec2(0), size - 1), 0);
        const bool same_surface = texel.a > 0.0 && abs(texel.a - shown) <= SCENE_VIEW_THICKNESS * shown;
        weights[i] = same_surface ? weights[i] : 0.0;
        value += weights[i] * texel;
    }
    const float total = weights.x + weights.y + weights.z + weights.w;
    if (!(total > 0.0)) return false;
    weights /= total;
    value /= total;
    return true;
}

// The same in the view a hit was found in: peeled, the refraction view's second layer alone. (One
// branch per hit rather than a choice per texel, which llvmpipe would run as both fetches; without
// the second layer the specialization constant leaves the branch out.)
bool read_hit_surface(sampler2D view, bool peeled, vec2 uv, float shown, out ivec2 base, out vec4 weights,
                      out vec4 value) {
    if (REFRACTION_SECOND_LAYER != 0u && peeled) {
        return read_surface_between_texels(refraction_view_behind, uv, shown, base, weights, value);
    }
    return read_surface_between_texels(view, uv, shown, base, weights, value);
}

// A hit's radiance read between the view's texels. The lookups end on one texel; its radiance alone
// would be copied to every pixel whose ray lands in that texel, so where the waves magnify what lies
// under them each texel shows as a block, and a caustic's focal line on a receiver as steps. Instead
// it is read bilinearly where the ray's point at the hit projects, over the texels around it that
// show the surface the hit's texel shows (read_hit_surface: across a silhouette the other
// side is left out, so edges stay where the lookup puts them). Where none of them shows that surface
// the hit keeps its own texel. (One more fixed-point step on the bilinear surface first lowered lake's
// error by a further 1-3% for 3-24% more of the water pass on lavapipe: docs/accuracy.md, "Hits read
// between the view's texels".)
void filter_hit(sampler2D view, bool mirrored, vec3 p, vec3 d, inout SceneHit hit) {
    vec2 uv;
    ivec2 base;
    vec4 weights, value;
    if (!scene_view_uv(p + hit.distance * d, mirrored, uv) ||
        !read_hit_surface(view, hit.peeled, uv, hit.shown, base, weights, value)) {
        return;
    }
    hit.radiance = value.rgb;
    hit.texel_base = base;
    hit.texel_weights = weights;
}

bool scene_lookup(uint method, bool reflected, vec3 p, vec3 d, float max_distance, int max_steps, out SceneHit hit) {
    hit = SCENE_NO_HIT;
    if (!ray_meets_receiver_box(p, d, max_distance)) return false;
    // Reflected rays read the reflection view (the mirrored one for the projective method); refracted
    // rays the camera's view of the other side.
    if (reflected) {
        const bool mirrored = method == SCENE_LOOKUP_PROJECTIVE;
        if (!lookup_in(reflection_view, false, method, mirrored, p, d, max_distance, max_steps, hit)) return false;
        filter_hit(reflection_view, mirrored, p, d, hit);
        return true;
    }
    if (!refracted_lookup(method, p, d, max_distance, max_steps, hit)) return false;
    filter_hit(refraction_view, false, p, d, hit);
    return true;
}

#ifdef VKWATER_CAUSTIC_LAYER
// `layer` at the texels and with the weights a hit's radiance was read with (filter_hit).
vec3 caustic_between_texels(sampler2D layer, SceneHit hit) {
    const ivec2 size = textureSize(layer, 0);
    vec3 caustic = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        caustic += hit.texel_weights[i] *
                   texelFetch(layer, clamp(hit.texel_base + ivec2(i & 1, i >> 1), ivec2(0), size - 1), 0).rgb;
    }
    return caustic;
}

// The caustic layer's value on what a refracted ray's hit shows.
vec3 refraction_view_caustic_at(SceneHit hit) {
    if (REFRACTION_SECOND_LAYER != 0u && hit.peeled) return caustic_between_texels(refraction_view_behind_caustic, hit);
    return caustic_between_texels(refraction_view_caustic, hit);
}
#endif

#endif
