// caustic_read_region (caustics_read_region.hpp).
#include "passes/caustics/caustics_read_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

namespace vkw::passes {
namespace {

struct Box {
    glm::dvec3 lo, hi;
};

// The six half-spaces of the view frustum, f(p) = dot(plane, (p, 1)) >= 0, from the rows of the
// reverse-Z clip transform: -w <= x, y <= w and 0 <= z <= w.
std::array<glm::dvec4, 6> frustum_planes(const glm::dmat4& m) {
    const glm::dvec4 x{m[0][0], m[1][0], m[2][0], m[3][0]}, y{m[0][1], m[1][1], m[2][1], m[3][1]},
        z{m[0][2], m[1][2], m[2][2], m[3][2]}, w{m[0][3], m[1][3], m[2][3], m[3][3]};
    return {w + x, w - x, w + y, w - y, z, w - z};
}

double side(const glm::dvec4& plane, const glm::dvec3& p) { return glm::dot(plane, glm::dvec4(p, 1.0)); }

// The vertices of the convex polytope frustum n box: each face of the box clipped against the
// six planes (Sutherland-Hodgman), plus the frustum's corners that lie inside the box. Every
// vertex of the intersection is one of these: it lies on a face of the box or is a corner of the
// frustum.
std::vector<glm::dvec3> frustum_box_vertices(const glm::dmat4& view_proj, const Box& box) {
    const std::array<glm::dvec4, 6> planes = frustum_planes(view_proj);
    std::vector<glm::dvec3> vertices;
    auto corner = [&](int i) {
        return glm::dvec3{(i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y, (i & 4) ? box.hi.z : box.lo.z};
    };
    // The faces as corner indices in order around each face.
    constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto& face : kFaces) {
        std::vector<glm::dvec3> polygon{corner(face[0]), corner(face[1]), corner(face[2]), corner(face[3])};
        for (const glm::dvec4& plane : planes) {
            std::vector<glm::dvec3> kept;
            for (size_t i = 0; i < polygon.size(); ++i) {
                const glm::dvec3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
                const double fp = side(plane, p), fq = side(plane, q);
                if (fp >= 0.0) kept.push_back(p);
                if ((fp >= 0.0) != (fq >= 0.0)) kept.push_back(p + (q - p) * (fp / (fp - fq)));
            }
            polygon = std::move(kept);
            if (polygon.empty()) break;
        }
        vertices.insert(vertices.end(), polygon.begin(), polygon.end());
    }
    const glm::dmat4 inverse = glm::inverse(view_proj);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p = inverse * glm::dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : 0.0, 1.0);
        const glm::dvec3 point = glm::dvec3(p) / p.w;
        if (glm::all(glm::greaterThanEqual(point, box.lo)) && glm::all(glm::lessThanEqual(point, box.hi))) {
            vertices.push_back(point);
        }
    }
    return vertices;
}

// A point's texel coordinates in the map (texel (i, j) spans [i, i + 1) x [j, j + 1)): where the
// line along t through it crosses the mean level (caustic_light_space.glsl).
glm::dvec2 texel_coordinates(const CausticMapFrame& frame, double level, const glm::dvec3& p) {
    const glm::dvec2 at_level = glm::dvec2(p.x, p.z) + (p.y - level) * frame.shear;
    return (at_level - frame.corner) / frame.texel;
}

// The convex hull of points (Andrew's monotone chain), counter-clockwise, no repeated point.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

CausticReadRegion unbounded(const std::string& why) {
    CausticReadRegion region;
    region.note = "every photon kept: " + why;
    return region;
}

}  // namespace

CausticReadRegion caustic_read_region(const CausticMapFrame& frame, const CausticReadInputs& in) {
    if (in.camera_space_splats) return unbounded("camera-space splats read the photons themselves, not the map");
    if (in.camera_may_be_in_water) {
        return unbounded("the camera may be under the water, where totally reflected rays reach any receiver");
    }
    const double slope_angle = std::atan(in.max_slope);
    constexpr double kSteepestBounded = 89.0 * std::numbers::pi / 180.0;
    if (!(std::asin(1.0 / in.ior) + slope_angle < kSteepestBounded)) {
        char text[160];
        std::snprintf(text, sizeof text, "the waves' slope bound (%.3g) lets refracted rays run horizontally",
                      in.max_slope);
        return unbounded(text);
    }
    const double top = in.level + in.amplitude;
    const double lowest = std::min(in.lowest_receiver, in.level - in.amplitude);
    const double depth = top - lowest;
    auto texels = [&](const glm::dvec3& p) { return texel_coordinates(frame, in.level, p); };
    // The box of points that project onto the map, and the water's slab.
    const glm::dvec2 map_lo = frame.corner, map_hi = frame.corner + glm::dvec2(frame.width, frame.height) * frame.texel;
    const glm::dvec2 shift = glm::abs(frame.shear) * std::max(in.level - lowest, in.amplitude);
    const Box projecting{{map_lo.x - shift.x, lowest, map_lo.y - shift.y},
                         {map_hi.x + shift.x, top, map_hi.y + shift.y}};
    // Gerstner terms move surface points sideways by up to the amplitude, past the grid's extent.
    const double half_width = in.half_extent + in.amplitude;
    const Box slab{{-half_width, in.level - in.amplitude, -half_width}, {half_width, top, half_width}};

    // Per block of the screen (kBlocks^2 sub-frusta), the read sets' images in the map, each convex.
    constexpr int kBlocks = 8, kSides = 8;
    std::vector<std::vector<glm::dvec2>> polygons;
    std::vector<glm::dmat4> views = {in.view_proj};
    views.insert(views.end(), in.more_views.begin(), in.more_views.end());
    for (const glm::dmat4& view_proj : views) {
        const glm::dmat4 inverse = glm::inverse(view_proj);
        for (int by = 0; by < kBlocks; ++by) {
            for (int bx = 0; bx < kBlocks; ++bx) {
                const double x0 = -1.0 + 2.0 * bx / kBlocks, x1 = x0 + 2.0 / kBlocks;
                const double y0 = -1.0 + 2.0 * by / kBlocks, y1 = y0 + 2.0 / kBlocks;
                // The block's own clip space: x' = (2 x - (x0 + x1) w) / (x1 - x0), likewise y.
                glm::dmat4 to_block(1.0);
                to_block[0][0] = 2.0 / (x1 - x0);
                to_block[3][0] = -(x0 + x1) / (x1 - x0);
                to_block[1][1] = 2.0 / (y1 - y0);
                to_block[3][1] = -(y0 + y1) / (y1 - y0);
                const glm::dmat4 block = to_block * view_proj;
                // Receivers seen straight, and the marched godrays' samples.
                std::vector<glm::dvec2> direct;
                for (const glm::dvec3& p : frustum_box_vertices(block, projecting)) direct.push_back(texels(p));
                if (!direct.empty()) polygons.push_back(convex_hull(direct));
                // Receivers met by rays refracted where the block's rays enter the slab. The block's
                // most oblique ray is one of its corners' (the rays within a given angle of -y form a
                // convex cone). Under flat water it leaves -y by asin(sin(theta_i) / n); a normal
                // tilted by up to atan(slope) turns the refracted ray by no more than it turns the
                // normal (t = eta i + (eta cos_i - cos_t) n changes by at most |dn|: by a factor
                // 1 - cos_i / (n cos_t) in the plane of incidence, |eta cos_i - cos_t| across it).
                const std::vector<glm::dvec3> entries = frustum_box_vertices(block, slab);
                if (entries.empty()) continue;
                double oblique = 0.0;
                for (int c = 0; c < 4; ++c) {
                    const glm::dvec4 n = inverse * glm::dvec4((c & 1) ? x1 : x0, (c & 2) ? y1 : y0, 1.0, 1.0);
                    const glm::dvec4 f = inverse * glm::dvec4((c & 1) ? x1 : x0, (c & 2) ? y1 : y0, 0.5, 1.0);
                    const glm::dvec3 d = glm::normalize(glm::dvec3(f) / f.w - glm::dvec3(n) / n.w);
                    oblique = std::max(oblique, std::acos(std::clamp(-d.y, -1.0, 1.0)));
                }
                const double incidence = std::min(oblique, std::numbers::pi / 2);
                const double steepest = std::asin(std::sin(incidence) / in.ior) + slope_angle;
                const double reach = depth * std::tan(steepest) / std::cos(std::numbers::pi / kSides);
                std::vector<glm::dvec2> entry_xz;
                for (const glm::dvec3& p : entries) entry_xz.push_back({p.x, p.z});
                std::vector<glm::dvec2> refracted;
                for (const glm::dvec2& e : convex_hull(entry_xz)) {
                    for (int k = 0; k < kSides; ++k) {
                        const double angle = 2.0 * std::numbers::pi * (k + 0.5) / kSides;
                        const glm::dvec2 xz = e + reach * glm::dvec2(std::cos(angle), std::sin(angle));
                        for (const double y : {lowest, top}) refracted.push_back(texels({xz.x, y, xz.y}));
                    }
                }
                polygons.push_back(convex_hull(refracted));
            }
        }
    }

    // Per unit row [j, j + 1] of the map, the x-range of every polygon's part of it: a convex
    // polygon's part of a strip spans its vertices inside the strip and its edges' crossings of
    // the strip's two lines. One pass over the edges, each crossing updating the rows on both
    // sides of its line.
    const int height = static_cast<int>(frame.height);
    const glm::dvec2 empty{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    std::vector<glm::dvec2> unit(frame.height, empty);
    auto include = [&](int row, double x) {
        if (row < 0 || row >= height) return;
        unit[row] = {std::min(unit[row].x, x), std::max(unit[row].y, x)};
    };
    for (const std::vector<glm::dvec2>& polygon : polygons) {
        for (size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
            const double row = std::floor(p.y);
            if (row >= -1.0 && row <= height) {
                include(static_cast<int>(row), p.x);
                if (row == p.y) include(static_cast<int>(row) - 1, p.x);  // on a line: both rows
            }
            const double lo = std::max(std::ceil(std::min(p.y, q.y)), 0.0);
            const double hi = std::min(std::floor(std::max(p.y, q.y)), double(height));
            for (double line = lo; line <= hi; line += 1.0) {
                if (p.y == q.y) break;
                const double x = p.x + (q.x - p.x) * (line - p.y) / (q.y - p.y);
                include(static_cast<int>(line) - 1, x);
                include(static_cast<int>(line), x);
            }
        }
    }
    // The strip of row r widened by the margin, [r - m, r + 1 + m], is the unit rows r - m .. r + m.
    const double margin = in.read_margin;
    const int m = static_cast<int>(in.read_margin);
    std::vector<glm::dvec2> spans(frame.height, empty);
    for (int row = 0; row < height; ++row) {
        for (int near = std::max(0, row - m); near <= std::min(height - 1, row + m); ++near) {
            spans[row] = {std::min(spans[row].x, unit[near].x), std::max(spans[row].y, unit[near].y)};
        }
    }
    CausticReadRegion region;
    region.bounded = true;
    const double sun_angle = std::acos(std::clamp(-frame.direction.y, -1.0, 1.0));
    if (sun_angle + slope_angle < kSteepestBounded) {
        region.photon_spread = depth * (std::tan(sun_angle + slope_angle) - std::tan(sun_angle - slope_angle)) +
                               in.amplitude * (glm::length(frame.shear) + 1.0);
    }
    region.rows.assign(frame.height, {});
    region.x0 = frame.width;
    region.y0 = frame.height;
    uint64_t texel_count = 0;
    for (uint32_t row = 0; row < frame.height; ++row) {
        const glm::dvec2 span = spans[row];
        if (span.x > span.y) continue;
        const double first = std::clamp(std::floor(span.x) - margin, 0.0, double(frame.width));
        const double end = std::clamp(std::floor(span.y) + 1.0 + margin, 0.0, double(frame.width));
        if (end <= first) continue;
        CausticTexelSpan& texel_span = region.rows[row];
        texel_span = {static_cast<uint32_t>(first), static_cast<uint32_t>(end)};
        texel_count += texel_span.x1 - texel_span.x0;
        region.x0 = std::min(region.x0, texel_span.x0);
        region.x1 = std::max(region.x1, texel_span.x1);
        region.y0 = std::min(region.y0, row);
        region.y1 = row + 1;
    }
    if (region.y1 == 0) region.x0 = region.y0 = 0;  // nothing read
    region.packed_rows = std::make_shared<const std::vector<uint32_t>>(pack_caustic_read_rows(region.rows));
    const double share = double(texel_count) / (double(frame.width) * double(frame.height));
    char text[200];
    std::snprintf(text, sizeof text,
                  "photons kept where their kernel reaches the %.0f%% of the map's %u x %u texels the frame can "
                  "read (rows %u..%u)",
                  100.0 * share, frame.width, frame.height, region.y0, region.y1);
    region.note = text;
    return region;
}

const CausticReadRegion& CausticReadRegionCache::region(const CausticMapFrame& frame, const CausticReadInputs& inputs) {
    if (!valid_ || !(frame == frame_) || !(inputs == inputs_)) {
        region_ = caustic_read_region(frame, inputs);
        frame_ = frame;
        inputs_ = inputs;
        valid_ = true;
        ++computed_;
    }
    return region_;
}

}  // namespace vkw::passes
