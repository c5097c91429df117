// The photon pass's culling bound (passes/caustics/caustics_read_region.hpp), tested on the CPU in
// double precision against what it must contain: for pixels over the whole view, the exact first
// intersection of the camera ray with the waves (marched and bisected), refracted with the exact
// normal and carried to the floor, must read only texels inside the read region (the four texels
// of the lookup's bilinear sample); rays that miss the water and reach the floor likewise; and every
// photon must land within photon_spread of its cell's own place. The images with and without the
// culling are compared on the GPU in tests/render/caustic_culling_test.cpp.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "passes/caustics/caustics_read_region.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vkw {
namespace {

constexpr double kAspect = 4.0 / 3.0;

struct Case {
    const char* name;
    std::vector<std::string> overrides;
};

struct RegionCase {
    Scene scene;
    passes::CausticMapFrame frame;
    passes::CausticReadRegion region;
    std::unique_ptr<WaterSurface> surface;
};

RegionCase prepare(const Case& c) {
    RegionCase s{load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json", c.overrides), {}, {}, {}};
    const Water& water = *s.scene.water;
    const double amplitude = water_bounds(s.scene).hi.y - water.level;
    // The caustic inputs the renderer fits its map from (passes/frame/renderer.cpp).
    passes::CausticInputs caustics;
    caustics.grid_resolution = water.grid_resolution;
    caustics.water_level = water.level;
    caustics.half_extent = water.half_extent;
    caustics.max_amplitude = amplitude;
    caustics.sun_direction = s.scene.sun.direction;
    caustics.ior = water.ior;
    caustics.floor_height = s.scene.floor.height;
    caustics.kernel = s.scene.effects.caustics.kernel;
    caustics.map_width = caustics.map_height = water.grid_resolution + 2;
    s.frame = passes::fit_caustic_map(caustics);
    s.region = passes::caustic_read_region(
        s.frame,
        caustic_read_inputs(s.scene, kAspect, decide_frame_needs(s.scene, kAspect), amplitude, s.scene.floor.height));
    s.surface = make_surface(water.waves, water.level, water.time);
    return s;
}

glm::dvec2 texel_coordinates(const RegionCase& s, const glm::dvec3& p) {
    const glm::dvec2 at_level = glm::dvec2(p.x, p.z) + (p.y - s.scene.water->level) * s.frame.shear;
    return (at_level - s.frame.corner) / s.frame.texel;
}

// True when the bilinear look-up at p (caustic_lookup.glsl: texels floor(c - 0.5) and the next)
// reads only texels inside the region, or off the map.
bool lookup_inside(const RegionCase& s, const glm::dvec3& p) {
    const glm::dvec2 c = texel_coordinates(s, p) - 0.5;
    for (int k = 0; k < 4; ++k) {
        const double x = std::floor(c.x) + (k & 1), y = std::floor(c.y) + (k >> 1);
        if (x < 0 || y < 0 || x >= s.frame.width || y >= s.frame.height) continue;
        const passes::CausticTexelSpan& span = s.region.rows[static_cast<size_t>(y)];
        if (x < span.x0 || x >= span.x1) return false;
    }
    return true;
}

std::optional<glm::dvec3> refract(const glm::dvec3& d, const glm::dvec3& n, double eta) {
    const double cos_i = -glm::dot(d, n), k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (k < 0.0) return std::nullopt;
    return glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
}

class CausticReadRegion : public ::testing::TestWithParam<Case> {};

TEST_P(CausticReadRegion, HoldsEveryTexelTheViewReads) {
    const RegionCase s = prepare(GetParam());
    ASSERT_TRUE(s.region.bounded) << s.region.note;
    const Water& water = *s.scene.water;
    const double amplitude = water_bounds(s.scene).hi.y - water.level, floor_y = s.scene.floor.height;
    const glm::dmat4 inverse = glm::inverse(projection_matrix(s.scene.camera, kAspect) * view_matrix(s.scene.camera));
    int refracted = 0, direct = 0;
    constexpr int kColumns = 64, kRows = 48;
    for (int j = 0; j <= kRows; ++j) {
        for (int i = 0; i <= kColumns; ++i) {
            const glm::dvec2 ndc(-1.0 + 2.0 * i / kColumns, -1.0 + 2.0 * j / kRows);
            const glm::dvec4 near = inverse * glm::dvec4(ndc, 1.0, 1.0), far = inverse * glm::dvec4(ndc, 0.5, 1.0);
            const glm::dvec3 origin = glm::dvec3(near) / near.w;
            const glm::dvec3 d = glm::normalize(glm::dvec3(far) / far.w - origin);
            if (d.y >= 0.0) continue;
            // The slab level +- amplitude, where the first intersection lies; marched in 1500
            // steps (the slab's chord is at most a few metres and the shortest wavelength 0.5 m:
            // steps of a few mm, far finer than a crest) and bisected.
            const double t0 = (water.level + amplitude - origin.y) / d.y,
                         t1 = (water.level - amplitude - origin.y) / d.y;
            auto above = [&](double t) {
                const glm::dvec3 p = origin + t * d;
                return p.y > s.surface->height_at(p.x, p.z);
            };
            std::optional<double> hit;
            constexpr int kSteps = 1500;
            for (int k = 0; k < kSteps && !hit; ++k) {
                double a = t0 + (t1 - t0) * k / kSteps, b = t0 + (t1 - t0) * (k + 1) / kSteps;
                const glm::dvec3 pb = origin + b * d;
                if (std::abs(pb.x) > water.half_extent || std::abs(pb.z) > water.half_extent) continue;
                if (above(a) && !above(b)) {
                    for (int n = 0; n < 60; ++n) (above(0.5 * (a + b)) ? a : b) = 0.5 * (a + b);
                    hit = 0.5 * (a + b);
                }
            }
            if (hit) {
                const glm::dvec3 entry = origin + *hit * d;
                const SurfacePoint point = s.surface->at_parameter(s.surface->parameter_at(entry.x, entry.z).x,
                                                                   s.surface->parameter_at(entry.x, entry.z).y);
                const std::optional<glm::dvec3> t = refract(d, point.normal, 1.0 / water.ior);
                ASSERT_TRUE(t && t->y < 0.0);
                const glm::dvec3 on_floor = entry + *t * ((entry.y - floor_y) / -t->y);
                EXPECT_TRUE(lookup_inside(s, on_floor))
                    << "pixel " << i << ", " << j << " refracted to " << on_floor.x << ", " << on_floor.z;
                ++refracted;
            } else {
                const glm::dvec3 on_floor = origin + d * ((floor_y - origin.y) / d.y);
                EXPECT_TRUE(lookup_inside(s, on_floor))
                    << "pixel " << i << ", " << j << " straight to " << on_floor.x << ", " << on_floor.z;
                ++direct;
            }
        }
    }
    // The samples must have tested the bound: most of the view sees the floor through the water.
    EXPECT_GT(refracted, kColumns * kRows / 4) << direct;
}

TEST_P(CausticReadRegion, EveryPhotonLandsWithinItsSpread) {
    const RegionCase s = prepare(GetParam());
    ASSERT_TRUE(s.region.bounded && std::isfinite(s.region.photon_spread)) << s.region.note;
    const Water& water = *s.scene.water;
    const glm::dvec3 sun = s.scene.sun.direction;
    double widest = 0.0;
    constexpr int kCells = 160;
    for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) {
            const glm::dvec2 at = water.half_extent * (glm::dvec2(i + 0.5, j + 0.5) / (0.5 * kCells) - 1.0);
            const SurfacePoint point = s.surface->at_parameter(at.x, at.y);
            const std::optional<glm::dvec3> t = refract(sun, point.normal, 1.0 / water.ior);
            ASSERT_TRUE(t && t->y < 0.0);
            const glm::dvec3 landing = point.position + *t * ((point.position.y - s.scene.floor.height) / -t->y);
            const glm::dvec2 moved =
                glm::abs(texel_coordinates(s, landing) - texel_coordinates(s, {at.x, water.level, at.y})) *
                s.frame.texel;
            widest = std::max({widest, moved.x, moved.y});
            EXPECT_LE(moved.x, s.region.photon_spread) << i << ", " << j;
            EXPECT_LE(moved.y, s.region.photon_spread) << i << ", " << j;
        }
    }
    // A bound that holds only because it is huge would not cull: it is below the water's half
    // extent (for the sines within 20x of the widest landing seen; the Gerstner terms' 1 / (1 -
    // sum s) loosens it further).
    EXPECT_LT(s.region.photon_spread, water.half_extent) << widest;
    EXPECT_GT(widest, 0.0);
}

// pool as it is culls a share of its map: a region that held every texel would pass the tests above.
TEST(CausticReadRegionShare, PoolLeavesOutTexelsTheViewCannotRead) {
    const RegionCase s = prepare({"pool", {}});
    uint64_t read = 0;
    for (const passes::CausticTexelSpan& span : s.region.rows) read += span.x1 - span.x0;
    const double share = double(read) / (double(s.frame.width) * s.frame.height);
    EXPECT_LT(share, 0.75) << s.region.note;
    EXPECT_GT(share, 0.2) << s.region.note;
}

// The region for several cameras (the sub-frames of a supersampled frame, which share one map)
// holds each camera's own region, and, for cameras that look at different parts of the pool, more
// than either.
TEST(CausticReadRegionShare, SeveralCamerasReadTheUnionOfTheirRegions) {
    const RegionCase s = prepare({"pool", {}});
    const double amplitude = water_bounds(s.scene).hi.y - s.scene.water->level;
    auto inputs = [&](const glm::dvec2& shift) {
        Scene shifted = s.scene;
        shifted.camera.image_shift_ndc = shift;
        return caustic_read_inputs(shifted, kAspect, decide_frame_needs(shifted, kAspect), amplitude,
                                   s.scene.floor.height);
    };
    // Half the screen to the left and to the right: each sees a part of the floor the other does not.
    const passes::CausticReadRegion left = passes::caustic_read_region(s.frame, inputs({-1.0, 0.0}));
    const passes::CausticReadRegion right = passes::caustic_read_region(s.frame, inputs({1.0, 0.0}));
    passes::CausticReadInputs both = inputs({-1.0, 0.0});
    both.more_views = {inputs({1.0, 0.0}).view_proj};
    const passes::CausticReadRegion region = passes::caustic_read_region(s.frame, both);
    ASSERT_TRUE(left.bounded && right.bounded && region.bounded);
    uint64_t only_left = 0, only_right = 0, missed = 0;
    for (size_t row = 0; row < region.rows.size(); ++row) {
        for (uint32_t x = 0; x < s.frame.width; ++x) {
            auto in = [&](const passes::CausticReadRegion& r) { return x >= r.rows[row].x0 && x < r.rows[row].x1; };
            if ((in(left) || in(right)) && !in(region)) ++missed;
            if (in(left) && !in(right)) ++only_left;
            if (in(right) && !in(left)) ++only_right;
        }
    }
    EXPECT_EQ(missed, 0u);
    EXPECT_GT(only_left, 0u);
    EXPECT_GT(only_right, 0u);
}

INSTANTIATE_TEST_SUITE_P(Cameras, CausticReadRegion,
                         ::testing::Values(Case{"pool", {}},
                                           Case{"oblique_near_the_surface",
                                                {"camera.position=[3, 0.12, 6]", "camera.target=[-2, 0.02, -8]"}},
                                           Case{"steep_from_a_corner",
                                                {"camera.position=[9, 4, 9]", "camera.target=[2, -1.5, 2]"}},
                                           Case{"gerstner_low_sun",
                                                {"water.waves.components[0].steepness=0.3",
                                                 "water.waves.components[1].steepness=0.3", "sun.elevation_deg=35"}}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace vkw
