// A glTF square with a base colour texture, above the water and seen from straight above, in both
// renderers: at the centre of each checker square the image shows the texel's albedo (sRGB-decoded)
// times the model's closed-form irradiance, L = rho (E_s cos(theta_s) + pi L_sky) / pi (docs/model.md
// section 1). Every square has its own colour, so a texture drawn flipped, transposed, untextured or
// with its sRGB decoding skipped lands on the wrong value.
#include "passes/frame/renderer.hpp"
#include "passes/receivers/texture_mips.hpp"
#include "tests/render/overhead_scene.hpp"
#include "tests/render/uniform_agreement.hpp"
#include "tests/scene/gltf_textured_square.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"
#include "tools/reference/texture_lookup.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <numbers>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 64;    // image side, pixels
constexpr uint32_t kSquares = 4;  // checker squares per side
constexpr uint32_t kTexelsPerSquare = 4;

// The colour of checker square (i, j): i along u (x), j along v (z); each distinct.
std::array<uint8_t, 3> square_colour(uint32_t i, uint32_t j) {
    return {uint8_t(30 + 60 * i), uint8_t(30 + 60 * j), uint8_t(220 - 25 * (i + j))};
}

// The checker as a texture; with `cutout`, the squares with i + j odd have alpha 0 and the material
// is alphaMode MASK (cutoff 0.5), so that they are holes.
TexturedSquare checker(bool cutout = false) {
    TexturedSquare square;
    square.width = square.height = kSquares * kTexelsPerSquare;
    square.rgba.clear();
    for (uint32_t y = 0; y < square.height; ++y) {
        for (uint32_t x = 0; x < square.width; ++x) {
            const uint32_t i = x / kTexelsPerSquare, j = y / kTexelsPerSquare;
            const auto colour = square_colour(i, j);
            const uint8_t alpha = cutout && (i + j) % 2 == 1 ? 0 : 255;
            square.rgba.insert(square.rgba.end(), {colour[0], colour[1], colour[2], alpha});
        }
    }
    if (cutout) square.material_extra = R"("alphaMode": "MASK", )";
    return square;
}

// The square lifted to y = 1 over water at 0, the camera 4 m above it: a square of 0.5 m spans
// about 12 pixels, so each checker square's centre pixel lies inside it with margin.
struct CheckerView {
    Scene scene;
    double square_height = 1.0;
    ImageRGBA32F real_time, reference;

    // `height`: the square's, 4 m under the camera (overridden with the camera).
    CheckerView(Context& context, const TexturedSquare& square, const std::string& name,
                const std::vector<std::string>& overrides = {}, double height = 1.0) {
        const std::filesystem::path dir = scratch_dir(name);
        write_text(dir / "checker.gltf", textured_square_text(square));
        scene = overhead_receiver_scene(
            R"({"type": "gltf", "file": "checker.gltf", "translation": [0, )" + std::to_string(height) + ", 0]}",
            dir / "scene.json", 0.0, overrides);
        square_height = height;
        Renderer renderer(context);
        real_time = renderer.render(scene, {kSize, kSize, true, fg::TimingMode::None}).image;
        reference = ref::render_reference(scene, {kSize, kSize, 0, {}});
    }

    // The pixel that sees the centre of checker square (i, j): u = (i + 0.5) / 4 at x = 2 u - 1,
    // likewise v and z.
    glm::ivec2 pixel_of(uint32_t i, uint32_t j) const {
        const glm::dmat4 view_proj = projection_matrix(scene.camera, 1.0) * view_matrix(scene.camera);
        const glm::dvec4 clip = view_proj * glm::dvec4(2.0 * (i + 0.5) / kSquares - 1.0, square_height,
                                                       2.0 * (j + 0.5) / kSquares - 1.0, 1.0);
        return {int((clip.x / clip.w + 1.0) / 2.0 * kSize), int((1.0 - clip.y / clip.w) / 2.0 * kSize)};
    }

    // Checks both renderers at the centre of square (i, j) against the closed form of its colour.
    void expect_square_colour(uint32_t i, uint32_t j) const {
        const glm::ivec2 at = pixel_of(i, j);
        ASSERT_TRUE(at.x >= 0 && at.x < int(kSize) && at.y >= 0 && at.y < int(kSize));
        const auto colour = square_colour(i, j);
        const double cos_sun = -scene.sun.direction.y;
        glm::dvec3 irradiance_over_pi, expected;
        for (int c = 0; c < 3; ++c) {
            irradiance_over_pi[c] =
                (scene.sun.irradiance[c] * cos_sun + std::numbers::pi * scene.sky.radiance[c]) / std::numbers::pi;
            expected[c] = ref::srgb_to_linear(colour[std::size_t(c)]) * irradiance_over_pi[c];
        }
        // The fp32 shading's error (the receiver tests' 1e-5 relative) is absolute at the scale of
        // the point's radiance: at 2 of these 16 points the darker channels carry 1e-6 to 4e-6 of it,
        // 1e-5 to 8e-5 of their own value (measured; the cause is not traced, as in the receiver
        // tests). So the bound is 1e-5 of the brightest channel.
        const double brightest = std::max({expected.r, expected.g, expected.b});
        for (int c = 0; c < 3; ++c) {
            // Real time: the texel as uploaded, the exact decoding rounded to a half float (2^-11
            // relative at most), times the same closed form, within the shading's bound. Every tap of
            // the bilinear filter lies inside the square (4 texels wide, the pixel a third of a
            // texel), so the filter adds nothing. A neighbouring square's colour is off by 10-80% of
            // the value, an sRGB decoding skipped or approximated (lavapipe's sampler is 2% off in
            // dark texels) by far more than the bound.
            const double uploaded =
                glm::unpackHalf1x16(glm::packHalf1x16(float(ref::srgb_to_linear(colour[std::size_t(c)]))));
            EXPECT_NEAR(real_time.pixel(at.x, at.y)[c], uploaded * irradiance_over_pi[c], 1e-5 * brightest)
                << "square (" << i << ", " << j << ") at pixel (" << at.x << ", " << at.y << "), channel " << c;
            // The reference: double precision, stored as fp32 (6e-8 relative): 1e-7.
            EXPECT_NEAR(reference.pixel(at.x, at.y)[c], expected[c], 1e-7 * expected[c])
                << "square (" << i << ", " << j << ") at pixel (" << at.x << ", " << at.y << "), channel " << c;
        }
    }
};

using TexturedReceiver = GpuTest;

TEST_F(TexturedReceiver, EachTexelShowsItsAlbedoTimesTheIrradianceInBothRenderers) {
    const CheckerView view(context(), checker(), "textured_receiver");
    for (uint32_t j = 0; j < kSquares; ++j) {
        for (uint32_t i = 0; i < kSquares; ++i) view.expect_square_colour(i, j);
    }
}

// Under flat water, seen by a camera in the water (no view ray crosses the surface) through clear
// water that absorbs but does not scatter: a pixel's radiance is its point's albedo times what the
// same point sends back as a white one, L = rho T_view E / pi, with E the sun through the flat surface
// and the transmitted sky (docs/model.md sections 1 and 3). So each square's centre shows its texel's
// albedo times the white square's value there, in both renderers.
TEST_F(TexturedReceiver, UnderFlatWaterEachTexelScalesTheIrradianceInBothRenderers) {
    const std::vector<std::string> under_water = {"camera.position=[0, -0.1, 0]", "floor.height=-6",
                                                  R"(medium={"sigma_a": [0.1, 0.05, 0.03], "sigma_s": [0, 0, 0]})"};
    const CheckerView view(context(), checker(), "textured_under_water", under_water, -4.1);
    TexturedSquare white = checker();
    std::fill(white.rgba.begin(), white.rgba.end(), uint8_t(255));
    const CheckerView lit(context(), white, "white_under_water", under_water, -4.1);
    for (uint32_t j = 0; j < kSquares; ++j) {
        for (uint32_t i = 0; i < kSquares; ++i) {
            const glm::ivec2 at = view.pixel_of(i, j);
            ASSERT_TRUE(at.x >= 0 && at.x < int(kSize) && at.y >= 0 && at.y < int(kSize));
            const auto colour = square_colour(i, j);
            const float* white_rt = lit.real_time.pixel(at.x, at.y);
            const float* white_ref = lit.reference.pixel(at.x, at.y);
            ASSERT_GT(white_rt[0], 0.0f);  // lit: the sun and the sky reach 4 m down
            const double brightest = std::max({white_rt[0], white_rt[1], white_rt[2]});
            for (int c = 0; c < 3; ++c) {
                const double rho = ref::srgb_to_linear(colour[std::size_t(c)]);
                // The real-time texel as uploaded (the exact decoding as a half float; white is 1
                // exactly), and the fp32 shading's 1e-5 of the brightest channel as above.
                const double uploaded = glm::unpackHalf1x16(glm::packHalf1x16(float(rho)));
                EXPECT_NEAR(view.real_time.pixel(at.x, at.y)[c], uploaded * white_rt[c], 1e-5 * brightest)
                    << "square (" << i << ", " << j << "), channel " << c;
                // The reference: both images rounded to fp32 once (6e-8 relative each): 2e-7.
                EXPECT_NEAR(view.reference.pixel(at.x, at.y)[c], rho * white_ref[c], 2e-7 * white_ref[c])
                    << "square (" << i << ", " << j << "), channel " << c;
            }
        }
    }
}

// alphaMode MASK: the squares of alpha 0 are holes. The opaque ones keep their colour; through the
// holes both renderers see the water below, and the sun reaches it through them (the square's
// shadow on the water has the same holes in the real-time shadow map and the reference's rays).
TEST_F(TexturedReceiver, CutoutsLetTheViewAndTheSunThroughInBothRenderers) {
    // Water that does not scatter: the sun through the holes lights the water's volume, and the
    // real-time godrays' blurred, half-resolution in-scatter would bleed 1e-5 to 4e-5 of it onto the
    // opaque squares' pixels next to the holes (measured), a godray matter, not a cutout one.
    const CheckerView view(context(), checker(/*cutout=*/true), "cutout_receiver",
                           {R"(medium={"sigma_a": [0.1, 0.05, 0.05], "sigma_s": [0, 0, 0]})"});
    int holes = 0;
    for (uint32_t j = 0; j < kSquares; ++j) {
        for (uint32_t i = 0; i < kSquares; ++i) {
            if ((i + j) % 2 == 0) {
                view.expect_square_colour(i, j);
                continue;
            }
            // A hole shows the water: nothing like the square's colour (its red alone is 0.01 to
            // 0.43 of the opaque value here), and the same in both renderers.
            const glm::ivec2 at = view.pixel_of(i, j);
            const float* rt = view.real_time.pixel(at.x, at.y);
            const float* ref = view.reference.pixel(at.x, at.y);
            const auto colour = square_colour(i, j);
            bool unlike_the_square = false;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(rt[c], ref[c], kUniformBound * ref[c]) << "hole (" << i << ", " << j << "), channel " << c;
                const double square = ref::srgb_to_linear(colour[std::size_t(c)]) * view.scene.sky.radiance[c];
                unlike_the_square = unlike_the_square || std::abs(rt[c] - square) > 0.1 * square;
            }
            EXPECT_TRUE(unlike_the_square) << "hole (" << i << ", " << j << ") shows the square";
            ++holes;
        }
    }
    EXPECT_EQ(holes, 8);
    // The square's shadow has the holes too: outside the square's own pixels, the reference of the
    // cutout differs from that of the whole square where the sun now reaches the floor through the
    // holes (and the real-time image agrees there, below).
    const CheckerView whole(context(), checker(), "cutout_receiver_whole",
                            {R"(medium={"sigma_a": [0.1, 0.05, 0.05], "sigma_s": [0, 0, 0]})"});
    const glm::ivec2 corner_lo = view.pixel_of(0, 0), corner_hi = view.pixel_of(kSquares - 1, kSquares - 1);
    int relit = 0;
    for (int y = 0; y < int(kSize); ++y) {
        for (int x = 0; x < int(kSize); ++x) {
            const int margin = int(kSize) / 8;  // half a checker square and more, around the square's pixels
            const bool on_square =
                x >= std::min(corner_lo.x, corner_hi.x) - margin && x <= std::max(corner_lo.x, corner_hi.x) + margin &&
                y >= std::min(corner_lo.y, corner_hi.y) - margin && y <= std::max(corner_lo.y, corner_hi.y) + margin;
            if (!on_square && view.reference.pixel(x, y)[1] > 1.05f * whole.reference.pixel(x, y)[1]) ++relit;
        }
    }
    // From this camera the shadow lies mostly under the square itself: 19 pixels beside it are relit
    // (measured); without the holes in the reference's shadow rays, none would be.
    EXPECT_GE(relit, 10);
    // Everywhere the reference is uniform (the opaque squares, the water, the shadow with its holes),
    // the real-time image agrees.
    const UniformAgreement agreement = compare_uniform(view.real_time, view.reference);
    EXPECT_GT(agreement.uniform, 1000);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.examples;
}

}  // namespace
}  // namespace vkw::test
