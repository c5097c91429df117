// The structs many shaders share (shaders/common/shared_blocks.comp) are one C++ type in every
// shader's generated header, so that one value fills the same block of each; and the blocks the
// passes push have the sizes the passes rely on.
#include <shader_structs/caustics/caustic_camera_splats.comp.hpp>
#include <shader_structs/caustics/caustic_photons.comp.hpp>
#include <shader_structs/caustics/caustic_probe.comp.hpp>
#include <shader_structs/common/shared_blocks.comp.hpp>
#include <shader_structs/godrays/godray_beams.comp.hpp>
#include <shader_structs/receivers/receiver.frag.hpp>
#include <shader_structs/water/ocean_grid.comp.hpp>
#include <shader_structs/water/water_surface.frag.hpp>
#include <shader_structs/water/wave_sum.comp.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <type_traits>

namespace vkw::test {
namespace {

namespace shared = vkw::glsl::shared_blocks_comp;

// Each shared struct, as every header that declares it names it, is the shared type itself.
static_assert(std::is_same_v<glsl::water_surface_frag::SunShadowSpace, shared::SunShadowSpace>);
static_assert(std::is_same_v<glsl::receiver_frag::SunShadowSpace, shared::SunShadowSpace>);
static_assert(std::is_same_v<glsl::caustic_photons_comp::SunShadowSpace, shared::SunShadowSpace>);
static_assert(std::is_same_v<glsl::caustic_photons_comp::CausticPhotonSource, shared::CausticPhotonSource>);
static_assert(std::is_same_v<glsl::caustic_camera_splats_comp::CausticPhotonSource, shared::CausticPhotonSource>);
static_assert(std::is_same_v<glsl::caustic_probe_comp::CausticLightSpace, shared::CausticLightSpace>);
static_assert(std::is_same_v<glsl::wave_sum_comp::WaterGrid, shared::WaterGrid>);
static_assert(std::is_same_v<glsl::ocean_grid_comp::WaterGrid, shared::WaterGrid>);
static_assert(std::is_same_v<glsl::water_surface_frag::FrameConstants, shared::FrameConstants>);
static_assert(std::is_same_v<glsl::godray_beams_comp::FrameConstants, shared::FrameConstants>);

// receivers/sun_shadow.glsl's uniform block: two (mat4, vec4) projections, 160 bytes in std140.
TEST(SharedStructs, SunShadowSpaceIsTwoProjections) {
    EXPECT_EQ(sizeof(shared::ShadowProjection), 80u);
    EXPECT_EQ(sizeof(shared::SunShadowSpace), 160u);
    EXPECT_EQ(offsetof(shared::SunShadowSpace, beam), 80u);
    EXPECT_EQ(offsetof(shared::ShadowProjection, params), 64u);
}

// The caustic light space is four vec4 in the photon kernels' push blocks (std430) and in the
// caustic map's uniform block (std140) alike; every photon kernel's push block begins with the
// photon source and fills the 128 bytes every device supports.
TEST(SharedStructs, PhotonPushBlocksBeginWithTheSourceAndFill128Bytes) {
    EXPECT_EQ(sizeof(shared::CausticLightSpace), 64u);
    EXPECT_EQ(sizeof(glsl::caustic_probe_comp::CausticMapBlock), 64u);
    EXPECT_EQ(sizeof(shared::CausticPhotonSource), 96u);
    EXPECT_EQ(offsetof(glsl::caustic_photons_comp::Push, source), 0u);
    EXPECT_EQ(offsetof(glsl::caustic_camera_splats_comp::Push, source), 0u);
    EXPECT_EQ(sizeof(glsl::caustic_photons_comp::Push), 128u);
    EXPECT_EQ(sizeof(glsl::caustic_camera_splats_comp::Push), 128u);
}

// Every water grid kernel's push block begins with the grid, which dispatch_water_grid fills per band.
TEST(SharedStructs, WaterGridKernelsBeginWithTheGrid) {
    EXPECT_EQ(sizeof(shared::WaterGrid), 20u);
    EXPECT_EQ(offsetof(glsl::wave_sum_comp::Params, grid), 0u);
    EXPECT_EQ(offsetof(glsl::ocean_grid_comp::Params, grid), 0u);
}

}  // namespace
}  // namespace vkw::test
