// CPU-only checks of the caustic passes' layout: the light-space basis stays finite and
// orthonormal for a sun exactly overhead, and every binding and dispatch respects lavapipe's
// limits (128 MiB per storage-buffer binding, 65535 groups per dimension) at the largest sizes.
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/water/water_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vkw::test {
namespace {

constexpr VkDeviceSize kRange = VkDeviceSize{128} << 20, kAlignment = 16;

TEST(caustics_layout, BasisIsFiniteAndOrthonormalForEverySun) {
    for (const glm::dvec3 s :
         {glm::dvec3(0, -1, 0), glm::dvec3(0, -1, -0.0), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, -1, 0)),
          glm::normalize(glm::dvec3(0.3, -1, -1e-12)), glm::normalize(glm::dvec3(0, 0, -1))}) {
        glm::dvec3 u, v;
        passes::branchless_basis(s, u, v);
        EXPECT_NEAR(glm::length(u), 1.0, 1e-14);
        EXPECT_NEAR(glm::length(v), 1.0, 1e-14);
        EXPECT_NEAR(glm::dot(u, v), 0.0, 1e-14);
        EXPECT_NEAR(glm::dot(u, s), 0.0, 1e-14);
        EXPECT_NEAR(glm::dot(v, s), 0.0, 1e-14);
    }
    glm::dvec3 u, v;
    passes::branchless_basis({0, -1, 0}, u, v);
    EXPECT_EQ(u, glm::dvec3(1, 0, 0));
    EXPECT_EQ(v, glm::dvec3(0, 0, 1));
}

TEST(caustics_layout, MapFitStaysFiniteAtTheHorizon) {
    for (const double zenith : {0.0, 60.0, 89.0, 89.999, 90.0, 91.0, 180.0}) {
        passes::CausticInputs in;
        const double a = zenith * 3.14159265358979323846 / 180.0;
        in.sun_direction = glm::normalize(glm::dvec3(std::sin(a), -std::cos(a), 0.0));
        const passes::CausticMapFrame f = passes::fit_caustic_map(in);
        EXPECT_TRUE(std::isfinite(f.texel_area) && f.texel_area > 0.0) << zenith;
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(f.lsb[c]) && f.lsb[c] > 0.0) << zenith;
        // LSB at most 1e-9 of the flat texel flux where the sun is up and the int64 headroom allows.
        if (zenith <= 60.0) {
            EXPECT_LE(f.lsb.x, 1e-9 * f.flat_texel_flux.x * (1 + 1e-12)) << zenith;
        }
    }
}

// The map holds the read texels' rectangle alone only when asked (the blur reads around every
// texel) and when there is one; a rectangle reaching past the map is clipped to it. The rest of
// the frame (lattice, size, LSB) does not move: the photons land on the same texels either way.
TEST(caustics_layout, TheMapHoldsTheReadTexelsOnlyWhenAskedAndBounded) {
    passes::CausticInputs in;
    in.map_width = in.map_height = 66;
    const passes::CausticMapFrame whole = passes::fit_caustic_map(in);
    const passes::CausticTexelRect all{0, 0, whole.width, whole.height};
    EXPECT_EQ(whole.held, all);
    in.read_texels = passes::CausticReadTexels{{5, 7, 40, 30}, nullptr, 0.0};
    EXPECT_EQ(passes::fit_caustic_map(in).held, all);  // not asked
    in.hold_read_texels_only = true;
    passes::CausticMapFrame held = passes::fit_caustic_map(in);
    EXPECT_EQ(held.held, (passes::CausticTexelRect{5, 7, 40, 30}));
    held.held = all;
    EXPECT_EQ(held, whole);
    in.read_texels->bounds = {60, 0, 90, 200};
    EXPECT_EQ(passes::fit_caustic_map(in).held, (passes::CausticTexelRect{60, 0, whole.width, whole.height}));
    in.read_texels.reset();
    EXPECT_EQ(passes::fit_caustic_map(in).held, all);  // asked, but nothing bounds the reads
}

TEST(caustics_layout, BandsRespectTheBindingAndGroupLimits) {
    // The flux map at 16384^2 (6 GiB: more than lavapipe's heap, but the bands must still fit).
    for (const uint32_t side : {64u, 2364u, 2365u, 4096u, 16384u}) {
        const auto bands = passes::row_bands(side, VkDeviceSize{side} * passes::kCausticTexelBytes,
                                             passes::kCausticFluxHeaderBytes, 0, kRange, kAlignment, side);
        uint32_t next = 0;
        for (const passes::RowBand& b : bands) {
            EXPECT_EQ(b.first, next);
            EXPECT_LE(b.bytes, kRange);
            EXPECT_EQ(b.offset % kAlignment, 0u);
            EXPECT_LE((b.rows + 7) / 8, 65535u);
            next += b.rows;
        }
        EXPECT_EQ(next, side);
    }
    // Vertex chunks of the photon pass for R = 16384 and S = 4: one extra vertex row each.
    for (const uint32_t sub : {1u, 4u}) {
        const uint32_t r = 16384;
        const auto chunks = passes::row_bands(r, VkDeviceSize{r + 1} * passes::kWaterVertexBytes, 0, 1, kRange,
                                              kAlignment, 65535 * 8 / sub);
        uint32_t next = 0;
        for (const passes::RowBand& b : chunks) {
            EXPECT_EQ(b.first, next);
            EXPECT_LE(b.bytes, kRange);
            EXPECT_EQ(b.offset % kAlignment, 0u);
            EXPECT_LE((b.rows * sub + 7) / 8, 65535u);
            EXPECT_LE((r * sub + 7) / 8, 65535u);
            next += b.rows;
        }
        EXPECT_EQ(next, r);
    }
}

}  // namespace
}  // namespace vkw::test
