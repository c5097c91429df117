#version 460
// Godray lines (passes/godrays_lines.hpp; PHYSICS.md section 6, seed 000 section 4.6): each beam
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
// beam), its ends on the line turned into beam parameters perspective-correctly (exact for the
// direct and mirrored views, whose seen point is affine in the beam parameter; the refracted view
// is cut into pieces of about 16 pixels of chord and a tenth of the apparent distance, within
// which the surface crossing is taken as affine). The tube's width across the line at the step (its cross-section with the column, from
// the projection's derivatives) decides how the step deposits:
// - thinner than a pixel: PHYSICS.md section 6's line estimate at level 0,
//     Delta L = Phi0 sigma_s p(cos alpha) exp(-sigma_t (d_in + s_w)) l_pix / A_pix,
//   l_pix the beam length of the step, spread across the line over the cross-section's profile
//   (a trapezoid, the projection of the square; at least one pixel wide: antialiased) whose
//   weights sum to 1, so that the tubes' profiles tile the screen as the tubes tile the water;
// - one pixel or wider: at the level l where it spans one to two of that level's pixels, each
//   pixel of the level near the step takes the exact in-scatter of its own centre ray through the
//   step's slice of the tube: the ray's chord through that slice (a ray against a slanted prism),
//   sigma_s E_tube times the integral of exp(-sigma_t (d_in + s_w)) along the chord, in closed form.
//   The slices of all tubes partition the water, so every such ray sums its exact in-scatter.
// The singular case, the camera looking along the beams (l_pix without bound as a beam turns into
// the view ray): a wide tube seen end-on gives each ray the chord it really has; a thin one spreads
// its step over at least a pixel; either way one beam adds to a pixel at most the radiance of its
// tube seen end-on, sigma_s p E_tube / sigma_t (PHYSICS.md section 6 with the tube's irradiance).
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

// Mirrors GodrayLinesPush in passes/godrays_lines.cpp.
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

// The level-0 pixel offsets of moving the beam point p by h along x and along z: the projection's
// derivatives at the seen point (the mirror keeps horizontal moves), and for the refracted view the
// crossing's own move, radially dr/dR = n d^2 / b^3 / (c^2 / a^3 + n d^2 / b^3) (Snell's law
// differentiated; c the eye's height, d the point's depth, a and b the view path's lengths in air
// and water) and sideways r / R (the plane of incidence turning about the eye).
void footprint_axes(vec3 p, GodraySight sight, out vec2 along_x, out vec2 along_z) {
    const vec4 clip = frame.view_proj * vec4(sight.seen, 1.0);
    const vec2 ndc = clip.xy / clip.w;
    const vec2 half_size = 0.5 * vec2(image_size) * vec2(1.0, -1.0);
    const vec4 cx = frame.view_proj[0], cz = frame.view_proj[2];
    const vec2 screen_x = half_size * (cx.xy - ndc * cx.w) / clip.w;
    const vec2 screen_z = half_size * (cz.xy - ndc * cz.w) / clip.w;
    vec2 move_x = vec2(1.0, 0.0), move_z = vec2(0.0, 1.0);  // of the seen point, per metre of p
    if (kind == kGodrayViewRefracted) {
        const float n = frame.water.y;
        const float c = view.eye.y - frame.water.x, d = max(frame.water.x - p.y, 0.0);
        const float a = max(sight.surface, 1e-6), b = max(sight.in_water, 1e-6);
        const float water = n * d * d / (b * b * b);
        const float radial = water / (c * c / (a * a * a) + water);
        const vec2 reach = p.xz - view.eye.xz;
        const float r_p = length(reach);
        const float sideways = r_p > 1e-6 ? length(sight.seen.xz - view.eye.xz) / r_p : radial;
        const vec2 u = r_p > 1e-6 ? reach / r_p : vec2(1.0, 0.0);
        move_x = radial * u.x * u + sideways * (vec2(1.0, 0.0) - u.x * u);
        move_z = radial * u.y * u + sideways * (vec2(0.0, 1.0) - u.y * u);
    }
    const float h = beam.direction.w;
    along_x = h * (move_x.x * screen_x + move_x.y * screen_z);
    along_z = h * (move_z.x * screen_x + move_z.y * screen_z);
}

// The tube's cross-section with the column at the sight (the rays of one major coordinate), across
// the line: the widths of the square's two sides there, level-0 pixels.
vec2 cross_section(Line line, GodraySight sight, float tau, out vec2 along_x, out vec2 along_z) {
    const int major = line.major, minor = 1 - major;
    const vec2 d = line.b.xy - line.a.xy;
    const float slope = d[major] != 0.0 ? d[minor] / d[major] : 0.0;
    footprint_axes(beam_point(tau), sight, along_x, along_z);
    return vec2(abs(along_x[minor] - along_x[major] * slope), abs(along_z[minor] - along_z[major] * slope));
}

// The integral up to y of the unit ramp clamp((v + w / 2) / w, 0, 1).
float ramp_integral(float y, float w) {
    if (y <= -0.5 * w) return 0.0;
    return y < 0.5 * w ? (y + 0.5 * w) * (y + 0.5 * w) / (2.0 * w) : y;
}

// The cumulative share up to y of the profile box_a * box_b centred at 0 (a trapezoid of area 1 and
// base a + b; a >= b > 0).
float trapezoid_share(float y, float a, float b) {
    return (ramp_integral(y + 0.5 * a, b) - ramp_integral(y - 0.5 * a, b)) / a;
}

// A thin tube's step at level 0 (screen parameters us < ue): PHYSICS.md section 6's line estimate.
// sinh(y) / y, even, 1 at 0.
float sinhc(float y) {
    return abs(y) < 1e-3 ? 1.0 + y * y / 6.0 : (exp(y) - exp(-y)) / (2.0 * y);
}

// The refracted view's sight is recomputed with the exact surface crossing (the line's is
// interpolated within its piece, which is good enough to place the pixels but would bias s_w and
// A_pix, and so the light).
void thin_step(Line line, float us, float ue, GodraySight sight, float tau, vec2 section, vec2 along_x, vec2 along_z) {
    if (kind == kGodrayViewRefracted) {
        const vec3 p = beam_point(tau);
        const float level = frame.water.x, n = frame.water.y;
        sight = godray_sight(kind, view.eye, p, godray_surface_crossing(view.eye, p, level, n), level, n);
    }
    const float ls = perspective(us, line.a.z, line.b.z), le = perspective(ue, line.a.z, line.b.z);
    const float l_pix = abs(line.tau_b - line.tau_a) * abs(le - ls);
    const vec3 optical = sigma_t * (tau + sight.in_water);
    if (!(l_pix > 0.0) || min(optical.r, min(optical.g, optical.b)) > kNegligible) return;
    // exp(-sigma_t (d_in + s_w)) integrated over the step rather than taken at its middle: the optical
    // depth grows along the beam at sigma_t (1 + dt s_w), dt s_w = t . v (exact where the view path is
    // straight, to first order through the refracting surface), and the mean of an exponential over a
    // span of optical length x is exp(-x_mid) sinh(x / 2) / (x / 2): no midpoint-rule bias.
    vec3 attenuation = exp(-optical);
    const float along_view = 1.0 + dot(beam.direction.xyz, sight.v);
    for (int c = 0; c < 3; ++c) attenuation[c] *= sinhc(0.5 * sigma_t[c] * along_view * l_pix);
    const vec3 value =
        beam.flux.rgb * frame.medium_sigma_s.rgb * (own_phase(sight.v) * l_pix / pixel_area(sight)) * attenuation;
    const int major = line.major, minor = 1 - major;
    const vec2 d = line.b.xy - line.a.xy;
    const vec2 centre = line.a.xy + 0.5 * (us + ue) * d;
    // Across the line the cross-section's profile; along it too where the step is shorter than
    // half a pixel (a beam seen nearly end-on), over the square's own extent.
    const bool end_on = abs(d[major]) * (ue - us) < 0.5;
    const vec2 widths = end_on ? vec2(abs(along_x[minor]), abs(along_z[minor])) : section;
    const float across_a = max(max(widths.x, widths.y), 1e-3), across_b = max(min(widths.x, widths.y), 1e-4);
    const float along_a = max(abs(along_x[major]), max(abs(along_z[major]), 1e-3));
    const float along_b = max(min(abs(along_x[major]), abs(along_z[major])), 1e-4);
    const float reach_across = 0.5 * (across_a + across_b), reach_along = 0.5 * (along_a + along_b);
    const int i0 = end_on ? int(floor(centre[major] - reach_along)) : int(floor(centre[major]));
    const int i1 = end_on ? int(floor(centre[major] + reach_along)) : i0;
    for (int i = i0; i <= i1; ++i) {
        const float y = float(i) - centre[major];
        const float w_major = end_on ? trapezoid_share(y + 1.0, along_a, along_b) - trapezoid_share(y, along_a, along_b) : 1.0;
        for (int j = int(floor(centre[minor] - reach_across)); j <= int(floor(centre[minor] + reach_across)); ++j) {
            ivec2 pixel;
            pixel[major] = i;
            pixel[minor] = j;
            const float x = float(j) - centre[minor];
            const float cover =
                w_major * (trapezoid_share(x + 1.0, across_a, across_b) - trapezoid_share(x, across_a, across_b));
            if (!(cover > 0.0) || any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, image_size))) continue;
            if (visible(pixel, sight)) deposit(0, pixel, value * cover);
        }
    }
}

// The in-water part of the view ray through level-0 pixel coordinates `pixel`, in this view: it
// starts at `origin` after `before` metres of view path in the water and runs along v; `air`: the
// distance from the eye to the surface (refracted, mirrored). False where this view's ray does not
// enter the water.
bool water_ray(vec2 pixel, out vec3 origin, out vec3 v, out float before, out float air, out float cos_surface) {
    const vec3 d = godray_pixel_ray(pixel, vec2(image_size));
    const float level = frame.water.x;
    origin = view.eye;
    v = d;
    before = 0.0;
    air = 0.0;
    cos_surface = abs(d.y);
    if (kind == kGodrayViewDirect) return true;
    if (kind == kGodrayViewMirrored) {
        if (!(d.y > 0.0)) return false;
        before = (level - view.eye.y) / d.y;
        air = before;
        origin = view.eye + before * d;
        v = vec3(d.x, -d.y, d.z);
        return on_water(origin);
    }
    if (!(d.y < 0.0)) return false;
    air = (view.eye.y - level) / -d.y;
    origin = view.eye + air * d;
    return on_water(origin) && refract_direction(d, vec3(0.0, 1.0, 0.0), 1.0 / frame.water.y, v);
}

// log2 of the tube's width in level-0 pixels across the narrower side of the pixel's cone,
// h / (sqrt(Omega) min(cone)): the pyramid level where the tube spans one pixel. The cone's widths
// per unit angle as in godray_sight, where the view path has run `air` metres in the air and
// `in_water` in the water along the ray of unit direction d (a refracted cone at a grazing angle is
// much wider within the plane of incidence than across it, and the tube spans the most pixels across).
float width_level(vec3 d, float air, float in_water, float cos_surface) {
    float cone = in_water;
    if (kind == kGodrayViewRefracted) {
        const float n = frame.water.y, cos_v = max(cos_surface, 1e-6);
        const float sin_w = sqrt(max(0.0, 1.0 - cos_v * cos_v)) / n, cos_w = sqrt(max(0.0, 1.0 - sin_w * sin_w));
        cone = min(air + in_water / n, air * cos_w / cos_v + in_water * cos_v / (n * cos_w));
    }
    return log2(beam.direction.w / max(sqrt(godray_pixel_solid_angle(view, d)) * cone, 1e-30));
}

// The same at a sight.
float sight_level(GodraySight sight) {
    return log2(beam.direction.w / max(sqrt(godray_pixel_solid_angle(view, sight.seen - view.eye)) *
                                           min(sight.cone.x, sight.cone.y), 1e-30));
}

// The share of pyramid level `level` of a point whose width level is lambda: hat functions over
// the levels, a partition of unity (level 0 also takes everything thinner, the top everything wider),
// so that each level holds a smooth band of distances and its bilinear upsampling stays accurate.
float level_weight(int level, float lambda) {
    if ((level == 0 && lambda <= 0.0) || (level == pc.levels - 1 && lambda >= float(level))) return 1.0;
    return max(0.0, 1.0 - abs(lambda - float(level)));
}

// The exact in-scatter of the ray through the level-l pixel `cell` from the slice [tau_s, tau_e]
// of the tube, times the level's share at the chord: the ray's chord through the slanted prism
// (entry + a x + b z + c t, |a|, |b| <= h/2, c in the slice), each bound affine along the ray, and
// the integral of exp(-sigma_t (c + s_w)) over it, whose exponent is affine too.
void chord_deposit(int level, ivec2 cell, float tau_s, float tau_e) {
    vec3 origin, v;
    float before, air, cos_surface;
    const vec2 centre = (vec2(cell) + 0.5) / godray_level_scale(image_size, level);
    if (!water_ray(centre, origin, v, before, air, cos_surface)) return;
    float scene;
    if (!scene_at(ivec2(centre), scene)) return;
    if (kind != kGodrayViewDirect && !sees_water(ivec2(centre), scene)) return;
    const vec3 t = beam.direction.xyz;
    const vec3 rel = origin - beam.entry.xyz;
    // c(s) = c0 + c1 s: the beam parameter of the point of the ray that lies on the slice's plane
    // through it; a and b its horizontal offsets from the beam's axis there.
    const float c0 = rel.y / t.y, c1 = v.y / t.y;
    const vec2 a = vec2(rel.x - c0 * t.x, v.x - c1 * t.x), b = vec2(rel.z - c0 * t.z, v.z - c1 * t.z);
    const float half_h = 0.5 * beam.direction.w;
    float s0 = 0.0, s1 = kind == kGodrayViewDirect ? scene : 1e30;
    for (int k = 0; k < 3; ++k) {
        const vec2 f = k == 0 ? a : k == 1 ? b : vec2(c0 - 0.5 * (tau_s + tau_e), c1);
        const float half_width = k == 2 ? 0.5 * (tau_e - tau_s) : half_h;
        if (f.y == 0.0) {  // a ray along a face: half-open, so that neighbouring tubes never both count it
            if (!(f.x >= -half_width && f.x < half_width)) return;
            continue;
        }
        const float e0 = (-half_width - f.x) / f.y, e1 = (half_width - f.x) / f.y;
        s0 = max(s0, min(e0, e1));
        s1 = min(s1, max(e0, e1));
    }
    if (!(s1 > s0)) return;
    const float length_in = s1 - s0, middle = 0.5 * (s0 + s1);
    const float share = level_weight(level, width_level(godray_pixel_ray(centre, vec2(image_size)),
                                                        kind == kGodrayViewRefracted ? air : 0.0, before + middle,
                                                        cos_surface));
    if (!(share > 0.0)) return;
    const vec3 optical = sigma_t * (c0 + c1 * middle + before + middle);
    if (min(optical.r, min(optical.g, optical.b)) > kNegligible) return;
    vec3 integral;
    for (int c = 0; c < 3; ++c) integral[c] = exp(-optical[c]) * length_in * sinhc(0.5 * sigma_t[c] * (c1 + 1.0) * length_in);
    const vec3 e_tube = beam.flux.rgb / (beam.direction.w * beam.direction.w * -t.y);
    deposit(level, cell, e_tube * frame.medium_sigma_s.rgb * (share * own_phase(v)) * integral);
}

// A wide tube's step: on each level whose share is not zero around the step's width level lambda
// (a step spans less than a third of a level: at most a quarter of the view distance), the level's
// pixels near the step each take their chord through the step's slice [tau_s, tau_e]. The slice
// projects within its square's footprint around the step's screen span, plus a pixel of the level
// for the projection's curvature, within the image (kMaxCells per side at most).
void wide_step(Line line, float us, float ue, float lambda, float tau_s, float tau_e, vec2 along_x, vec2 along_z) {
    const vec2 d = line.b.xy - line.a.xy;
    const vec2 p0 = line.a.xy + us * d, p1 = line.a.xy + ue * d;
    const vec2 square = 0.5 * (abs(along_x) + abs(along_z));
    const int first = clamp(int(floor(lambda - 0.25)), 0, pc.levels - 1);
    const int last = clamp(int(floor(lambda + 0.25)) + 1, 0, pc.levels - 1);
    for (int level = first; level <= last; ++level) {
        const vec2 scale = godray_level_scale(image_size, level);
        const ivec2 size = godray_level_size(image_size, level);
        const ivec2 lo = max(ivec2(floor((min(p0, p1) - square) * scale)) - 1, ivec2(0));
        const ivec2 hi = min(min(ivec2(floor((max(p0, p1) + square) * scale)) + 1, size - 1), lo + kMaxCells - 1);
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) chord_deposit(level, ivec2(x, y), tau_s, tau_e);
        }
    }
}

// A slice of a tube that straddles the eye's plane (its axis behind the near plane, its body partly
// in front): it covers the image from every side, so every pixel of the coarsest level takes its
// chord through it.
void straddling_slice(float tau_s, float tau_e) {
    if (!(tau_e > tau_s)) return;
    const int top = pc.levels - 1;
    const ivec2 size = godray_level_size(image_size, top);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) chord_deposit(top, ivec2(x, y), tau_s, tau_e);
    }
}

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
    // The view ray starts at the eye (PHYSICS.md section 6), not at the near plane: beams are clipped
    // just past walk_start() (rounding keeps a clipped end in front of it).
    const float near = 1.001 * walk_start();

    if (kind != kGodrayViewRefracted) {
        // The seen point is affine in tau, and so is its clip w: clip to the near plane exactly.
        const float w0 = clip_w(seen_point(beam_point(0.0))), w1 = clip_w(seen_point(beam_point(len)));
        // Where the axis passes behind the eye, the tube around it still reaches in front for as
        // long as w stays above minus its half extent along the view axis.
        const vec3 seen_t = seen_point(beam_point(1.0)) - seen_point(beam_point(0.0));
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
