// The godrays where numbers break (docs/model.md section 8): a grazing sun, the sun overhead, a camera
// in the water looking toward the sun (the beams seen end-on, the singular case of the line
// estimate), and optical depths sigma_t x depth from 1e-6 to 1e3, with both methods. Every pass's
// float targets are scanned for NaN/Inf (the frame graph's finite check), and every pixel must be
// non-negative: in-scatter only ever adds light.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 24;
constexpr uint32_t kHeight = 16;

struct SunAndCamera {
    const char* name;
    std::vector<std::string> overrides;
};

// The pool is 1.5 m deep; scattering albedo 1/2, so sigma_t = 2 sigma_s.
std::vector<std::string> optical_depth(double tau) {
    const double sigma_t = tau / 1.5;
    const std::string half = std::to_string(sigma_t / 2.0);
    return {"medium.preset=null", "medium.sigma_a=[" + half + "," + half + "," + half + "]",
            "medium.sigma_s=[" + half + "," + half + "," + half + "]", "medium.g=0.9"};
}

using godrays_extremes = GpuTest;

TEST_F(godrays_extremes, FiniteAndNonNegative) {
    const std::vector<SunAndCamera> cases = {
        {"grazing sun", {"sun.elevation_deg=1"}},
        {"sun overhead", {"sun.elevation_deg=90"}},
        // Under the water looking up the refracted beam (sun at elevation 60, azimuth 30).
        {"looking toward the sun from below",
         {"sun.elevation_deg=60", "camera.position=[0, -1.2, 0]", "camera.target=null",
          "camera.direction=[0.1875, 0.927, -0.325]"}},
    };
    Renderer renderer(context());
    for (const SunAndCamera& sun_and_camera : cases) {
        for (const double tau : {1e-6, 1e-3, 1.0, 1e3}) {
            for (const char* method : {"lines", "marched"}) {
                std::vector<std::string> overrides = {"water.grid_resolution=32", "effects.godrays.grid=32",
                                                      "effects.godrays.mode=on",
                                                      std::string("effects.godrays.method=") + method};
                for (const std::string& o : sun_and_camera.overrides) overrides.push_back(o);
                for (const std::string& o : optical_depth(tau)) overrides.push_back(o);
                const Scene scene =
                    load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json", overrides);
                SCOPED_TRACE(std::string(sun_and_camera.name) + ", optical depth " + std::to_string(tau) + ", " +
                             method);
                RenderResult result;
                ASSERT_NO_THROW(result = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None}));
                size_t negative = 0;
                for (const float value : result.image.rgba) negative += std::isfinite(value) && value >= 0.0f ? 0 : 1;
                EXPECT_EQ(negative, 0u);
            }
        }
    }
}

}  // namespace
}  // namespace vkw::test
