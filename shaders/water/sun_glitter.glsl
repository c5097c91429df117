// The sun's glitter (docs/model.md section 1, "Sun glitter"; Bruneton, Neyret and Holzschuch 2010):
// the wave components finer than a pixel's footprint on the surface cannot be drawn, so their
// slopes become a distribution, and the sun's mirror image in them a lobe (water/glitter_lobe.glsl).
// The slopes of the unresolved part are Gaussian with the covariance S_u of
// engine/water/unresolved_slopes.hpp (a table over the pixel's cutoff wavenumber, in the frame
// constants). The pixel's own normal is one sample of the whole slope, resolved part and
// unresolved part together; for independent Gaussian parts, given that sample z_c, the resolved
// slope is expected at (1 - r) z_c with a variance of (1 - r) S_u left, r = tr S_u / tr S the
// unresolved share. So the facets' slopes are taken as Gaussian about (1 - r) z_c with covariance
// (2 - r) S_u, plus the sun disk's own spread: the pixel's normal where every wave is resolved, the
// level's with the whole covariance where none is.
#ifndef VKWATER_SUN_GLITTER_GLSL
#define VKWATER_SUN_GLITTER_GLSL

#include "common/frame_constants.glsl"
#include "water/glitter_lobe.glsl"

// The covariance (S_xx, S_xz, S_zz) of the slopes finer than cutoff wavenumber `cutoff` (rad/m),
// interpolated in log(cutoff) as engine/water/unresolved_slopes.cpp does.
vec3 unresolved_slope_covariance(float cutoff) {
    if (frame.glitter.z < 0.5) return vec3(0.0);
    const float x = (log(cutoff) - frame.glitter.x) / frame.glitter.y;
    if (x <= 0.0) return frame.unresolved_slopes[0].xyz;
    if (x >= 15.0) return frame.unresolved_slopes[15].xyz;
    const int i = int(x);
    return mix(frame.unresolved_slopes[i].xyz, frame.unresolved_slopes[i + 1].xyz, x - float(i));
}

// The slopes a pixel cannot resolve where it sees the surface point p: its footprint there, the
// square root of the area its screen derivatives span (the ray differentials across one pixel),
// sets its Nyquist wavenumber pi / side. Call in uniform control flow.
vec3 pixel_unresolved_slopes(vec3 p) {
    const float side = sqrt(length(cross(dFdx(p), dFdy(p))));
    return unresolved_slope_covariance(GLITTER_PI / max(side, 1e-6));
}

// The sun's disk as a spread of slopes: a Gaussian lobe of reflected directions with the disk's solid
// angle Omega has a per-axis variance Omega / (2 pi), and a slope tilts the reflected ray by twice
// itself, so Omega / (8 pi) in slope.
float sun_disk_slope_variance() { return frame.sun_disk.y / (8.0 * GLITTER_PI); }

// The same seen from the water through the level surface of index n. A source direction that turns by
// an angle b turns the refracted ray by k b, with k = cos(theta_i) / (n cos(theta_t)) the derivative
// of Snell's law; a facet that tilts by a turns it by (1 - k) a. So the disk's spread is that of a
// slope spread k / (1 - k) times its own: Omega / (2 pi) (k / (1 - k))^2 in slope (in the plane of
// incidence; taken for both axes). The sun overhead and n = 1.333 give 9 Omega / (2 pi).
float refracted_sun_disk_slope_variance(float n) {
    const float cos_i = max(-frame.sun_direction.y, 0.0);
    const float cos_t = sqrt(max(0.0, 1.0 - (1.0 - cos_i * cos_i) / (n * n)));
    const float k = cos_i / (n * cos_t);
    return frame.sun_disk.y / (2.0 * GLITTER_PI) * (k * k) / ((1.0 - k) * (1.0 - k));
}

// The lobe takes over from the sun's disk in reflections (`refracted`: in the refracted view of
// the sky from the water, of index n) where the unresolved slopes spread the sun's image more than
// its own disk does.
bool glitter_replaces_disk(vec3 covariance, bool refracted, float n) {
    const float disk = refracted ? refracted_sun_disk_slope_variance(n) : sun_disk_slope_variance();
    return 0.5 * (covariance.x + covariance.z) > disk;
}

// The mean and covariance of the facets' slopes under a pixel whose own normal is `normal`, with
// the sun's disk as a further spread of `disk` per axis (the header above).
void glitter_slopes(vec3 normal, vec3 covariance, float disk, out vec2 mean_slope, out vec3 lobe_covariance) {
    const float share = clamp((covariance.x + covariance.z) / max(frame.glitter.w, 1e-30), 0.0, 1.0);
    mean_slope = (1.0 - share) * (-normal.xz / normal.y);
    lobe_covariance = (2.0 - share) * covariance + vec3(disk, 0.0, disk);
}

// The sun's radiance reflected toward `to_eye` around the pixel's `normal` with the unresolved
// slopes' `covariance`; `reflectance` gives F at a cosine as the surface's Fresnel form does.
vec3 sun_glitter_radiance(vec3 to_eye, vec3 normal, vec3 covariance, float reflectance) {
    if (frame.sun_direction.w < 0.5 || !(normal.y > 0.0)) return vec3(0.0);
    const vec3 to_sun = -frame.sun_direction.xyz;
    vec2 mean_slope;
    vec3 lobe_covariance;
    glitter_slopes(normal, covariance, sun_disk_slope_variance(), mean_slope, lobe_covariance);
    return frame.sun_irradiance.rgb * glitter_lobe(to_eye, to_sun, mean_slope, lobe_covariance, reflectance) *
           glitter_visibility(to_eye, to_sun, lobe_covariance);
}

// The sun's radiance transmitted toward an eye in the water (`to_eye` points down) around the
// pixel's `normal`, for water of index n; `transmittance` gives T at a cosine as the surface's
// Fresnel form does. The visibility takes the eye's direction reversed, pointing up: a Gaussian
// heightfield of zero-mean slopes seen from below hides its facets as it does from above.
vec3 refracted_sun_glitter_radiance(vec3 to_eye, vec3 normal, vec3 covariance, float n, float transmittance) {
    if (frame.sun_direction.w < 0.5 || !(normal.y > 0.0)) return vec3(0.0);
    const vec3 to_sun = -frame.sun_direction.xyz;
    vec2 mean_slope;
    vec3 lobe_covariance;
    glitter_slopes(normal, covariance, refracted_sun_disk_slope_variance(n), mean_slope, lobe_covariance);
    return frame.sun_irradiance.rgb *
           glitter_transmission_lobe(to_eye, to_sun, n, mean_slope, lobe_covariance, transmittance) *
           glitter_visibility(-to_eye, to_sun, lobe_covariance);
}

#endif
