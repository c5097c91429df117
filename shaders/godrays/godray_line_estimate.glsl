// The line estimate of thin beams (shaders/godrays/godray_lines.comp): the tube's projected
// cross-section with a screen column, and one step's deposit, l_pix / A_pix over that profile.
// Part of godray_lines.comp, included after its bindings, globals and common helpers (the beam, the
// view, the Line, deposit, visible, sight_at, pixel_area); not a standalone include.
#ifndef VKWATER_GODRAY_LINE_ESTIMATE_GLSL
#define VKWATER_GODRAY_LINE_ESTIMATE_GLSL

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

// sinh(y) / y, even, 1 at 0.
float sinhc(float y) {
    return abs(y) < 1e-3 ? 1.0 + y * y / 6.0 : (exp(y) - exp(-y)) / (2.0 * y);
}

// A thin tube's step at level 0 (screen parameters us < ue): docs/model.md section 6's line estimate.
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

#endif
