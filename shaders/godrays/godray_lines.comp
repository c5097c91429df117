#version 460
// Godray lines (passes/godrays/godrays_lines.hpp; docs/model.md section 6, de la Fuente 2011 section 4.6): each beam
// of godray_beams.comp is walked along its line on the screen, one invocation per beam and view
// (gl_GlobalInvocationID.z: direct, mirrored or refracted, godray_view.glsl), and deposits its
// in-scattered radiance into 64-bit fixed-point counters (godray_fixed_point.glsl) of two
// pyramids (godray_pyramid.glsl), without the flat beam's phase function and the surface's weight,
// which the resolve applies per pixel. Integer addition makes the sum independent of the order the
// atomics land in, so runs are bit-identical.
//
// A beam stands for a tube: its photon cell, a horizontal square of side h (beam.direction.w),
// swept along its direction t, carrying E_tube = Phi0 / (h^2 |t.y|); the tubes of the grid tile the
// lit water. The walk is a DDA along the line's major screen axis; each step covers one column of
// a pyramid level (or less: at most a quarter of the view distance and half an optical length of
// beam), its ends on the line turned into beam parameters perspective-correctly. The direct and
// mirrored views, whose seen point is affine in the beam parameter, walk the line in pieces over
// which the clip w at most doubles (fp32 screen parameters stay resolved however near the eye the
// line comes); the refracted view in pieces of about 16 pixels of chord and a tenth of the apparent
// distance, within which the surface crossing is taken as affine. The tube's width in pixels across
// the narrower side of the pixel cone, 2^lambda with lambda = log2(h / (sqrt(Omega) min(cone))),
// decides how the step deposits (godray_line_estimate.glsl, godray_chords.glsl):
// - lambda < 0, thinner than a pixel: docs/model.md section 6's line estimate at level 0,
//     Delta L = Phi0 sigma_s p(cos alpha) exp(-sigma_t (d_in + s_w)) l_pix / A_pix,
//   l_pix the beam length of the step (the exponential integrated over it), spread across the line
//   over the tube's projected cross-section with the column (a trapezoid, from the projection's
//   derivatives), so that each pixel takes its share of the tube's area and the tubes' profiles tile
//   the screen as the tubes tile the water;
// - wider: on the pyramid levels around lambda (hat-function shares of adjacent levels, a partition
//   of unity that varies smoothly with distance), each pixel of the level near the step takes the
//   exact in-scatter of its own centre ray through the step's slice of the tube: the ray's chord
//   through that slice (a ray against a slanted prism), sigma_s E_tube times the integral of
//   exp(-sigma_t (d_in + s_w)) along the chord, in closed form. The slices of all tubes partition the
//   water, so every such ray sums its exact in-scatter. A tube whose axis passes behind the eye but
//   whose body reaches in front deposits that slice on the coarsest level, every pixel of it.
// The singular case, the camera looking along the beams (l_pix without bound as a beam turns into
// the view ray): a wide tube seen end-on gives each ray the chord it really has; a thin one spreads
// its step over its projected cross-section, in pixels whose cone is wider than the tube; either way
// one beam adds to a pixel at most the radiance of its tube seen end-on, sigma_s p E_tube / sigma_t
// (docs/model.md section 6 with the tube's irradiance).
// Depth: the line estimate tests each pixel of its profile against the scene; a chord is cut at
// the scene's distance (direct) or kept only where the pixel sees the water surface (mirrored,
// refracted).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

#include "common/medium.glsl"
#include "godrays/godray_beam.glsl"
#include "godrays/godray_fixed_point.glsl"
#include "godrays/godray_pyramid.glsl"
#include "godrays/godray_view.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) readonly buffer Beams { GodrayBeam beams[]; };
// r: the distance to the scene along the pixel's ray; g: 1 where the ray starts in the water.
layout(set = 0, binding = 2) uniform sampler2D view_depth;
// The pyramids of godray_pyramid.glsl, in units of godray_lsb().
layout(set = 0, binding = 3, std430) buffer Radiance { uint64_t radiance[]; };

// Its C++ type (GodrayLinesPush in passes/godrays/godrays_lines.cpp) is generated from this shader.
layout(push_constant) uniform Push {
    uint grid;              // G: beams per side
    uint per_pixel_medium;  // 1: view_depth.g decides each pixel's view; 0: the frame's camera medium
    float max_amplitude;    // m: a bound on the waves' height, the margin of the surface's depth
    int levels;             // of each pyramid
} pc;

const float kNegligible = 40.0;  // optical depth beyond which exp(-x) < 4.3e-18 adds nothing
const float kPieceChord = 16.0;  // pixels of chord per piece of a refracted line
const int kMaxPieces = 128;      // of a refracted line
const int kMaxSteps = 16384;     // a guard: a line is at most a few thousand steps
const int kMaxCells = 16;        // per side of the cells one wide step visits
// The beams are walked from this fraction of the near plane's distance, or of the beams' width,
// whichever is larger, on: the part before it holds that distance times sigma_t of the in-scatter
// at most (1e-5 of it at near 1 cm, sigma_t 1), and fp32 projections stay finite and ordered.
const float kNearFraction = 1e-3;

GodrayView view;
GodrayBeam beam;
uint kind;
ivec2 image_size;
float inv_lsb;
uint level_offset[17];  // and the whole pyramid's size last
vec3 flat_sun;          // the beams' direction under flat water
vec3 sigma_t;

float walk_start() { return kNearFraction * max(frame.camera_near.x, beam.direction.w); }

bool view_applies() {
    const float level = frame.water.x;
    if (kind == kGodrayViewRefracted && !(view.eye.y > level)) return false;
    if (kind == kGodrayViewMirrored && !(view.eye.y < level)) return false;
    return pc.per_pixel_medium != 0u || ((kind == kGodrayViewRefracted) != (frame.camera_medium.x > 0.5));
}

// The scene at a level-0 pixel (clamped to the image): r its distance, g its camera medium; false
// where this view does not serve the pixel.
bool scene_at(ivec2 pixel, out float scene_distance) {
    const vec2 scene = texelFetch(view_depth, clamp(pixel, ivec2(0), image_size - 1), 0).rg;
    scene_distance = scene.x;
    return pc.per_pixel_medium == 0u || ((kind == kGodrayViewRefracted) != (scene.y > 0.5));
}

// The margin within which a pixel sees the water surface where the flat one lies at `surface`:
// waves move it by up to max_amplitude.
float surface_margin(float surface, float cos_surface) {
    return pc.max_amplitude / max(cos_surface, 0.05) + 1e-3 * surface;
}

// The flat surface at p lies over the water's square (a ray crossing it elsewhere leaves or misses
// the water through its sides).
bool on_water(vec3 p) { return all(lessThanEqual(abs(p.xz), vec2(frame.water.z))); }

// The level-0 pixel, whose scene lies at `scene`, sees the water surface rather than something in
// front of it: its own centre ray meets the flat surface where the scene is, within the waves'
// margin (mirrored and refracted views; the scene distance is that of the pixel's centre ray, which
// at a grazing angle differs from its corners' by far more than the margin).
bool sees_water(ivec2 pixel, float scene) {
    const vec3 d = godray_pixel_ray(vec2(pixel) + 0.5, vec2(image_size));
    if (d.y == 0.0) return false;
    const float surface = (frame.water.x - view.eye.y) / d.y;
    if (!(surface > 0.0)) return false;
    const float margin = surface_margin(surface, abs(d.y));
    return kind == kGodrayViewMirrored ? scene >= surface - margin : surface <= scene + margin;
}

// The scene at a level-0 pixel lets the view path reach the beam point, from this view's medium.
// Directly: the point lies before the scene, give or take two pixels' width at its distance (the
// scene's distance is the pixel centre's, and a surface seen obliquely spans more within a pixel).
// Mirrored or refracted: the view path crosses the flat surface over the water, and the pixel sees
// the water surface, not something in front of it: its centre ray meets the flat surface where the
// scene is, within the waves' margin.
bool visible(ivec2 pixel, GodraySight sight) {
    float scene;
    if (!scene_at(pixel, scene)) return false;
    if (kind == kGodrayViewDirect) {
        return sight.in_water <= scene + 2.0 * sqrt(godray_pixel_solid_angle(view, sight.seen - view.eye)) * sight.in_water;
    }
    const vec3 crossing = kind == kGodrayViewRefracted ? sight.seen
                                                       : view.eye + sight.surface * normalize(sight.seen - view.eye);
    return on_water(crossing) && sees_water(pixel, scene);
}

vec3 beam_point(float tau) { return beam.entry.xyz + tau * beam.direction.xyz; }

vec3 seen_point(vec3 p) {
    const float level = frame.water.x;
    if (kind == kGodrayViewDirect) return p;
    if (kind == kGodrayViewMirrored) return vec3(p.x, 2.0 * level - p.y, p.z);
    return godray_surface_crossing(view.eye, p, level, frame.water.y);
}

float clip_w(vec3 p) { return (frame.view_proj * vec4(p, 1.0)).w; }

// The fraction of the way from a to b (in the seen points) at screen parameter u, for a line whose
// ends lie at clip w_a and w_b (1/w is affine in screen space), and its inverse.
float perspective(float u, float w_a, float w_b) { return u * w_a / ((1.0 - u) * w_b + u * w_a); }
float screen_parameter(float lambda, float w_a, float w_b) { return lambda * w_b / ((1.0 - lambda) * w_a + lambda * w_b); }

void deposit(int level, ivec2 pixel, vec3 value) {
    const uint set = kind == kGodrayViewMirrored ? uint(kGodrayMirrored) : uint(kGodrayStraight);
    const uint base = (set * level_offset[pc.levels] + level_offset[level] +
                       uint(pixel.y * godray_level_size(image_size, level).x + pixel.x)) * 3u;
    for (uint ch = 0u; ch < 3u; ++ch) {
        const float units = value[ch] * inv_lsb;
        if (!(units >= 0.5)) continue;  // rounds to 0 (and keeps any NaN out of the counters)
        atomicAdd(radiance[base + ch], uint64_t(min(units, kGodrayMaxDeposit) + 0.5));
    }
}

// The ratio of the beam's own phase function to the flat beam's for view direction v (exactly 1
// under flat water): the resolve multiplies by the flat beam's, per pixel.
float own_phase(vec3 v) {
    const float g = frame.medium_sigma_s.w;
    return henyey_greenstein(dot(beam.direction.xyz, -v), g) / henyey_greenstein(dot(flat_sun, -v), g);
}

// The line being walked: screen ends a, b (xy level-0 pixels, z clip w), beam parameters and seen
// points at its ends.
struct Line {
    vec3 a, b;
    float tau_a, tau_b;
    vec3 seen_a, seen_b;
    int major;
};

GodraySight sight_at(Line line, float lambda, out float tau) {
    tau = mix(line.tau_a, line.tau_b, lambda);
    return godray_sight(kind, view.eye, beam_point(tau), mix(line.seen_a, line.seen_b, lambda), frame.water.x,
                        frame.water.y);
}

// A_pix of a level-0 pixel at the sight's point.
float pixel_area(GodraySight sight) {
    return godray_pixel_solid_angle(view, sight.seen - view.eye) * sight.cone.x * sight.cone.y;
}

#include "godrays/godray_line_estimate.glsl"
#include "godrays/godray_chords.glsl"

// The line between the seen points of beam parameters tau_a and tau_b, step by step.
void walk_line(float tau_a, float tau_b, vec3 seen_a, vec3 seen_b) {
    Line line;
    line.a = godray_project(view, seen_a);
    line.b = godray_project(view, seen_b);
    line.tau_a = tau_a;
    line.tau_b = tau_b;
    line.seen_a = seen_a;
    line.seen_b = seen_b;
    const float near = walk_start();
    if (!(line.a.z >= near) || !(line.b.z >= near) || !(tau_b > tau_a)) return;
    // Liang-Barsky: the part of the line over the image, grown by the widest footprint (twice the
    // beam's width at the nearer end: a tube next to the camera covers the image from far outside it,
    // and its steps there are coarse).
    const vec2 d = line.b.xy - line.a.xy;
    float tau;
    const float widest =
        2.0 * beam.direction.w / sqrt(min(pixel_area(sight_at(line, 0.0, tau)), pixel_area(sight_at(line, 1.0, tau))));
    const float margin = min(widest, 1e7) + 2.0;
    const vec2 lo = vec2(-margin), hi = vec2(image_size) + margin;
    float u0 = 0.0, u1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0.0) {
            if (line.a[axis] < lo[axis] || line.a[axis] > hi[axis]) return;
            continue;
        }
        const float ta = (lo[axis] - line.a[axis]) / d[axis], tb = (hi[axis] - line.a[axis]) / d[axis];
        u0 = max(u0, min(ta, tb));
        u1 = min(u1, max(ta, tb));
    }
    if (!(u0 < u1)) return;
    line.major = abs(d.x) >= abs(d.y) ? 0 : 1;
    const float dm = d[line.major];
    const float max_sigma_t = max(sigma_t.r, max(sigma_t.g, sigma_t.b));
    const float min_sigma_t = min(sigma_t.r, min(sigma_t.g, sigma_t.b));
    // Each step is sized by the tube's width at the previous step's middle (the first: at the start).
    GodraySight sight = sight_at(line, perspective(u0, line.a.z, line.b.z), tau);
    float lambda = sight_level(sight);
    vec2 along_x, along_z;
    float u = u0;
    for (int step = 0; step < kMaxSteps && u < u1; ++step) {
        // Past 40 optical depths of the beam itself nothing further along it can count.
        if (min_sigma_t * tau > kNegligible) return;
        // Steps of one column of the finest level the step deposits on (beyond the coarsest level,
        // of the tube's own width: next to the camera a tube spans far more than the image).
        const float cell = exp2(max(floor(lambda - 0.25), 0.0));
        float ue = u1;
        if (dm != 0.0) {
            const float at = line.a[line.major] + u * dm;
            const float boundary = dm > 0.0 ? (floor(at / cell) + 1.0) * cell : (ceil(at / cell) - 1.0) * cell;
            ue = min(ue, (boundary - line.a[line.major]) / dm);
        }
        // At most a quarter of the view distance (A_pix stays within a factor 1.6) and half an
        // optical length of beam per step.
        const float reach = min(0.25 * min(sight.cone.x, sight.cone.y), 0.5 / max(max_sigma_t, 1e-30));
        const float lambda_end = (tau + reach - line.tau_a) / (line.tau_b - line.tau_a);
        if (lambda_end < 1.0) ue = min(ue, screen_parameter(lambda_end, line.a.z, line.b.z));
        ue = min(max(ue, u + 1e-6), u1);  // always forward, whatever the rounding
        sight = sight_at(line, perspective(0.5 * (u + ue), line.a.z, line.b.z), tau);
        const vec2 section = cross_section(line, sight, tau, along_x, along_z);
        lambda = sight_level(sight);
        if (lambda < 0.0) {
            thin_step(line, u, ue, sight, tau, section, along_x, along_z);
        } else {
            wide_step(line, u, ue, lambda, mix(line.tau_a, line.tau_b, perspective(u, line.a.z, line.b.z)),
                      mix(line.tau_a, line.tau_b, perspective(ue, line.a.z, line.b.z)), along_x, along_z);
        }
        u = ue;
    }
}

void main() {
    const uvec3 g = gl_GlobalInvocationID;
    if (g.x >= pc.grid || g.y >= pc.grid) return;
    kind = g.z;
    beam = beams[g.y * pc.grid + g.x];
    const float len = beam.entry.w;
    if (!(len > 0.0) || !(max(beam.flux.r, max(beam.flux.g, beam.flux.b)) > 0.0)) return;
    image_size = textureSize(view_depth, 0);
    view = godray_view(vec2(image_size));
    if (!view_applies()) return;
    inv_lsb = 1.0 / godray_lsb();
    for (int l = 0; l <= pc.levels; ++l) level_offset[l] = godray_level_offset(image_size, l);
    flat_sun = godray_flat_refracted_sun();
    sigma_t = frame.medium_sigma_t.rgb;
    // The view ray starts at the eye (docs/model.md section 6), not at the near plane: beams are clipped
    // just past walk_start() (rounding keeps a clipped end in front of it).
    const float near = 1.001 * walk_start();

    if (kind != kGodrayViewRefracted) {
        // The seen point is affine in tau, and so is its clip w: clip to the near plane exactly.
        const float w0 = clip_w(seen_point(beam_point(0.0))), w1 = clip_w(seen_point(beam_point(len)));
        // Where the axis passes behind the eye, the tube around it still reaches in front for as
        // long as w stays above minus its half extent along the view axis.
        const float rate = (w1 - w0) / len;  // dw / dtau
        const float half_extent = 0.5 * beam.direction.w * (abs(view.forward.x) + abs(view.forward.z));
        const float behind = abs(rate) > 0.0 ? half_extent / abs(rate) : 0.0;
        if (w0 < near && w1 < near) {
            if (max(w0, w1) > -half_extent) straddling_slice(0.0, len);
            return;
        }
        float t0 = 0.0, t1 = len;
        if (w0 < near) {
            t0 = len * (near - w0) / (w1 - w0);
            straddling_slice(max(0.0, t0 - behind), t0);
        }
        if (w1 < near) {
            t1 = len * (near - w0) / (w1 - w0);
            straddling_slice(t1, min(len, t1 + behind));
        }
        // In pieces over which w at most doubles: a piece's screen length stays within what fp32
        // screen parameters resolve, however close to the eye the line comes. w is affine in tau.
        const float wa = w0 + rate * t0, wb = w0 + rate * t1;
        const float w_near = min(wa, wb), ratio = max(wa, wb) / w_near;
        const int pieces = rate == 0.0 ? 1 : int(clamp(ceil(log2(ratio)), 1.0, 64.0));
        float w_from = w_near;
        for (int k = 1; k <= pieces; ++k) {
            const float w_to = w_near * exp2(log2(ratio) * float(k) / float(pieces));
            const float ta = rate == 0.0 ? t0 : clamp(t0 + (w_from - wa) / rate, t0, t1);
            const float tb = rate == 0.0 ? t1 : (k == pieces ? (wa < wb ? t1 : t0) : clamp(t0 + (w_to - wa) / rate, t0, t1));
            const float lo = min(ta, tb), hi = max(ta, tb);
            walk_line(lo, hi, seen_point(beam_point(lo)), seen_point(beam_point(hi)));
            w_from = w_to;
        }
        return;
    }
    // Refracted: the surface crossing moves nonlinearly along the beam; pieces of at most a tenth of
    // the apparent distance s_a + s_w / n at their start (so they grow geometrically away from the
    // eye) and about kPieceChord pixels of chord (kMaxPieces at most, the last taking the rest), each
    // walked as a line. Pieces behind the camera drop.
    const vec3 a = godray_project(view, seen_point(beam_point(0.0))), b = godray_project(view, seen_point(beam_point(len)));
    const float chord = a.z > near && b.z > near ? length(b.xy - a.xy) : 1e6;
    const float by_chord = len / clamp(ceil(chord / kPieceChord), 1.0, float(kMaxPieces));
    const float n = frame.water.y;
    vec3 start = seen_point(beam_point(0.0));
    float tau0 = 0.0;
    for (int k = 1; k <= kMaxPieces && tau0 < len; ++k) {
        const float apparent = distance(start, view.eye) + distance(beam_point(tau0), start) / n;
        const float tau1 = k == kMaxPieces ? len : min(len, tau0 + max(min(by_chord, 0.1 * n * apparent), 1e-6 * len));
        const vec3 end = seen_point(beam_point(tau1));
        walk_line(tau0, tau1, start, end);
        start = end;
        tau0 = tau1;
    }
}
