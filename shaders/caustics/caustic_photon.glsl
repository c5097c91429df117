// One caustic photon (docs/model.md sections 4 and 8): sub-cell (a, b) of cell
// (i, j) of the GPU water grid (passes/water/water_surface.hpp), refracted with the exact Fresnel of
// common/fresnel.glsl and carried to the floor plane (the receiver meshes in front of it are
// found by caustic_receiver_hit.glsl). Shared by the fixed-point kernel, the godray beams and any
// other splat variant, so that they trace identical photons.
#ifndef VKWATER_CAUSTIC_PHOTON_GLSL
#define VKWATER_CAUSTIC_PHOTON_GLSL

#include "caustics/caustic_light_space.glsl"
#include "common/fresnel.glsl"
#include "water/water_vertex.glsl"

// A refracted ray whose y component is above -kCausticUpEpsilon is dropped: it points up or runs
// so flat that the division by t.y would send it arbitrarily far (docs/model.md section 8).
const float kCausticUpEpsilon = 1e-6;

struct CausticPhoton {
    vec3 entry;      // where it enters the water (the sub-cell's centre)
    vec3 direction;  // its refracted direction t (unit, pointing down)
    float area;      // max(0, -s.a), a the sub-cell's vector area: what it intercepts of the beam, m^2
    float carried;   // area T(theta_i): its flux over E_s just below the surface
    float path;      // l: the path in the water to its receiver
    vec3 hit;        // entry + l t, where it meets the receiver
    vec3 energy;     // per RGB: carried exp(-sigma_t l); times E_s this is the photon's flux Phi (W)
};

// Stops the photon after l metres in the water (its receiver, found by the caller).
void caustic_photon_stop_at(inout CausticPhoton photon, float l, vec3 sigma_t) {
    photon.path = l;
    photon.hit = photon.entry + l * photon.direction;
    photon.energy = photon.carried * exp(-sigma_t * l);
}

// The four corners of one grid cell, as the GPU surface wrote them.
struct CausticCell {
    WaterVertex v00, v10, v01, v11;  // (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)
};

// The bilinear patch through the cell's corners at (x, y) in [0, 1]^2. mix(a, b, 0) is exactly a,
// so with one photon per cell the sub-cell's corners are the grid's vertices bit for bit.
vec3 caustic_patch_point(CausticCell c, vec2 uv) {
    return mix(mix(c.v00.position.xyz, c.v10.position.xyz, uv.x), mix(c.v01.position.xyz, c.v11.position.xyz, uv.x),
               uv.y);
}
vec3 caustic_patch_normal(CausticCell c, vec2 uv) {
    return mix(mix(c.v00.normal.xyz, c.v10.normal.xyz, uv.x), mix(c.v01.normal.xyz, c.v11.normal.xyz, uv.x), uv.y);
}

// The ray of a photon that would leave from point `at` of the patch: its entry point p and
// refracted direction t; false where it does not enter (refracted up or too flat). The kernels
// sized by where a photon's neighbours land trace these.
bool caustic_patch_ray(CausticCell cell, vec2 at, CausticLightSpace space, out vec3 p, out vec3 t) {
    p = caustic_patch_point(cell, at);
    t = vec3(0.0, -1.0, 0.0);
    return refract_direction(space.sun.xyz, normalize(caustic_patch_normal(cell, at)), 1.0 / space.sun.w, t) &&
           t.y <= -kCausticUpEpsilon;
}

// Traces the photon of the sub-cell [uv0, uv1] of the patch. False when it carries nothing: the
// sub-cell faces away from the sun (its projected area or the cosine at its centre is not
// positive), the refracted ray points up, or the surface lies below the floor.
// Intercepted area: the sub-cell's vector area a = (d2 x d1) / 2 from its diagonals, which is
// exactly |dP/du x dP/dv| du dv (times the unit normal) at the centre of a bilinear patch; for a
// heightfield -s.a = (cos theta_s - u_h . grad h) dA_h, docs/model.md section 4's intercepted area,
// so no slope factor is applied again.
// Optics (Fresnel, refraction): the interpolated vertex normals at the centre, which are the
// surface model's analytic normals rather than the chord's.
// `at` is the point of the patch (in [uv0, uv1]) the photon leaves from: the sub-cell's centre, or
// a jittered point of it; its area stays the sub-cell's either way.
bool trace_caustic_photon_at(CausticCell cell, vec2 uv0, vec2 uv1, vec2 at, CausticLightSpace space, vec3 sigma_t,
                             out CausticPhoton photon) {
    photon = CausticPhoton(vec3(0.0), vec3(0.0, -1.0, 0.0), 0.0, 0.0, 0.0, vec3(0.0), vec3(0.0));
    const vec3 s = space.sun.xyz;
    const float n = space.sun.w;
    const vec3 c00 = caustic_patch_point(cell, uv0), c11 = caustic_patch_point(cell, uv1);
    const vec3 c10 = caustic_patch_point(cell, vec2(uv1.x, uv0.y)), c01 = caustic_patch_point(cell, vec2(uv0.x, uv1.y));
    // u runs along x and v along z: (c01 - c10) x (c11 - c00) points up (+y) on a flat cell.
    const vec3 area = 0.5 * cross(c01 - c10, c11 - c00);
    const float projected = -dot(s, area);
    const vec3 p = caustic_patch_point(cell, at);
    const vec3 normal = normalize(caustic_patch_normal(cell, at));
    const float cos_i = -dot(s, normal);
    if (!(projected > 0.0) || !(cos_i > 0.0)) return false;
    vec3 t;
    if (!refract_direction(s, normal, 1.0 / n, t) || t.y > -kCausticUpEpsilon) return false;
    const float l = (p.y - space.origin.w) / (-t.y);  // path length in the water
    if (!(l >= 0.0)) return false;
    const Fresnel fresnel = fresnel_exact(cos_i, 1.0, n);
    photon.entry = p;
    photon.direction = t;
    photon.area = projected;
    photon.carried = projected * fresnel.T;
    caustic_photon_stop_at(photon, l, sigma_t);
    return true;
}

bool trace_caustic_photon(CausticCell cell, vec2 uv0, vec2 uv1, CausticLightSpace space, vec3 sigma_t,
                          out CausticPhoton photon) {
    return trace_caustic_photon_at(cell, uv0, uv1, 0.5 * (uv0 + uv1), space, sigma_t, photon);
}

#endif
