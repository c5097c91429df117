#version 450
#extension GL_GOOGLE_include_directive : require
// The closed water volume for the stencil split (passes/water/water_volume_stencil.hpp), pulled
// from the surface grid (passes/water/water_surface.hpp) by vertex index, with no vertex buffer:
//   [0, 6 R^2)             the surface: R x R cells, two triangles each (as water_surface.vert);
//   [6 R^2, 6 R^2 + 24 R)  the walls: one quad per rim edge, from the displaced rim straight
//                          down to y = bottom_y;
//   the rest, 12 R         the bottom: a fan of 4 R triangles from (0, bottom_y, 0) to the
//                          walls' lower edges (star-shaped about the grid's centre, which the
//                          grid is centred on; folded surfaces are refused upstream).
// Every shared edge is made of the same fp32 points, transformed by the one expression at
// the end of main(), so the mesh is watertight on screen and each pixel centre is covered
// by exactly one triangle per boundary crossing (the rasteriser's top-left rule).
#include "common/frame_constants.glsl"
#include "water/water_vertex.glsl"

layout(set = 0, binding = 2, std430) readonly buffer Surface { WaterVertex vertices[]; } surface;
layout(push_constant) uniform Params { uint resolution; float bottom_y; } params;

vec3 surface_point(uvec2 ij) { return surface.vertices[ij.y * (params.resolution + 1u) + ij.x].position.xyz; }

// Grid index of rim vertex m, walking the rim once around as m goes from 0 to 4 R.
uvec2 rim(uint m) {
    uint r = params.resolution;
    m = m % (4u * r);
    if (m < r) return uvec2(m, 0u);
    if (m < 2u * r) return uvec2(r, m - r);
    if (m < 3u * r) return uvec2(3u * r - m, r);
    return uvec2(0u, 4u * r - m);
}

vec3 volume_point(uint index) {
    uint r = params.resolution;
    uint surface_count = 6u * r * r;
    if (index < surface_count) {
        const uvec2 corners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(1, 1), uvec2(0, 0), uvec2(1, 1), uvec2(0, 1));
        uint cell = index / 6u;
        return surface_point(uvec2(cell % r, cell / r) + corners[index % 6u]);
    }
    index -= surface_count;
    uint edge = index / 6u;  // walls: rim edge e, from rim(e) to rim(e + 1)
    if (edge < 4u * r) {
        const uint along[6] = uint[](0, 1, 1, 0, 1, 0);
        const bool lower[6] = bool[](false, false, true, false, true, true);
        vec3 p = surface_point(rim(edge + along[index % 6u]));
        if (lower[index % 6u]) p.y = params.bottom_y;
        return p;
    }
    index -= 24u * r;
    uint corner = index % 3u;  // bottom: (centre, rim(e), rim(e + 1)) at y = bottom_y
    if (corner == 0u) return vec3(0.0, params.bottom_y, 0.0);
    vec3 p = surface_point(rim(index / 3u + corner - 1u));
    return vec3(p.x, params.bottom_y, p.z);
}

void main() {
    gl_Position = frame.view_proj * vec4(volume_point(uint(gl_VertexIndex)), 1.0);
    // Reversed-Z clip depth n (the near distance) keeps the near-plane clip (n <= w) and
    // drops the far one (0 <= n): crossings beyond the far plane still count.
    gl_Position.z = frame.camera_near.x;
}
