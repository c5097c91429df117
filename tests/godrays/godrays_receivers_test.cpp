// Receiver meshes under the water end the godray beams where they end the caustic photons
// (godray_beams.comp with the sun shadow map's beam half). A slab 1 m under flat water covering the
// whole surface: a camera 2 m down looking level sees no beam at all (its view never rises to the
// slab), so every pixel is black; without the slab the same view is section 6's in-scatter.
#include "tests/godrays/godrays_support.hpp"
#include "tests/support/gpu_test.hpp"

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 7;
constexpr const char* kCamera =
    R"({"position": [0, -2, 0], "direction": [-1, 0, 0], "fov_y_deg": 10, "near": 0.01, "far": 100})";
constexpr const char* kMedium = R"({"sigma_a": [0.9, 0.3, 0.1], "sigma_s": [0.3, 0.5, 0.8], "g": 0.5})";
// 10 m square and 10 cm thick, its underside 1.05 m below the surface: every beam that enters the
// 8 m water meets it; the view's highest ray rises 4 m x tan(5 degrees) = 0.35 m over its 4 m in
// the water, to 1.65 m below the surface, under the slab.
constexpr const char* kSlab =
    R"(receivers=[{"type": "box", "half_size": [5, 0.05, 5], "translation": [0, -1, 0], "albedo": [0, 0, 0]}])";

using godrays_receivers = GpuTest;

TEST_F(godrays_receivers, SlabUnderTheWaterEndsTheBeams) {
    const std::vector<std::string> overrides = {"effects.godrays.grid=64"};
    std::vector<std::string> with_slab = overrides;
    with_slab.push_back(kSlab);
    const RenderResult open = render_godrays(context(), godray_scene(kCamera, kMedium, overrides), kSize, kSize);
    const RenderResult covered = render_godrays(context(), godray_scene(kCamera, kMedium, with_slab), kSize, kSize);
    for (int c = 0; c < 3; ++c) {
        // The open water's in-scatter is there (what the slab must remove)...
        ASSERT_GT(open.image.pixel(3, 3)[c], 0.0f) << "channel " << c;
        for (int y = 0; y < int(kSize); ++y) {
            for (int x = 0; x < int(kSize); ++x) {
                // ...and under the slab no beam reaches any ray: exactly nothing is deposited.
                EXPECT_EQ(covered.image.pixel(x, y)[c], 0.0f) << "pixel " << x << "," << y << " channel " << c;
            }
        }
    }
}

}  // namespace
}  // namespace vkw::test
