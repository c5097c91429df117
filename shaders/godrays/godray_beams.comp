#version 460
// The godray beams (passes/godrays/godrays_beams.hpp): one photon per cell of a coarse G x G grid over the
// water, each cell's corners interpolated bilinearly from the GPU surface grid (R x R cells), traced
// by the caustics' own photon code (caustics/caustic_photon.glsl: vector area, exact Fresnel,
// refraction, the drop rules) with no extinction, so that its energy times E_s is Phi0, the flux
// just below the surface (docs/model.md section 6). The beam runs from the entry point along t to
// the floor, or to max_depth below the mean level. Variant VKWATER_SUN_SHADOW: objects above the
// water block the photon at its entry point, and receiver meshes under the water end its beam
// where the caustic photons end (the sun shadow map's beam half, caustics/caustic_receiver_hit.glsl).
#extension GL_GOOGLE_include_directive : require

#include "caustics/caustic_photon.glsl"
#include "common/frame_constants.glsl"
#include "godrays/godray_beam.glsl"
#ifdef VKWATER_SUN_SHADOW
#include "caustics/caustic_receiver_hit.glsl"  // and receivers/sun_shadow.glsl: bindings 6 and 7
#endif

layout(local_size_x = 8, local_size_y = 8) in;

// Vertex rows vertex_row0 .. of the grid, the first one vertex_base elements into the binding.
layout(set = 0, binding = 1, std430) readonly buffer Surface { WaterVertex vertices[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Beams { GodrayBeam beams[]; };

// Its C++ type (GodrayBeamsPush in passes/godrays/godrays_beams.cpp) is generated from this shader.
layout(push_constant) uniform Push {
    uint resolution;   // R: surface cells per side
    uint grid;         // G: beams per side
    uint first_row;    // the first beam row of this chunk
    uint rows;         // beam rows in this chunk
    uint vertex_row0;  // the first vertex row in the surface binding
    uint vertex_base;  // elements before it in the binding (the binding's offset is aligned down)
    float max_depth;   // m below the mean level where beams stop
    float pad;
} pc;

WaterVertex surface_vertex(uvec2 ij) {
    return vertices[(ij.y - pc.vertex_row0) * (pc.resolution + 1u) + ij.x + pc.vertex_base];
}

// The surface at continuous vertex-grid coordinates a in [0, R]^2, bilinear in its cell; exactly
// the vertex where a is an integer (mix(x, y, 0) = x).
WaterVertex surface_at(vec2 a) {
    const uvec2 cell = min(uvec2(a), uvec2(pc.resolution - 1u));
    const vec2 f = a - vec2(cell);
    const WaterVertex v00 = surface_vertex(cell), v10 = surface_vertex(cell + uvec2(1, 0));
    const WaterVertex v01 = surface_vertex(cell + uvec2(0, 1)), v11 = surface_vertex(cell + uvec2(1, 1));
    return WaterVertex(mix(mix(v00.position, v10.position, f.x), mix(v01.position, v11.position, f.x), f.y),
                       mix(mix(v00.normal, v10.normal, f.x), mix(v01.normal, v11.normal, f.x), f.y));
}

void main() {
    const uvec2 g = gl_GlobalInvocationID.xy;
    if (g.x >= pc.grid || g.y >= pc.rows) return;
    const uvec2 ij = uvec2(g.x, g.y + pc.first_row);
    const uint index = ij.y * pc.grid + ij.x;
    beams[index] = GodrayBeam(vec4(0.0), vec4(0.0, -1.0, 0.0, 0.0), vec4(0.0));
    if (frame.sun_direction.w < 0.5) return;

    // Corners at i R / G (exact when G divides i R: with G = R they are the grid's vertices).
    const vec2 a0 = vec2(ij * pc.resolution) / float(pc.grid);
    const vec2 a1 = vec2((ij + 1u) * pc.resolution) / float(pc.grid);
    const CausticCell cell = CausticCell(surface_at(a0), surface_at(vec2(a1.x, a0.y)), surface_at(vec2(a0.x, a1.y)),
                                         surface_at(a1));
    const float n = frame.water.y, floor_y = frame.floor_plane.x;
    const CausticLightSpace space = CausticLightSpace(vec4(0.0, 0.0, 0.0, floor_y), vec4(0.0), vec4(0.0),
                                                      vec4(frame.sun_direction.xyz, n));
    CausticPhoton photon;
    if (!trace_caustic_photon(cell, vec2(0.0), vec2(1.0), space, vec3(0.0), photon)) return;

    // The photon's own entry point and direction (the trace's, recomputed: it succeeded, so the
    // refraction does too).
    const vec3 entry = caustic_patch_point(cell, vec2(0.5));
    vec3 t;
    refract_direction(frame.sun_direction.xyz, normalize(caustic_patch_normal(cell, vec2(0.5))), 1.0 / n, t);
    const float deepest = frame.water.x - pc.max_depth;
    float length_in_water = min((entry.y - floor_y) / -t.y, max(0.0, (entry.y - deepest) / -t.y));
#ifdef VKWATER_SUN_SHADOW
    // The first receiver mesh along the beam ends it, as it ends the caustic photon (searched
    // against the meshes as the map sees them along the flat-water refracted sun t0).
    vec3 t0;
    refract_direction(frame.sun_direction.xyz, vec3(0.0, 1.0, 0.0), 1.0 / n, t0);
    photon.entry = entry;
    photon.direction = t;
    length_in_water = min(length_in_water, receiver_path(photon, t0, floor_y, (entry.y - floor_y) / -t.y));
#endif
    if (!(length_in_water > 0.0)) return;
    vec3 flux = frame.sun_irradiance.rgb * photon.energy;
#ifdef VKWATER_SUN_SHADOW
    flux *= sun_visibility(entry, max(-frame.sun_direction.y, 1e-3));
#endif
    // The tube's width: the cell's side on the grid of parameters (exact on flat water; under waves
    // the beams' spacing changes along them, and the width is the footprint's kernel).
    beams[index] = GodrayBeam(vec4(entry, length_in_water), vec4(t, 2.0 * frame.water.z / float(pc.grid)), vec4(flux, 0.0));
}
