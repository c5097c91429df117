#version 460
// Photon grid -> camera-space caustic flux (Ojeda & Susín 2013 section 4): each photon of
// the grid (caustic_grid_photon.glsl, the very photons of the light-space map) that lands on a
// receiver the camera sees without the water is splatted as a gaussian lying in that receiver's
// tangent plane, into a per-pixel flux buffer of the receivers' view
// (passes/caustics/caustics_camera_splats.hpp), accumulated in 64-bit fixed point like the light-space map,
// so two runs are bit-identical. Variants: plain (the floor plane) and VKWATER_SUN_SHADOW
// (receiver meshes under the water and occluders above it).
//
// Per photon, at its hit P:
// - visibility: P projects to pixel c of the view; the photon counts only when P lies on the
//   receiver c shows, within kReceiverPlaneTolerance of its distance from the receiver's tangent plane
//   (the depth test against the water-less depth; a plane test, not a distance test, so a slanted
//   floor seen between two pixel centres passes); otherwise its flux goes to `lost`;
// - size: an anisotropic gaussian in the receiver's tangent plane, covariance kSigmaPerSpacing^2
//   M M^T with M the steps to where the photon's grid neighbours' rays meet that plane (the photon
//   density sizing: a lattice of them is the affine image of an isotropic one and sums flat, and
//   a focal line keeps its width across the line), plus kMinSigmaPixels of the view's pixels;
//   de la Fuente 2011's point size regulation by distance follows from projecting a splat of fixed size on
//   the receiver, and its cost is held by the level pyramid (caustic_camera_view.glsl);
// - taps: every pixel within the ellipse of kSplatCutoff sigmas on the splat's level that shows
//   the same receiver plane (the same plane test: a splat stops at silhouettes) gets weight
//   g(X - P) A, X where the pixel's ray meets the tangent plane and A the plane's area that pixel
//   sees (caustic_camera_view.glsl); the integer flux is split over the taps by cumulative
//   rounding (the remainder to the photon's own pixel), so the taps sum to it exactly and the
//   resolve's E = Phi_pixel / A is the gaussian's density times the flux.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

#include "caustics/caustic_camera_view.glsl"  // binding 0: the frame constants
#include "water/water_vertex.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// The vertex rows first_row .. first_row + rows of the grid (a chunk's binding).
layout(set = 0, binding = 1, std430) readonly buffer Surface { WaterVertex vertices[]; };

#include "caustics/caustic_grid_photon.glsl"  // with VKWATER_SUN_SHADOW: bindings 6 and 7

// The flux pyramid (caustic_camera_view.glsl), three uint64 per pixel (R, G, B), row after row.
layout(set = 0, binding = 2, std430) buffer Flux { uint64_t flux[]; };
// Flux of photons the camera does not see on a receiver (off the view, hidden, or no receiver).
layout(set = 0, binding = 3, std430) buffer Lost { uint64_t lost[]; };
// The receivers' view (passes/caustics/caustics_camera_receivers.hpp): normal toward the eye, distance.
layout(set = 0, binding = 5) uniform sampler2D receivers;

// Its C++ type (CameraSplatPush in passes/caustics/caustics_camera_splats.cpp) is generated from
// this shader; 128 bytes.
layout(push_constant) uniform Push {
    CausticPhotonSource source;
    uint resolution;  // R cells per side
    uint sub;         // S: S x S photons per cell
    uint first_row;   // first cell row of this chunk
    uint rows;        // cell rows in this chunk
    uint jitter;      // 1: each photon leaves from a hashed point of its sub-cell
    uint width;       // the view, pixels
    uint height;
    uint pad;
} pc;

const float kSigmaPerSpacing = 0.75;  // a lattice of gaussians this wide sums flat to 2 exp(-2 pi^2 0.75^2) = 3e-5
// Sigmas: the box of taps on each axis. A step at the box's edge ripples the sum of a lattice of
// splats by about the gaussian's value there (measured under flat water, top-down: 2.5 sigmas
// +-0.8 % in lines at the photon spacing, 3.5 sigmas +-0.03 %).
const float kSplatCutoff = 3.5;
const float kMinSigmaPixels = 0.7;     // a pixel lattice samples such a gaussian's sum to 1e-4

void lose(u64vec3 q) {
    for (uint ch = 0u; ch < 3u; ++ch) {
        if (q[ch] != 0ul) atomicAdd(lost[ch], q[ch]);
    }
}

// Where the photon's grid neighbours (one sub-cell along u and along v) meet the tangent plane
// (point P, normal N), relative to P, in the plane's coordinates (e1, e2), m; false where a
// neighbour does not enter or runs parallel to the plane.
bool neighbour_steps(GridPhoton p, vec3 normal, vec3 e1, vec3 e2, out vec2 m1, out vec2 m2) {
    const float step = 1.0 / float(pc.sub);
    const vec3 hit = p.photon.hit;
    m1 = m2 = vec2(0.0);
    for (int axis = 0; axis < 2; ++axis) {
        vec3 entry, t;
        if (!caustic_patch_ray(p.cell, p.at + (axis == 0 ? vec2(step, 0.0) : vec2(0.0, step)), pc.source.space, entry, t)) {
            return false;
        }
        const float along = dot(t, normal);
        if (abs(along) < 1e-4) return false;
        const vec3 d = entry + (dot(hit - entry, normal) / along) * t - hit;
        if (axis == 0) m1 = vec2(dot(d, e1), dot(d, e2));
        else m2 = vec2(dot(d, e1), dot(d, e2));
    }
    return true;
}

// A splat: the photon's hit P on the receiver (normal N, h = (P - eye) . N, tangents e1, e2), its
// pixel coordinate x in the view, its gaussian's inverse covariance on the plane (xx, xy, yy in
// the (e1, e2) coordinates, 1/m^2) and the tap box's half-size (view pixels).
struct SplatPlane {
    CameraRays rays;
    vec3 hit;
    vec3 normal;
    float h;
    vec3 e1, e2;
    vec2 x;
    vec3 inverse_covariance;
    vec2 box;
    vec3 pixel_normal;  // dx x dy of the rays
};

// Splats q over the pixels of `level` (pass 0 sums the weights, pass 1 deposits cumulative shares
// in the same order; what the rounding leaves, a few units, goes to the photon's own pixel).
// False (nothing deposited) when no pixel of the box shows the receiver's plane.
bool splat_at_level(SplatPlane s, int level, u64vec3 q) {
    const ivec2 size = ivec2(pc.width, pc.height);
    const float scale = float(1 << level);
    const ivec2 level_size = ivec2(camera_level_size(uvec2(size), level));
    const uint base = camera_level_offset(uvec2(size), level);
    const vec2 at = s.x / scale;
    const vec2 reach = s.box / scale;
    const ivec2 lo = max(ivec2(floor(at - reach)), ivec2(0));
    const ivec2 hi = min(ivec2(floor(at + reach)), level_size - 1);
    float total = 0.0, partial = 0.0;
    u64vec3 given = u64vec3(0ul);
    for (int pass = 0; pass < 2; ++pass) {
        for (int ty = lo.y; ty <= hi.y; ++ty) {
            for (int tx = lo.x; tx <= hi.x; ++tx) {
                const ivec2 t = ivec2(tx, ty);
                // The gaussian first (cheap, and the box's corners beyond the cut-off ellipse drop
                // out before the receiver fetch), then the plane test and the area.
                const vec3 ray = camera_ray(s.rays, (vec2(t) + 0.5) * scale);
                const float rn = dot(ray, s.normal);
                if (!(rn * s.h > 0.0)) continue;  // the ray meets the plane behind the eye
                const vec3 offset = s.rays.eye + (s.h / rn) * ray - s.hit;
                const vec2 d = vec2(dot(offset, s.e1), dot(offset, s.e2));
                const vec3 ic = s.inverse_covariance;
                const float quadratic = ic.x * d.x * d.x + 2.0 * ic.y * d.x * d.y + ic.z * d.y * d.y;
                if (quadratic > kSplatCutoff * kSplatCutoff) continue;
                const ivec2 texel = camera_level_texel(t, level, size);
                if (!receiver_on_plane(s.rays, texel, texelFetch(receivers, texel, 0), s.hit, s.normal)) continue;
                const float area = scale * scale * s.h * s.h * abs(dot(s.pixel_normal, ray)) / abs(rn * rn * rn);
                const float w = exp(-0.5 * quadratic) * area;
                if (pass == 0) {
                    total += w;
                    continue;
                }
                partial += w;
                const float f = min(partial / total, 1.0);
                const uint i = (base + uint(ty) * uint(level_size.x) + uint(tx)) * 3u;
                for (uint ch = 0u; ch < 3u; ++ch) {
                    const uint64_t upto = caustic_share(q[ch], f);
                    if (upto > given[ch]) atomicAdd(flux[i + ch], upto - given[ch]);
                    given[ch] = max(given[ch], upto);
                }
            }
        }
        if (pass == 0 && !(total > 0.0)) return false;
    }
    const ivec2 own = clamp(ivec2(at), ivec2(0), level_size - 1);
    const uint i = (base + uint(own.y) * uint(level_size.x) + uint(own.x)) * 3u;
    for (uint ch = 0u; ch < 3u; ++ch) {
        if (q[ch] > given[ch]) atomicAdd(flux[i + ch], q[ch] - given[ch]);
    }
    return true;
}

// The taps a box of half-size `box` (view pixels) takes on `level`.
float splat_taps(vec2 box, int level) {
    const vec2 side = 2.0 * box / float(1 << level) + 1.0;
    return side.x * side.y;
}

void main() {
    GridPhoton p;
    const CausticPhotonChunk chunk = CausticPhotonChunk(pc.resolution, pc.sub, pc.first_row, pc.rows, pc.jitter != 0u, 0u);
    if (!trace_grid_photon(gl_GlobalInvocationID.xy, chunk, pc.source, p)) return;
    const u64vec3 q = u64vec3(p.q + 0.5);
    const vec2 size = vec2(pc.width, pc.height);
    const CameraRays rays = camera_rays(size);
    const vec3 hit = p.photon.hit;
    vec2 x;
    if (!camera_pixel_coord(hit, size, x)) { lose(q); return; }
    const ivec2 centre = clamp(ivec2(x), ivec2(0), ivec2(size) - 1);
    const vec4 receiver = texelFetch(receivers, centre, 0);
    const vec3 normal = receiver.xyz;
    if (!receiver_on_plane(rays, centre, receiver, hit, normal)) { lose(q); return; }

    // J maps a step on the receiver's tangent plane (tangents e1, e2) to view pixels.
    const vec3 e1 = normalize(abs(normal.y) < 0.9 ? cross(normal, vec3(0.0, 1.0, 0.0)) : cross(normal, vec3(1.0, 0.0, 0.0)));
    const vec3 e2 = cross(normal, e1);
    const float probe = 1e-3 * receiver.w;
    vec2 x1, x2;
    camera_pixel_coord(hit + probe * e1, size, x1);
    camera_pixel_coord(hit + probe * e2, size, x2);
    const vec2 j1 = (x1 - x) / probe, j2 = (x2 - x) / probe;  // pixels per metre
    // Singular values of J = [j1 j2]: the pixels per metre along the plane's most compressed direction.
    const float a = dot(j1, j1), b = dot(j1, j2), c = dot(j2, j2);
    const float root = sqrt(max(0.0, 0.25 * (a - c) * (a - c) + b * b));
    const float s_min = sqrt(max(0.5 * (a + c) - root, 1e-20));
    // The covariance on the plane: the neighbours' steps M = [m1 m2] make it k^2 M M^T (a lattice
    // of such gaussians is the affine image of an isotropic one, so it sums flat, and a focal line
    // keeps its width across the line), plus kMinSigmaPixels^2 of the finest pixels.
    vec2 m1, m2;
    const float k2 = neighbour_steps(p, normal, e1, e2, m1, m2) ? kSigmaPerSpacing * kSigmaPerSpacing : 0.0;
    const float floor2 = (kMinSigmaPixels / s_min) * (kMinSigmaPixels / s_min);
    vec3 covariance = vec3(k2 * (m1.x * m1.x + m2.x * m2.x) + floor2, k2 * (m1.x * m1.y + m2.x * m2.y),
                           k2 * (m1.y * m1.y + m2.y * m2.y) + floor2);
    // Its extent on the view: J C J^T, whose diagonal gives the box along x and y.
    const vec2 jx = vec2(j1.x, j2.x), jy = vec2(j1.y, j2.y);
    const mat2 cov = mat2(covariance.x, covariance.y, covariance.y, covariance.z);
    vec2 box = kSplatCutoff * sqrt(max(vec2(dot(jx, cov * jx), dot(jy, cov * jy)), vec2(0.0)));
    // The level: the finest on which the box takes at most kMaxSplatTaps pixels (at the coarsest,
    // the gaussian is shrunk to fit). Counting taps rather than the wider side keeps a splat seen
    // at a grazing angle (wide and a pixel or two high) on a fine level, so that its rows keep their
    // depth; choosing by the wider side moved flux toward the camera near the horizon (measured:
    // -55 % in the top floor rows, +33 % a few rows lower). Near the limit the photon is shared with
    // the next level, its share rising from 0 at half the budget to all of it at the budget, so
    // that the levels take over from each other gradually (a hard switch leaves a seam: the coarse
    // level's bilinear read blurs its edge by a coarse pixel, measured 5-20 % under flat water).
    const int last = kCameraCausticLevels - 1;
    int level = 0;
    while (level < last && splat_taps(box, level) > kMaxSplatTaps) ++level;
    if (splat_taps(box, level) > kMaxSplatTaps) {
        // The coarsest level: shrink the gaussian by steps of 0.8 until it fits.
        float shrink = 1.0;
        while (splat_taps(box * shrink, level) > kMaxSplatTaps && shrink > 1e-3) shrink *= 0.8;
        covariance *= shrink * shrink;
        box *= shrink;
    }
    const float fill = splat_taps(box, level) / kMaxSplatTaps;
    const float coarser = level < last ? clamp(2.0 * fill - 1.0, 0.0, 1.0) : 0.0;
    const float det = max(covariance.x * covariance.z - covariance.y * covariance.y, 1e-30);
    const vec3 inverse_covariance = vec3(covariance.z, -covariance.y, covariance.x) / det;
    const u64vec3 q_coarser = u64vec3(vec3(q) * coarser + 0.5);
    const u64vec3 q_here = q - min(q_coarser, q);
    const SplatPlane plane =
        SplatPlane(rays, hit, normal, dot(hit - rays.eye, normal), e1, e2, x, inverse_covariance, box,
                   cross(rays.dx, rays.dy));
    if (!splat_at_level(plane, level, q_here)) { lose(q); return; }
    if (any(greaterThan(q_coarser, u64vec3(0ul))) && !splat_at_level(plane, level + 1, min(q_coarser, q))) lose(min(q_coarser, q));
}
