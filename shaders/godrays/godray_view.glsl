// The camera as the godray passes see it, at their own resolution (the output's or half of it):
// world points to continuous pixel coordinates, pixel rays and their solid angles, the scene's
// distance behind a pixel, and the three ways a point under the water is seen (docs/model.md
// section 6): directly from a camera in the water, mirrored in the surface from below, and
// refracted through the FLAT surface at the mean level from a camera above it.
#ifndef VKWATER_GODRAY_VIEW_GLSL
#define VKWATER_GODRAY_VIEW_GLSL

#include "common/camera_ray.glsl"
#include "common/frame_constants.glsl"
#include "common/fresnel.glsl"

// The distance stored for pixels whose ray meets nothing (the clear depth): far beyond any
// scene, finite so that the frame graph's finite check stays quiet.
const float kGodrayNoHit = 1e20;

// The three views of a point under the water.
const uint kGodrayViewDirect = 0u;     // camera in the water, straight to the point
const uint kGodrayViewMirrored = 1u;   // camera in the water, via the surface's reflection
const uint kGodrayViewRefracted = 2u;  // camera in the air, through the flat surface

struct GodrayView {
    vec3 eye;
    vec3 forward;      // unit view axis
    vec2 size;         // the godray resolution, pixels
    float pixel_area;  // one pixel's area on the image plane at unit distance along the axis
};

vec3 godray_unproject(vec2 ndc, float depth) {
    const vec4 p = frame.inv_view_proj * vec4(ndc, depth, 1.0);
    return p.xyz / p.w;
}

GodrayView godray_view(vec2 size) {
    const vec3 eye = frame.camera_position.xyz;
    // On the far plane: near-plane points, centimetres from the eye, lose bits to the subtraction
    // (common/camera_ray.glsl).
    const vec3 centre = godray_unproject(vec2(0.0), 0.0);  // the far plane's centre
    const float axis = distance(centre, eye);
    const float tan_x = distance(godray_unproject(vec2(1.0, 0.0), 0.0), centre) / axis;
    const float tan_y = distance(godray_unproject(vec2(0.0, 1.0), 0.0), centre) / axis;
    return GodrayView(eye, (centre - eye) / axis, size, (2.0 * tan_x / size.x) * (2.0 * tan_y / size.y));
}

// xy: continuous pixel coordinates (centres at integer + 0.5, row 0 at the top); z: clip w, the
// distance along the view axis (the point is in front of the camera where it exceeds the near plane).
vec3 godray_project(GodrayView view, vec3 p) {
    const vec4 clip = frame.view_proj * vec4(p, 1.0);
    const vec2 ndc = clip.xy / clip.w;
    return vec3(0.5 * (ndc.x + 1.0) * view.size.x, 0.5 * (1.0 - ndc.y) * view.size.y, clip.w);
}

// The unit ray through continuous pixel coordinates `pixel` at a resolution of `size`.
vec3 godray_pixel_ray(vec2 pixel, vec2 size) {
    return camera_ray_through_ndc(vec2(2.0 * pixel.x / size.x - 1.0, 1.0 - 2.0 * pixel.y / size.y));
}

// Solid angle of the pixel whose ray is `direction`: its image-plane area times cos^3 of the angle
// off the axis (exact to second order in the pixel's size).
float godray_pixel_solid_angle(GodrayView view, vec3 direction) {
    const float c = dot(normalize(direction), view.forward);
    return view.pixel_area * c * c * c;
}

// How far the ray of the pixel at continuous coordinates `pixel` (of a `size` image) travels to the
// scene surface of reversed-Z depth `depth`; kGodrayNoHit where the depth is the clear value 0.
float godray_scene_distance(vec2 pixel, vec2 size, float depth) {
    if (!(depth > 0.0)) return kGodrayNoHit;
    const vec2 ndc = vec2(2.0 * pixel.x / size.x - 1.0, 1.0 - 2.0 * pixel.y / size.y);
    return distance(godray_unproject(ndc, depth), frame.camera_position.xyz);
}

// Where the view ray from `eye` above the flat surface y = level to `p` below it crosses the
// surface: Snell's law sin(theta_v) = n sin(theta_w) for the horizontal distance r of the crossing
// from the eye. The residual f(r) = sin(theta_v) - n sin(theta_w) increases on [0, R] from
// f(0) <= 0 to f(R) >= 0, so Newton's method kept inside a shrinking bracket (bisection when a
// step leaves it) converges from the paraxial start r = R n h / (d + n h).
vec3 godray_surface_crossing(vec3 eye, vec3 p, float level, float n) {
    const float h = eye.y - level, d = max(level - p.y, 0.0);
    const vec2 horizontal = p.xz - eye.xz;
    const float reach = length(horizontal);
    if (!(reach > 0.0) || !(h > 0.0)) return vec3(eye.x, level, eye.z);
    float lo = 0.0, hi = reach;
    float r = reach * n * h / (d + n * h);
    for (int k = 0; k < 24; ++k) {
        const float a = sqrt(r * r + h * h), b = sqrt((reach - r) * (reach - r) + d * d);
        const float f = r / a - n * (reach - r) / max(b, 1e-30);
        if (f > 0.0) hi = r; else lo = r;
        const float slope = h * h / (a * a * a) + n * d * d / max(b * b * b, 1e-30);
        float next = r - f / max(slope, 1e-30);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (abs(next - r) <= 1e-7 * reach) {
            r = next;
            break;
        }
        r = next;
    }
    return vec3(eye.x + horizontal.x * (r / reach), level, eye.z + horizontal.y * (r / reach));
}

// The sun's direction under the flat surface (the beams' direction under flat water).
vec3 godray_flat_refracted_sun() {
    vec3 t = vec3(0.0, -1.0, 0.0);
    refract_direction(frame.sun_direction.xyz, vec3(0.0, 1.0, 0.0), 1.0 / frame.water.y, t);  // never TIR from the air
    return t;
}

// For a pixel whose camera ray is d, in the view `kind`: the view direction in the water and the
// surface's weight (1 directly; R for the mirrored view, where the ray meets the surface from
// below; T / n^2 for the refracted view, 0 for rays that do not go down into the water).
void godray_pixel_view(uint kind, vec3 d, out vec3 v, out float weight) {
    const float n = frame.water.y;
    v = d;
    weight = 1.0;
    if (kind == kGodrayViewMirrored) {
        v = vec3(d.x, -abs(d.y), d.z);
        weight = d.y > 0.0 ? fresnel_exact(d.y, n, 1.0).R : 0.0;
    } else if (kind == kGodrayViewRefracted) {
        weight = d.y < 0.0 ? fresnel_exact(-d.y, 1.0, n).T / (n * n) : 0.0;
        if (!(d.y < 0.0) || !refract_direction(d, vec3(0.0, 1.0, 0.0), 1.0 / n, v)) v = vec3(0.0, -1.0, 0.0);
    }
}

// How the pixel that sees a beam point p sees it (docs/model.md section 6).
struct GodraySight {
    vec3 seen;         // the point whose projection is the pixel: p, its mirror image, or its surface crossing
    vec3 v;            // unit direction of the view ray at p, away from the camera (cos(alpha) = dot(t, -v))
    float in_water;    // s_w: the view path in water between p and the camera (or the crossing), m
    float surface;     // distance from the eye to where the view ray meets the surface (mirrored, refracted)
    vec2 cone;         // the pixel cone's widths at p per unit angle: A_pix = Omega cone.x cone.y, m
    float weight;      // T(theta_v) / n^2 from the air, R at the surface for the mirrored view, 1 directly
    float cos_surface; // cosine of the view ray at the surface (mirrored, refracted), for depth margins
};

GodraySight godray_sight(uint kind, vec3 eye, vec3 p, vec3 crossing, float level, float n) {
    GodraySight sight;
    if (kind == kGodrayViewRefracted) {
        // A_pix = Omega (s_a + s_w / n) (s_a cos_w / cos_v + s_w cos_v / (n cos_w)): across and
        // within the plane of refraction.
        const float s_a = distance(crossing, eye), s_w = distance(p, crossing);
        const float cos_v = max((eye.y - level) / max(s_a, 1e-30), 1e-6);
        const float sin_w = sqrt(max(0.0, 1.0 - cos_v * cos_v)) / n;
        const float cos_w = sqrt(max(0.0, 1.0 - sin_w * sin_w));
        const vec2 along = crossing.xz - eye.xz;
        const float reach = length(along);
        const vec2 u = reach > 0.0 ? along / reach : vec2(0.0);
        sight.seen = crossing;
        sight.v = vec3(u.x * sin_w, -cos_w, u.y * sin_w);
        sight.in_water = s_w;
        sight.surface = s_a;
        sight.cone = vec2(s_a + s_w / n, s_a * cos_w / cos_v + s_w * cos_v / (n * cos_w));
        sight.weight = fresnel_exact(cos_v, 1.0, n).T / (n * n);
        sight.cos_surface = cos_v;
        return sight;
    }
    // Directly, or unfolded about the flat surface: a straight path of length s_w, A_pix = Omega s_w^2.
    const bool mirrored = kind == kGodrayViewMirrored;
    sight.seen = mirrored ? vec3(p.x, 2.0 * level - p.y, p.z) : p;
    sight.in_water = distance(sight.seen, eye);
    const vec3 u = (sight.seen - eye) / max(sight.in_water, 1e-30);
    sight.v = mirrored ? vec3(u.x, -u.y, u.z) : u;
    sight.surface = mirrored ? (level - eye.y) / max(u.y, 1e-30) : 0.0;
    sight.cone = vec2(sight.in_water);
    sight.weight = mirrored ? fresnel_exact(u.y, n, 1.0).R : 1.0;
    sight.cos_surface = mirrored ? u.y : 1.0;
    return sight;
}

#endif
