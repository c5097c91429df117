// The camera-space caustic irradiance a receiver point reads: the point is
// projected into the receivers' water-less view (caustic_camera_view.glsl; for a refracted view
// ray, the projection of where the ray meets the receiver, not of where the camera sees it through
// the water), and the resolved irradiance of passes/caustics/caustics_camera_splats.hpp is read bilinearly
// over the four nearest pixels that show the point's own surface (the same plane test as the
// splats' depth test), their weights renormalised. False where none does: the point is hidden from
// the camera (behind an object, outside the view), so no splat reached it; the caller then lights
// it with the flat-surface stand-in.
//
// Bindings 4 and 5 of set 0 (passes/receivers/lighting_inputs.hpp): the receivers' view and the irradiance.
#ifndef VKWATER_CAUSTIC_CAMERA_LOOKUP_GLSL
#define VKWATER_CAUSTIC_CAMERA_LOOKUP_GLSL

#include "caustics/caustic_camera_view.glsl"

layout(set = 0, binding = 4) uniform sampler2D caustic_receivers;
layout(set = 0, binding = 5) uniform sampler2D camera_caustics;

bool camera_caustic_irradiance(vec3 p, out vec3 irradiance) {
    irradiance = vec3(0.0);
    const ivec2 size = textureSize(camera_caustics, 0);
    vec2 x;
    if (!camera_pixel_coord(p, vec2(size), x)) return false;
    const CameraRays rays = camera_rays(vec2(size));
    const vec2 c = x - 0.5;
    const vec2 base = floor(c);
    const vec2 f = c - base;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int k = 0; k < 4; ++k) {
        const ivec2 step = ivec2(k & 1, k >> 1);
        const ivec2 texel = ivec2(base) + step;
        if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) continue;
        const vec4 receiver = texelFetch(caustic_receivers, texel, 0);
        if (!receiver_on_plane(rays, texel, receiver, p, receiver.xyz)) continue;
        // At least 1e-4: a valid pixel at bilinear weight 0 still answers when it is the only one.
        const float w = max((step.x == 1 ? f.x : 1.0 - f.x) * (step.y == 1 ? f.y : 1.0 - f.y), 1e-4);
        sum += w * texelFetch(camera_caustics, texel, 0).rgb;
        weights += w;
    }
    if (!(weights > 0.0)) return false;
    irradiance = sum / weights;
    return true;
}

#endif
