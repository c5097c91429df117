#version 450
#extension GL_GOOGLE_include_directive : require
// A Lambertian receiver (the floor, or a mesh: its vertex shader hands over the normal
// and the albedo): lit by the sun and the sky above the water, by the sun through the
// water (the caustic map, or the flat-surface stand-in) and the transmitted skylight
// below it. Seen from a camera in the water, the view path attenuates and scatters. In a
// scene view (passes/scene_views/scene_view.hpp) it keeps one side of the water plane and writes what
// leaves the receiver with its distance from the view's eye; the water adds the path.
// Variants (shaders/CMakeLists.txt): VKWATER_PER_PIXEL_MEDIUM (the stencil split's mask),
// VKWATER_CAUSTICS (the caustic map), VKWATER_MESH_BASE_COLOR (a mesh's albedo times its base
// colour texture and its vertex colour, docs/model.md section 4), VKWATER_CAUSTIC_LAYER (a
// second output: the sun's irradiance on the receiver under the water, 0 above it;
// passes/caustics/caustic_layer.hpp) and VKWATER_SCENE_VIEW_BEHIND (a view's second layer: only
// what lies behind the first layer's surface, facing the eye).
#include "common/medium.glsl"
#include "receivers/floor_albedo.glsl"
#include "receivers/receiver_push.glsl"
#include "scene_views/scene_view.glsl"
#include "water/camera_medium.glsl"
#include "water/underwater_light.glsl"

layout(set = 0, binding = 1, std430) readonly buffer Optics { SceneOptics optics; };

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec3 in_albedo;
#ifdef VKWATER_MESH_BASE_COLOR
// Linear texels (decoded from sRGB on the CPU: passes/receivers/texture_mips.hpp); 1 x 1 white for
// untextured parts.
layout(set = 0, binding = 8) uniform sampler2D base_color_texture;
layout(location = 3) in vec2 in_uv;
layout(location = 4) in vec4 in_color;
#endif
#ifdef VKWATER_SCENE_VIEW_BEHIND
// The same view's first layer, drawn before at the same size: texel for texel under this pass's
// fragments.
layout(set = 0, binding = 9) uniform sampler2D first_layer;
#endif
layout(location = 0) out vec4 out_radiance;
#ifdef VKWATER_CAUSTIC_LAYER
layout(location = 1) out vec4 out_caustic;
#endif

void main() {
    vec3 p = in_world_position;
    if (in_scene_view() && !kept_by_scene_view(p)) discard;
    vec3 eye = in_scene_view() ? scene_view_eye(scene_view_mirrored()) : frame.camera_position.xyz;
    vec3 normal = normalize(in_normal);
#ifdef VKWATER_SCENE_VIEW_BEHIND
    // Depth peeling: what the first layer shows, and anything within its thickness of it, is not
    // in the second. A face turned away from the eye (the back of the receiver the first layer
    // shows) is left out too, so that the layer shows what lies beyond that receiver. The meshes'
    // normals point out of them (a terrain's up).
    const float first = texelFetch(first_layer, ivec2(gl_FragCoord.xy), 0).a;
    if (first > 0.0 && distance(eye, p) <= first * (1.0 + SCENE_VIEW_THICKNESS)) discard;
    if (dot(normal, eye - p) < 0.0) discard;
#endif
    // Lambertian surfaces are lit on the side the eye sees.
    if (dot(normal, eye - p) < 0.0) normal = -normal;
    // floor.vert's mark for a tiled floor (receivers/floor_albedo.glsl).
    vec3 albedo = in_albedo.r < 0.0 ? floor_albedo_at(p.xz) : in_albedo;
#ifdef VKWATER_MESH_BASE_COLOR
    vec4 base_color = texture(base_color_texture, in_uv) * in_color;
    // A cutout (glTF alphaMode MASK) is not there where its alpha falls below the threshold.
    if (base_color.a * receiver.material.x < receiver.material.y) discard;
    albedo *= base_color.rgb;
#endif
    vec3 radiance = lambert_radiance(albedo, receiver_irradiance(p, normal, optics));
#ifdef VKWATER_CAUSTIC_LAYER
    out_caustic = vec4(caustic_layer_value(p, normal, optics), 1.0);
#endif
    if (in_scene_view()) {
        // What leaves the receiver, and how far it is: the water's shader adds the path.
        out_radiance = vec4(radiance, distance(eye, p));
        return;
    }
    if (camera_in_water()) {
        vec3 eye = frame.camera_position.xyz;
        radiance = water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb, frame.medium_sigma_s.w,
                                       max(0.0, frame.water.x - eye.y), distance(eye, p), normalize(p - eye),
                                       optics.refracted_sun.xyz, optics.e_perp0.rgb, radiance);
    }
    out_radiance = vec4(radiance, 1.0);
}
