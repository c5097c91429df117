// The window's display transform on the device (passes/present_tonemap) against the PNG
// preview's chain on the CPU (engine/image/tone_curve.hpp: exposure, ACES fit, sRGB, 8 bits),
// texel by texel, over a frame whose radiance spans the curve's every branch: the sRGB linear
// segment, the curve, the clamp past x = 7.24 and the sun's disk (about 1.5e4). The frame is
// the renderer's own, ended through the FrameOutput hook the window uses.
#include "passes/present/present_tonemap.hpp"
#include "engine/image/tone_curve.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/present/readback.hpp"
#include "tests/support/gpu_test.hpp"

#include <cmath>
#include <cstring>

namespace vkw::test {
namespace {

using PresentTonemap = GpuTest;

TEST_F(PresentTonemap, MatchesThePngPreviewChainWithinOneLevel) {
    // Camera toward a low sun: its disk, a bright horizon, a dim zenith and a dark ground.
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 1, 0], "direction": [0, 0.15, -1], "fov_y_deg": 70, "exposure": 1.7},
      "sun": {"elevation_deg": 8, "azimuth_deg": 0, "irradiance": [1, 1, 1]},
      "sky": {"model": "gradient", "zenith": [0.0005, 0.02, 0.3], "horizon": [6, 2, 0.5],
              "ground": [0.0002, 0.001, 0.004], "exponent": 0.7},
      "floor": {"height": -100, "half_extent": 1}
    })",
                                    "tonemap_sky.json");
    const uint32_t width = 96, height = 64;
    for (const VkFormat format : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB}) {
        SCOPED_TRACE(format == VK_FORMAT_R8G8B8A8_UNORM ? "UNORM: the shader encodes sRGB" : "SRGB: the hardware does");
        const passes::PresentTonemapSettings settings{1.7f, format == VK_FORMAT_R8G8B8A8_UNORM};
        Image display(context(),
                      {width, height, format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                      "display");
        Buffer display_bytes(context(), {VkDeviceSize{width} * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
                             "display readback");
        Buffer hdr_bytes(context(), {VkDeviceSize{width} * height * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
                         "HDR readback");
        const FrameOutput output{[&](fg::FrameGraph& graph, fg::ImageHandle hdr) {
            fg::ImportedImage target{display.handle(), display.view(), width, height, format};
            fg::ImageHandle shown = graph.import_image("display", target);
            shown = passes::add_present_tonemap_pass(graph, hdr, shown, &settings);
            passes::add_readback_pass(graph, shown, display_bytes.handle(), display_bytes.size(), "display readback");
            passes::add_readback_pass(graph, hdr, hdr_bytes.handle(), hdr_bytes.size(), "HDR readback");
        }};
        Renderer renderer(context());
        renderer.prepare_frame(scene, {width, height, false, fg::TimingMode::None}, output).execute();

        const auto* shown = static_cast<const uint8_t*>(display_bytes.mapped());
        const auto* hdr = static_cast<const float*>(hdr_bytes.mapped());
        int linear_segment = 0, clamped = 0, exact = 0;
        for (size_t i = 0; i < size_t{width} * height; ++i) {
            for (int c = 0; c < 3; ++c) {
                const float exposed = hdr[4 * i + c] * settings.exposure;
                const int expected = tonemap_to_srgb8(exposed);
                // One level: Vulkan lets a float-to-UNORM (and sRGB) conversion take either
                // neighbouring integer ("round to nearest" is only recommended), and the
                // shader's fp32 pow() is a few ulp from the CPU's, which moves a value lying
                // within that of a .5 boundary to the other side.
                EXPECT_NEAR(int(shown[4 * i + c]), expected, 1)
                    << "texel " << i << " channel " << c << ", radiance " << hdr[4 * i + c];
                exact += int(shown[4 * i + c]) == expected;
                linear_segment += aces_narkowicz(exposed) <= 0.0031308f && exposed > 0.0f;
                clamped += exposed > 7.25f;
            }
        }
        EXPECT_GT(linear_segment, 0) << "the frame must reach the sRGB linear segment";
        EXPECT_GT(clamped, 0) << "the frame must reach the curve's clamp";
        RecordProperty(format == VK_FORMAT_R8G8B8A8_UNORM ? "exact_unorm" : "exact_srgb", exact);
    }
}

}  // namespace
}  // namespace vkw::test
