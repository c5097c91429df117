// The footprint splat of a caustic photon (effects.caustics.kernel = footprint): Tipprasert 2006's area
// ratio done in the light-space map. A photon stands for its sub-cell of the surface; the rays of
// the sub-cell's four corners, refracted with their own normals and run the photon's path length,
// land on the corners of its footprint, and the photon's flux is spread over the footprint
// uniformly, each texel taking the share of the footprint's area it covers (exact polygon
// clipping of the footprint's two triangles against the texel's square). So the map holds
// flux / footprint area on the footprint: Tipprasert 2006's I = Phi / A_d, with T and exp(-sigma_t l) in
// Phi, and texel values that are box averages of the irradiance (no tent blur). A footprint over
// more than kMaxFootprintTexels texels on an axis (a sub-cell spread far out of focus) or with no
// area (its rays cross in a point or a line) falls back to the adaptive hat (caustic_splat.glsl).
#ifndef VKWATER_CAUSTIC_FOOTPRINT_GLSL
#define VKWATER_CAUSTIC_FOOTPRINT_GLSL

#include "caustics/caustic_photon.glsl"

const int kMaxFootprintTexels = 8;  // per axis: at most 64 texels

// The footprint's corners in texel coordinates (texel (i, j) is the square [i, i+1] x [j, j+1]),
// in order around the sub-cell [uv0, uv1]; false when a corner's ray does not enter the water.
bool footprint_corners(CausticCell cell, vec2 uv0, vec2 uv1, CausticPhoton photon, CausticLightSpace space,
                       out vec2 corner[4]) {
    const vec2 uv[4] = vec2[4](uv0, vec2(uv1.x, uv0.y), uv1, vec2(uv0.x, uv1.y));
    for (int k = 0; k < 4; ++k) {
        vec3 t;
        const vec3 normal = normalize(caustic_patch_normal(cell, uv[k]));
        if (!refract_direction(space.sun.xyz, normal, 1.0 / space.sun.w, t) || t.y > -kCausticUpEpsilon) return false;
        corner[k] = caustic_texel_coord(caustic_patch_point(cell, uv[k]) + photon.path * t, space);
    }
    return true;
}

// The area of triangle abc inside the unit square at lo (Sutherland-Hodgman against its four
// sides, then the shoelace formula), whatever the triangle's orientation. The corners are taken
// relative to lo first: the shoelace's products of absolute coordinates C texels from the map's
// origin would carry an fp32 error of about C^2 2^-24 texels^2 (6% of a texel at C = 1000).
float triangle_in_square(vec2 a, vec2 b, vec2 c, vec2 lo) {
    vec2 polygon[7] = vec2[7](a - lo, b - lo, c - lo, vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    int count = 3;
    for (int side = 0; side < 4 && count > 0; ++side) {
        const int axis = side / 2;
        // Inside: coordinate >= 0 (sides 0, 2) or <= 1 (sides 1, 3).
        const float bound = float(side % 2), sense = side % 2 == 0 ? 1.0 : -1.0;
        vec2 kept[7];
        int kept_count = 0;
        for (int i = 0; i < count; ++i) {
            const vec2 p = polygon[i], q = polygon[(i + 1) % count];
            const float fp = sense * (p[axis] - bound), fq = sense * (q[axis] - bound);
            if (fp >= 0.0 && kept_count < 7) kept[kept_count++] = p;
            if ((fp >= 0.0) != (fq >= 0.0) && kept_count < 7) kept[kept_count++] = mix(p, q, fp / (fp - fq));
        }
        polygon = kept;
        count = kept_count;
    }
    float twice = 0.0;
    for (int i = 0; i < count; ++i) {
        const vec2 p = polygon[i], q = polygon[(i + 1) % count];
        twice += p.x * q.y - q.x * p.y;
    }
    return 0.5 * abs(twice);
}

// The footprint's texel box (first texel, texels per axis) and each texel's covered area, row by
// row; false when the box exceeds kMaxFootprintTexels on an axis or the footprint has no area.
bool footprint_weights(vec2 corner[4], out ivec2 first, out ivec2 size, out float weight[64], out float total) {
    const vec2 lo = min(min(corner[0], corner[1]), min(corner[2], corner[3]));
    const vec2 hi = max(max(corner[0], corner[1]), max(corner[2], corner[3]));
    total = 0.0;
    for (int i = 0; i < 64; ++i) weight[i] = 0.0;
    if (!all(lessThan(abs(lo), vec2(1e7))) || !all(lessThan(abs(hi), vec2(1e7)))) return false;
    first = ivec2(floor(lo));
    size = ivec2(floor(hi)) - first + 1;
    if (any(greaterThan(size, ivec2(kMaxFootprintTexels)))) return false;
    for (int j = 0; j < size.y; ++j) {
        for (int i = 0; i < size.x; ++i) {
            const vec2 square = vec2(first + ivec2(i, j));
            const float w = triangle_in_square(corner[0], corner[1], corner[2], square) +
                            triangle_in_square(corner[0], corner[2], corner[3], square);
            weight[j * kMaxFootprintTexels + i] = w;
            total += w;
        }
    }
    return total > 0.0;
}

#endif
