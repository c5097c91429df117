// The hand-written mirrors of GLSL blocks in passes/ against the generated ones of the shaders that
// declare those blocks: the same size, and each member at the same offset. Until the passes use the
// generated structs, a drift between a hand mirror and its shader fails here.
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/receivers/receiver_draws.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/water_surface_draw.hpp"

#include <shader_structs/caustics/caustic_photons.comp.hpp>
#include <shader_structs/caustics/caustic_probe.comp.hpp>
#include <shader_structs/receivers/receiver.frag.hpp>
#include <shader_structs/water/water_surface.frag.hpp>

#include <gtest/gtest.h>

#include <cstddef>

namespace vkw::test {
namespace {

namespace water_frag = vkw::glsl::water_surface_frag;
namespace receiver_frag = vkw::glsl::receiver_frag;
namespace photons_comp = vkw::glsl::caustic_photons_comp;
namespace probe_comp = vkw::glsl::caustic_probe_comp;

// The same member in both structs (the hand mirror's names are the GLSL names) at the same offset.
#define EXPECT_SAME_OFFSET(Hand, Generated, member) \
    EXPECT_EQ(offsetof(Hand, member), offsetof(Generated, member)) << #member

// water/water_surface_params.glsl's push block: 17 scalars and a vec4, 80 bytes.
TEST(HandMirrors, WaterSurfacePushIsWaterSurfaceFragParams) {
    using Hand = vkw::passes::WaterSurfacePush;
    using Generated = water_frag::Params;
    EXPECT_EQ(sizeof(Hand), sizeof(Generated));
    EXPECT_EQ(sizeof(Generated), 80u);
    EXPECT_SAME_OFFSET(Hand, Generated, mesh_resolution);
    EXPECT_SAME_OFFSET(Hand, Generated, reflection_steps);
    EXPECT_SAME_OFFSET(Hand, Generated, refraction_steps);
    EXPECT_SAME_OFFSET(Hand, Generated, scene_size);
    EXPECT_SAME_OFFSET(Hand, Generated, shallow_blend);
    EXPECT_SAME_OFFSET(Hand, Generated, fresnel_power);
    EXPECT_SAME_OFFSET(Hand, Generated, blend_k);
    EXPECT_SAME_OFFSET(Hand, Generated, refine_steps);
    EXPECT_SAME_OFFSET(Hand, Generated, water_colour);
    EXPECT_SAME_OFFSET(Hand, Generated, level);
    EXPECT_SAME_OFFSET(Hand, Generated, half_extent);
    EXPECT_SAME_OFFSET(Hand, Generated, wave_count);
    EXPECT_SAME_OFFSET(Hand, Generated, ocean_n);
    EXPECT_SAME_OFFSET(Hand, Generated, nodes_per_metre);
    EXPECT_SAME_OFFSET(Hand, Generated, mesh_sag);
    EXPECT_SAME_OFFSET(Hand, Generated, bottom_y);
    EXPECT_SAME_OFFSET(Hand, Generated, amplitude);
}

// receivers/sun_shadow.glsl's uniform block: the hand mirror groups each (mat4, vec4) pair as a
// ShadowProjection; 160 bytes.
TEST(HandMirrors, SunShadowSpaceIsTheSunShadowSpaceBlock) {
    using Hand = vkw::passes::SunShadowSpace;
    using Projection = vkw::passes::ShadowProjection;
    using Generated = water_frag::SunShadowSpace;
    EXPECT_EQ(sizeof(Hand), sizeof(Generated));
    EXPECT_EQ(sizeof(Generated), 160u);
    EXPECT_EQ(offsetof(Hand, sun) + offsetof(Projection, light_from_world), offsetof(Generated, light_from_world));
    EXPECT_EQ(offsetof(Hand, sun) + offsetof(Projection, params), offsetof(Generated, params));
    EXPECT_EQ(offsetof(Hand, beam) + offsetof(Projection, light_from_world), offsetof(Generated, beam_from_world));
    EXPECT_EQ(offsetof(Hand, beam) + offsetof(Projection, params), offsetof(Generated, beam_params));
    // The same block, generated from another shader that includes sun_shadow.glsl.
    EXPECT_EQ(sizeof(receiver_frag::SunShadowSpace), sizeof(Hand));
}

// caustics/caustic_light_space.glsl's struct, in the photon kernels' push block (std430) and in
// the caustic map's uniform block (std140): four vec4, 64 bytes in both.
TEST(HandMirrors, CausticLightSpacePushIsCausticLightSpace) {
    using Hand = vkw::passes::CausticLightSpacePush;
    for (const size_t generated_size : {sizeof(photons_comp::CausticLightSpace), sizeof(probe_comp::CausticLightSpace),
                                        sizeof(probe_comp::CausticMapBlock)}) {
        EXPECT_EQ(sizeof(Hand), generated_size);
    }
    EXPECT_SAME_OFFSET(Hand, photons_comp::CausticLightSpace, origin);
    EXPECT_SAME_OFFSET(Hand, photons_comp::CausticLightSpace, u_axis);
    EXPECT_SAME_OFFSET(Hand, photons_comp::CausticLightSpace, v_axis);
    EXPECT_SAME_OFFSET(Hand, photons_comp::CausticLightSpace, sun);
    EXPECT_SAME_OFFSET(Hand, probe_comp::CausticLightSpace, origin);
    EXPECT_SAME_OFFSET(Hand, probe_comp::CausticLightSpace, sun);

    // What every photon kernel's push block begins with: the light space, E_s / LSB and sigma_t.
    using Source = vkw::passes::CausticPhotonSourcePush;
    EXPECT_EQ(sizeof(Source), sizeof(photons_comp::CausticPhotonSource));
    EXPECT_SAME_OFFSET(Source, photons_comp::CausticPhotonSource, space);
    EXPECT_SAME_OFFSET(Source, photons_comp::CausticPhotonSource, deposit_scale);
    EXPECT_SAME_OFFSET(Source, photons_comp::CausticPhotonSource, sigma_t);
    EXPECT_EQ(offsetof(photons_comp::Push, source), 0u);
    // The photon kernel's push block fills the 128 bytes every device supports.
    EXPECT_EQ(sizeof(photons_comp::Push), 128u);
}

}  // namespace
}  // namespace vkw::test
