// The scene views (passes/scene_views/scene_view.hpp): receiver meshes seen from the camera or from
// its mirror image in the mean water plane, with the field of view widened by a guard
// band so that perturbed lookups stay inside (Optical Phenomena c. 2008 found 50% enough). Each texel
// holds the radiance leaving the receiver toward the view's eye (rgb) and its distance
// from that eye (a; 0 where the view sees no receiver). Shared by the views' shaders,
// which draw them, and the water's, which look them up (water/scene_lookup.glsl).
#ifndef VKWATER_SCENE_VIEW_GLSL
#define VKWATER_SCENE_VIEW_GLSL

#include "common/camera_ray.glsl"
#include "common/frame_constants.glsl"

// Tangent of the view's half field of view over the camera's: the guard band.
const float SCENE_VIEW_GUARD = 1.5;

// The thickness given to what a view shows, as a fraction of its distance from the eye:
// neighbouring texels of a surface seen at a slant differ by about this much. A lookup's ray
// point this far behind a texel's distance has passed behind that surface; the second layer
// keeps only what lies further than this behind the first.
const float SCENE_VIEW_THICKNESS = 0.05;

vec3 mirrored_in_water_plane(vec3 p) { return vec3(p.x, 2.0 * frame.water.x - p.y, p.z); }

// The view's clip-space position of world point p. A mirrored view sees the mirror image
// of the world from the real camera, which is the world seen from the mirrored camera.
vec4 scene_view_clip(vec3 p, bool mirrored) {
    vec4 clip = frame.view_proj * vec4(mirrored ? mirrored_in_water_plane(p) : p, 1.0);
    clip.xy /= SCENE_VIEW_GUARD;
    return clip;
}

// The eye the view's distances are measured from.
vec3 scene_view_eye(bool mirrored) {
    return mirrored ? mirrored_in_water_plane(frame.camera_position.xyz) : frame.camera_position.xyz;
}

// Texture coordinates of p in the view (row 0 at the top: the frame graph flips the
// viewport); false when p is behind the eye or outside the view.
bool scene_view_uv(vec3 p, bool mirrored, out vec2 uv) {
    vec4 clip = scene_view_clip(p, mirrored);
    uv = vec2(0.0);
    if (clip.w <= 0.0) return false;
    vec2 ndc = clip.xy / clip.w;
    uv = vec2(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y);
    return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// The world point a view texel shows at distance a from the view's eye.
vec3 scene_view_point(vec2 uv, float a, bool mirrored) {
    vec2 ndc = vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y) * SCENE_VIEW_GUARD;
    vec3 p = frame.camera_position.xyz + a * camera_ray_through_ndc(ndc);
    return mirrored ? mirrored_in_water_plane(p) : p;
}

#endif
