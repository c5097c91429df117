// The frame's output at the edges: a caustic peak of 1e6 W m^-2 sr^-1 written to a
// half-float EXR (clamped to 65504 and counted, the rest to half precision), and a NaN injected
// into one texel of the HDR target, which the finite check must name by pass, resource and texel.
#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/image/exr_io.hpp"
#include "passes/present/readback.hpp"
#include "tests/extreme/extreme_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstring>
#include <filesystem>

namespace vkw::test {
namespace {

using extreme_output = GpuTest;

TEST_F(extreme_output, MillionCausticPeakInAHalfFloatExr) {
    // The pool's sine pair (lambda 0.5 m, A 0.017 m: first cusp 1.47 m down for a vertical sun)
    // with the floor at the cusp, a vertical sun of 1e6 W m^-2 and a 512-cell grid (43 cells per
    // wavelength): the focal lines' texels reach well past 1e6 W m^-2 sr^-1 of floor radiance.
    const Scene scene = extreme_scene(
        {"sun.elevation_deg=90", "sun.irradiance=[1e6, 1e6, 1e6]", "floor.height=-1.47", "water.grid_resolution=512",
         R"(water.waves={"model":"sum","components":[{"amplitude":0.017,"wavelength":0.5},)"
         R"({"amplitude":0.017,"wavelength":0.5,"direction_deg":90,"phase_deg":90}]})"});
    Renderer renderer(context());
    const ImageRGBA32F image = render_real_time(renderer, scene);
    expect_finite_non_negative(image, "1e6 caustic peak");
    expect_receiver_flux_bounded(run_scene_caustics(context(), scene), scene, "1e6 caustic peak");
    float peak = 0.0f;
    size_t above_half = 0;
    for (const float v : image.rgba) {
        peak = std::max(peak, v);
        above_half += std::fabs(v) > 65504.0f;
    }
    std::printf("peak radiance %.4g, %zu values above 65504\n", peak, above_half);
    ASSERT_GE(peak, 1e6f) << "the case must exercise a peak of at least 1e6";

    const std::filesystem::path path = std::filesystem::path(VKWATER_BINARY_DIR) / "tests/extreme/peak_half.exr";
    const ExrWriteReport report = write_exr(path, image, ExrPixelType::Half);
    EXPECT_EQ(report.clamped_values, above_half);
    EXPECT_EQ(report.nonfinite_values, 0u);
    const ImageRGBA32F back = read_exr(path);
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    size_t wrong = 0;
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        const float v = image.rgba[i], h = back.rgba[i];
        // Beyond 65504: exactly 65504. Below: rounded to the nearest half, 2^-11 relative for
        // normal halves (|v| >= 2^-14), 2^-25 absolute (half a subnormal step) below.
        const bool ok = std::fabs(v) > 65504.0f
                            ? h == 65504.0f
                            : std::fabs(h - v) <= std::max(std::ldexp(std::fabs(v), -11), std::ldexp(1.0f, -25));
        wrong += !ok;
    }
    EXPECT_EQ(wrong, 0u);
}

// One NaN (green channel) into texel (17, 5) of the HDR colour, by a graphics pass that loads the
// target (so it depends on everything drawn before; a transfer write would declare the old
// contents dead and cull their passes) and clears a one-texel rectangle to (0.25, NaN, 0.25, 1)
// with vkCmdClearAttachments, declared after the water pass and before the readback. The blur
// does not exist yet: today the readback is the last pass that reads an HDR target, so the NaN
// goes right before it. When the blur comes, this injection belongs before the blur, and the
// no-spreading check below becomes the blur's test (docs/model.md section 8: sanitise at the producer).
constexpr int kNanX = 17, kNanY = 5;

FrameOutput nan_then_readback(VkBuffer readback) {
    return {[readback](fg::FrameGraph& graph, fg::ImageHandle hdr) {
        struct Data {
            fg::ImageHandle hdr;
        };
        const auto& data = graph.add_pass<Data>(
            "inject NaN", fg::PassKind::Graphics,
            [&](fg::PassBuilder& builder, Data& d) { d.hdr = builder.color_attachment(hdr, fg::LoadOp::Load); },
            [](const Data&, fg::PassContext& pass) {
                VkClearAttachment clear{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}};
                clear.clearValue.color.float32[0] = 0.25f;
                clear.clearValue.color.float32[1] = std::numeric_limits<float>::quiet_NaN();
                clear.clearValue.color.float32[2] = 0.25f;
                clear.clearValue.color.float32[3] = 1.0f;
                const VkClearRect rect{{{kNanX, kNanY}, {1, 1}}, 0, 1};
                vkCmdClearAttachments(pass.cmd(), 1, &clear, 1, &rect);
            });
        passes::add_readback_pass(graph, data.hdr, readback,
                                  VkDeviceSize{kExtremeWidth} * kExtremeHeight * 4 * sizeof(float));
    }};
}

TEST_F(extreme_output, InjectedNanIsNamedByPassResourceAndTexel) {
    Buffer readback(context(),
                    {VkDeviceSize{kExtremeWidth} * kExtremeHeight * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
                    "HDR readback");
    const Scene scene = extreme_scene();
    const FrameOutput output = nan_then_readback(readback.handle());
    Renderer renderer(context());
    try {
        renderer.prepare_frame(scene, extreme_options(), output).execute();
        ADD_FAILURE() << "the finite check let the NaN through";
    } catch (const InternalError& error) {
        const std::string message = error.what();
        std::printf("finite check: %s\n", message.c_str());
        EXPECT_NE(message.find("pass 'inject NaN'"), std::string::npos) << message;
        EXPECT_NE(message.find("NaN into 'hdr colour'"), std::string::npos) << message;
        EXPECT_NE(message.find("texel (17, 5), channel 1"), std::string::npos) << message;
    }
    // Without the check: the one NaN reaches the output where it was put and nowhere else (no pass
    // after it filters the image yet).
    RenderOptions unchecked = extreme_options();
    unchecked.check_finite = false;
    renderer.prepare_frame(scene, unchecked, output).execute();
    std::vector<float> pixels(size_t{kExtremeWidth} * kExtremeHeight * 4);
    std::memcpy(pixels.data(), readback.mapped(), pixels.size() * sizeof(float));
    size_t non_finite = 0;
    for (const float v : pixels) non_finite += !std::isfinite(v);
    EXPECT_EQ(non_finite, 1u);
    const size_t nan_index = (size_t{kNanY} * kExtremeWidth + kNanX) * 4 + 1;
    EXPECT_TRUE(std::isnan(pixels[nan_index]));
    // And every other value is the plain frame's, bit for bit (the clear touched one texel).
    const ImageRGBA32F plain = renderer.render(scene, unchecked).image;
    size_t changed = 0;
    for (size_t i = 0; i < pixels.size(); ++i) {
        const bool in_texel = i / 4 == nan_index / 4;
        changed += !in_texel && pixels[i] != plain.rgba[i];
    }
    EXPECT_EQ(changed, 0u);
}

}  // namespace
}  // namespace vkw::test
