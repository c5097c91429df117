#version 450
#extension GL_GOOGLE_include_directive : require
// The floor plane y = floor_plane.x, a square of half extent floor_plane.y, as two
// triangles generated from the vertex index; seen from the camera or, in a view with the scene
// views' guard band (the camera-space caustics' receivers), as that view sees it.
#include "receivers/receiver_push.glsl"
#include "scene_views/scene_view.glsl"

layout(location = 0) out vec3 out_world_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec3 out_albedo;

void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 xz = corners[gl_VertexIndex] * frame.floor_plane.y;
    vec3 world = vec3(xz.x, frame.floor_plane.x, xz.y);
    out_world_position = world;
    out_normal = vec3(0.0, 1.0, 0.0);
    // A tiled floor's albedo varies within a triangle: -1 asks receiver.frag to evaluate it per
    // fragment (an albedo is never negative otherwise). mix() and step(), not a ?: select: with the
    // select, lavapipe's memory grew by about 125 KiB per frame in the viewer (the soak test,
    // tests/soak), with or without validation; with mix() it stays flat.
    out_albedo = mix(frame.floor_albedo.rgb, vec3(-1.0), step(1e-30, frame.floor_plane.z));
    gl_Position = in_scene_view() ? scene_view_clip(world, scene_view_mirrored()) : frame.view_proj * vec4(world, 1.0);
}
