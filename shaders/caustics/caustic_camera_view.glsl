// The camera's water-less view of the receivers as the camera-space caustics see it
// (passes/caustics/caustics_camera_splats.hpp): the scene view's guard-banded projection
// (scene_views/scene_view.glsl, not mirrored), in pixel coordinates of a target of `size` pixels
// (pixel (i, j) covers [i, i + 1) x [j, j + 1), row 0 at the top). The ray through pixel
// coordinate x is r(x) = d0 + x.x dx + x.y dy (not normalised; affine in x because the far plane
// is a plane), and the area of the receiver plane (point c, unit normal N) that pixel (i, j) sees
// is the central projection of the pixel onto the plane,
//   A = h^2 |(dx x dy) . r| / |r . N|^3,   h = (c - eye) . N,   r the ray through its centre,
// which for the point at distance s along r is A = s^2 Omega / |v . N| with v = r / |r| and
// Omega = |(dx x dy) . r| / |r|^3 the pixel's solid angle: the splats weigh their taps by it and
// the resolve divides by it, so E = Phi_pixel |v . N| / (s^2 Omega) holds pixel by pixel.
#ifndef VKWATER_CAUSTIC_CAMERA_VIEW_GLSL
#define VKWATER_CAUSTIC_CAMERA_VIEW_GLSL

#include "scene_views/scene_view.glsl"

struct CameraRays {
    vec3 eye;
    vec3 d0, dx, dy;  // r(x) = d0 + x.x dx + x.y dy
};

// The point of the far plane (depth 0, reversed-Z) at texture coordinate uv of the view: far from
// the eye, so that subtracting the eye loses no bits (common/camera_ray.glsl).
vec3 camera_far_point(vec2 uv) {
    const vec2 ndc = vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y) * SCENE_VIEW_GUARD;
    const vec4 q = frame.inv_view_proj * vec4(ndc, 0.0, 1.0);
    return q.xyz / q.w;
}

CameraRays camera_rays(vec2 size) {
    CameraRays rays;
    rays.eye = frame.camera_position.xyz;
    // Three corners of the view on the far plane, whose points are affine in the pixel coordinate.
    const vec3 o = camera_far_point(vec2(0.0)) - rays.eye;
    const vec3 corner_x = camera_far_point(vec2(1.0, 0.0)) - rays.eye;
    const vec3 corner_y = camera_far_point(vec2(0.0, 1.0)) - rays.eye;
    rays.d0 = o;
    rays.dx = (corner_x - o) / size.x;
    rays.dy = (corner_y - o) / size.y;
    return rays;
}

vec3 camera_ray(CameraRays rays, vec2 x) { return rays.d0 + x.x * rays.dx + x.y * rays.dy; }

// The pixel's solid angle, sr, for the ray through its centre.
float camera_pixel_solid_angle(CameraRays rays, vec3 r) {
    const float len = length(r);
    return abs(dot(cross(rays.dx, rays.dy), r)) / (len * len * len);
}

// The pixel coordinate of world point p; false behind the eye or outside the view.
bool camera_pixel_coord(vec3 p, vec2 size, out vec2 x) {
    vec2 uv;
    const bool inside = scene_view_uv(p, false, uv);
    x = uv * size;
    return inside;
}

// The splats' flux pyramid (passes/caustics/caustics_camera_splats.hpp): level L has pixels 2^L x 2^L view
// pixels wide (ceil(W / 2^L) x ceil(H / 2^L) of them), stored level after level, three uint64 per
// pixel. A splat that takes more than kMaxSplatTaps pixels of one level goes to the first level
// where it fits (de la Fuente 2011's point size regulation, done by level so that a splat never costs more
// than that many taps); the resolve adds the levels up.
const int kCameraCausticLevels = 4;
const float kMaxSplatTaps = 256.0;  // pixels of the splat's level

uvec2 camera_level_size(uvec2 size, int level) { return (size + (1u << level) - 1u) >> level; }

// The first pixel of level L in the flux buffer.
uint camera_level_offset(uvec2 size, int level) {
    uint offset = 0u;
    for (int k = 0; k < level; ++k) {
        const uvec2 s = camera_level_size(size, k);
        offset += s.x * s.y;
    }
    return offset;
}

// The view pixel that stands for pixel t of level L in depth and plane tests: the one under its centre.
ivec2 camera_level_texel(ivec2 t, int level, ivec2 size) {
    return min(ivec2((vec2(t) + 0.5) * float(1 << level)), size - 1);
}

// The area of the plane (point c, unit normal N, h = (c - eye) . N) that pixel t of level L sees.
float camera_level_pixel_area(CameraRays rays, ivec2 t, int level, vec3 normal, float h) {
    const float scale = float(1 << level);
    const vec3 r = camera_ray(rays, (vec2(t) + 0.5) * scale);
    const float rn = dot(r, normal);
    if (!(rn * h > 0.0)) return 0.0;  // the ray meets the plane behind the eye
    return scale * scale * h * h * abs(dot(cross(rays.dx, rays.dy), r)) / abs(rn * rn * rn);
}

// How far a point may lie from the plane of the receiver a pixel shows and still be on it, as a
// fraction of the receiver's distance from the eye: the depth test of the camera-space caustics.
// 0.5 % passes the fp32 rounding of the view's distances (1e-7 relative) and a curved receiver's
// departure from its tangent plane across a few pixels, and separates surfaces 5 cm apart at 10 m.
const float kReceiverPlaneTolerance = 0.005;

// Whether the receiver that pixel `texel` shows (its receivers-view texel: normal, distance)
// lies on the plane through `point` with unit normal `normal`.
bool receiver_on_plane(CameraRays rays, ivec2 texel, vec4 receiver, vec3 point, vec3 normal) {
    if (!(receiver.w > 0.0)) return false;
    const vec3 seen = rays.eye + receiver.w * normalize(camera_ray(rays, vec2(texel) + 0.5));
    return abs(dot(seen - point, normal)) <= kReceiverPlaneTolerance * receiver.w;
}

#endif
