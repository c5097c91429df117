// The chords of wide beams (shaders/godrays/godray_lines.comp): each pixel's centre ray against a
// slice of a tube, its exact in-scatter on the pyramid levels of the tube's width. Part of
// godray_lines.comp, included after its bindings, globals, common helpers and
// godray_line_estimate.glsl (sinhc); not a standalone include.
#ifndef VKWATER_GODRAY_CHORDS_GLSL
#define VKWATER_GODRAY_CHORDS_GLSL

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

#endif
