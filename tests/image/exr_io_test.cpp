// Tests of write_exr / read_exr: round trips, half clamping, NaN handling, extra layers,
// deterministic bytes and error reporting on bad input files.
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "engine/image/exr_io.hpp"
#include "tests/image/image_test_support.hpp"

namespace vkw {
namespace {

using test::expect_user_error;
using test::make_test_image;
using test::ScratchDir;

void expect_bit_identical(const std::vector<float>& expected, const std::vector<float>& actual) {
    ASSERT_EQ(expected.size(), actual.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(std::bit_cast<std::uint32_t>(expected[i]), std::bit_cast<std::uint32_t>(actual[i]))
            << "value " << i << ": " << expected[i] << " vs " << actual[i];
    }
}

// Writes a half EXR the way another program might: only the given channels (no alpha
// unless listed), data window starting at (x0, y0). Channel k of pixel i holds 10*i + k.
void write_foreign_exr(const std::filesystem::path& path, int x0, int y0, int width, int height,
                       const std::vector<std::string>& channels) {
    const Imath::Box2i window({x0, y0}, {x0 + width - 1, y0 + height - 1});
    Imf::Header header(window, window);
    std::vector<std::vector<half>> planes;
    Imf::FrameBuffer frame_buffer;
    for (std::size_t k = 0; k < channels.size(); ++k) {
        std::vector<half> plane(static_cast<std::size_t>(width * height));
        for (std::size_t i = 0; i < plane.size(); ++i) plane[i] = half(10.0f * i + k);
        planes.push_back(std::move(plane));
        header.channels().insert(channels[k], Imf::Channel(Imf::HALF));
        frame_buffer.insert(channels[k], Imf::Slice::Make(Imf::HALF, planes.back().data(), window));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame_buffer);
    file.writePixels(height);
}

TEST(image_exr_io, FloatRoundTripIsBitExact) {
    ScratchDir dir;
    ImageRGBA32F image = make_test_image(7, 5);
    image.pixel(0, 0)[0] = -0.0f;
    image.pixel(1, 0)[1] = std::numeric_limits<float>::denorm_min();
    image.pixel(6, 4)[2] = 1.0e30f;

    const ExrWriteReport report = write_exr(dir / "float.exr", image);
    EXPECT_EQ(report.clamped_values, 0u);
    EXPECT_EQ(report.nonfinite_values, 0u);

    const ImageRGBA32F back = read_exr(dir / "float.exr");
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    expect_bit_identical(image.rgba, back.rgba);
    EXPECT_TRUE(back.layers.empty());
}

TEST(image_exr_io, HalfRoundTripIsWithinHalfRounding) {
    ScratchDir dir;
    const ImageRGBA32F image = make_test_image(7, 5);  // all values normal halfs (0.1 .. 52)
    write_exr(dir / "half.exr", image, ExrPixelType::Half);
    const ImageRGBA32F back = read_exr(dir / "half.exr");
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        // Half keeps 10 explicit mantissa bits; round-to-nearest of a normal value is off by
        // at most half a unit in the last place, i.e. relative 2^-11.
        const float tolerance = std::fabs(image.rgba[i]) * std::ldexp(1.0f, -11);
        EXPECT_NEAR(back.rgba[i], image.rgba[i], tolerance) << "value " << i;
    }
}

TEST(image_exr_io, HalfClampsAndCountsValuesBeyondHalfMax) {
    ScratchDir dir;
    ImageRGBA32F image = make_test_image(2, 1);
    float* p = image.pixel(0, 0);
    p[0] = 1.0e6f;
    p[1] = -1.0e6f;
    p[2] = 65504.0f;  // exactly the largest half: kept, not counted
    image.pixel(1, 0)[3] = 70000.0f;

    const ExrWriteReport report = write_exr(dir / "clamp.exr", image, ExrPixelType::Half);
    EXPECT_EQ(report.clamped_values, 3u);
    EXPECT_EQ(report.nonfinite_values, 0u);

    const ImageRGBA32F back = read_exr(dir / "clamp.exr");
    EXPECT_EQ(back.pixel(0, 0)[0], 65504.0f);
    EXPECT_EQ(back.pixel(0, 0)[1], -65504.0f);
    EXPECT_EQ(back.pixel(0, 0)[2], 65504.0f);
    EXPECT_EQ(back.pixel(1, 0)[3], 65504.0f);
}

TEST(image_exr_io, FloatDoesNotClamp) {
    ScratchDir dir;
    ImageRGBA32F image = make_test_image(1, 1);
    image.pixel(0, 0)[0] = 1.0e6f;
    EXPECT_EQ(write_exr(dir / "big.exr", image).clamped_values, 0u);
    EXPECT_EQ(read_exr(dir / "big.exr").pixel(0, 0)[0], 1.0e6f);
}

TEST(image_exr_io, NonFiniteValuesAreCountedAndKept) {
    ScratchDir dir;
    for (const ExrPixelType type : {ExrPixelType::Float, ExrPixelType::Half}) {
        ImageRGBA32F image = make_test_image(2, 2, {"caustic"});
        image.pixel(0, 0)[0] = std::numeric_limits<float>::quiet_NaN();
        image.pixel(1, 1)[1] = std::numeric_limits<float>::infinity();
        image.layers[0].rgb[5] = -std::numeric_limits<float>::infinity();

        const ExrWriteReport report = write_exr(dir / "nan.exr", image, type);
        EXPECT_EQ(report.nonfinite_values, 3u);
        EXPECT_EQ(report.clamped_values, 0u);  // infinities are non-finite, not clamped

        const ImageRGBA32F back = read_exr(dir / "nan.exr");
        EXPECT_TRUE(std::isnan(back.pixel(0, 0)[0]));
        EXPECT_EQ(back.pixel(1, 1)[1], std::numeric_limits<float>::infinity());
        EXPECT_EQ(back.layers.at(0).rgb[5], -std::numeric_limits<float>::infinity());
    }
}

TEST(image_exr_io, ExtraLayersRoundTripSortedByName) {
    ScratchDir dir;
    const ImageRGBA32F image = make_test_image(4, 3, {"foam", "caustic"});
    write_exr(dir / "layers.exr", image);
    const ImageRGBA32F back = read_exr(dir / "layers.exr");

    ASSERT_EQ(back.layers.size(), 2u);
    EXPECT_EQ(back.layers[0].name, "caustic");
    EXPECT_EQ(back.layers[1].name, "foam");
    expect_bit_identical(image.layers[1].rgb, back.layers[0].rgb);
    expect_bit_identical(image.layers[0].rgb, back.layers[1].rgb);
    expect_bit_identical(image.rgba, back.rgba);
}

// The pixels are read in strips of 256 rows: an image of 700 rows (two whole strips and a part)
// with layers reads back bit for bit, and so does a foreign file whose data window starts at row 20.
TEST(image_exr_io, ImagesTallerThanAStripReadBackExactly) {
    ScratchDir dir;
    const ImageRGBA32F image = make_test_image(5, 700, {"caustic", "in_scatter"});
    write_exr(dir / "tall.exr", image);
    const ImageRGBA32F back = read_exr(dir / "tall.exr");
    ASSERT_EQ(back.height, 700);
    ASSERT_EQ(back.layers.size(), 2u);
    expect_bit_identical(image.rgba, back.rgba);
    expect_bit_identical(image.layers[0].rgb, back.layers[0].rgb);
    expect_bit_identical(image.layers[1].rgb, back.layers[1].rgb);

    write_foreign_exr(dir / "tall_rgb.exr", 10, 20, 3, 600, {"R", "G", "B"});
    const ImageRGBA32F foreign = read_exr(dir / "tall_rgb.exr");
    // Pixel (1, 599) is pixel 599 * 3 + 1 = 1798: R = 17980 as a half (17984, halves 16 apart there).
    EXPECT_EQ(foreign.pixel(1, 599)[0], static_cast<float>(half(17980.0f)));
    EXPECT_EQ(foreign.pixel(1, 599)[3], 1.0f);
    // Pixel (2, 256), the first row of the second strip: pixel 770, G = 7701 as a half.
    EXPECT_EQ(foreign.pixel(2, 256)[1], static_cast<float>(half(7701.0f)));
}

// The header carries the standard chromaticities (the renderers' linear RGB is Rec. 709 with a D65
// white) and every attribute of the image, which read back as written, sorted by name.
TEST(image_exr_io, AttributesAndChromaticitiesRoundTrip) {
    ScratchDir dir;
    ImageRGBA32F image = make_test_image(5, 4, {});
    image.attributes = {{"vkwater/scene", "scenes/pool.json"}, {"software", "vkwater test"}};
    write_exr(dir / "a.exr", image);
    Imf::InputFile file((dir / "a.exr").c_str());
    ASSERT_TRUE(Imf::hasChromaticities(file.header()));
    const Imf::Chromaticities c = Imf::chromaticities(file.header());
    EXPECT_FLOAT_EQ(c.red.x, 0.64f);
    EXPECT_FLOAT_EQ(c.green.y, 0.6f);
    EXPECT_FLOAT_EQ(c.blue.x, 0.15f);
    EXPECT_FLOAT_EQ(c.white.x, 0.3127f);
    EXPECT_FLOAT_EQ(c.white.y, 0.329f);
    const ImageRGBA32F back = read_exr(dir / "a.exr");
    ASSERT_EQ(back.attributes.size(), 2u);
    EXPECT_EQ(back.attributes[0].name, "software");
    EXPECT_EQ(back.attributes[0].value, "vkwater test");
    EXPECT_EQ(back.attributes[1].name, "vkwater/scene");
    EXPECT_EQ(back.attributes[1].value, "scenes/pool.json");
    expect_bit_identical(image.rgba, back.rgba);
    // One name twice (or one that a standard attribute already has) is a caller's bug.
    image.attributes.push_back({"software", "again"});
    EXPECT_THROW(write_exr(dir / "b.exr", image), InternalError);
    image.attributes.back() = {"chromaticities", "text"};
    EXPECT_THROW(write_exr(dir / "b.exr", image), InternalError);
}

TEST(image_exr_io, RepeatedWritesAreByteIdentical) {
    ScratchDir dir;
    const ImageRGBA32F image = make_test_image(33, 17, {"caustic"});
    for (const ExrPixelType type : {ExrPixelType::Float, ExrPixelType::Half}) {
        write_exr(dir / "a.exr", image, type);
        write_exr(dir / "b.exr", image, type);
        const auto a = test::read_bytes(dir / "a.exr");
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, test::read_bytes(dir / "b.exr"));
    }
}

TEST(image_exr_io, ForeignFileWithoutAlphaReadsOpaqueFromOffsetWindow) {
    ScratchDir dir;
    write_foreign_exr(dir / "rgb.exr", 10, 20, 3, 2, {"R", "G", "B", "depth.Z"});
    const ImageRGBA32F image = read_exr(dir / "rgb.exr");

    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    EXPECT_TRUE(image.layers.empty());  // "depth" has no colour channels
    // Pixel (2, 1) is the 6th pixel: R = 50, G = 51, B = 52 (exact in half), A filled with 1.
    EXPECT_EQ(image.pixel(2, 1)[0], 50.0f);
    EXPECT_EQ(image.pixel(2, 1)[1], 51.0f);
    EXPECT_EQ(image.pixel(2, 1)[2], 52.0f);
    EXPECT_EQ(image.pixel(2, 1)[3], 1.0f);
    EXPECT_EQ(image.pixel(0, 0)[3], 1.0f);
}

TEST(image_exr_io, FileWithoutColourChannelsIsUserError) {
    ScratchDir dir;
    write_foreign_exr(dir / "y.exr", 0, 0, 2, 2, {"Y"});
    expect_user_error([&] { read_exr(dir / "y.exr"); }, dir / "y.exr", "missing channel 'R'");
}

TEST(image_exr_io, NonExrFileIsUserError) {
    ScratchDir dir;
    test::write_text(dir / "notes.exr", "this is not an image\n");
    expect_user_error([&] { read_exr(dir / "notes.exr"); }, dir / "notes.exr", "not an OpenEXR file");
}

TEST(image_exr_io, TruncatedExrIsUserError) {
    ScratchDir dir;
    write_exr(dir / "full.exr", make_test_image(64, 64));
    const auto bytes = test::read_bytes(dir / "full.exr");
    test::write_text(dir / "cut.exr", std::string(bytes.begin(), bytes.begin() + bytes.size() / 2));
    expect_user_error([&] { read_exr(dir / "cut.exr"); }, dir / "cut.exr", "a corrupt or truncated OpenEXR file");
}

// A header's declared size is bounded before any pixel is allocated: a side over 16384 (the
// largest image vkwater writes) is refused even in a valid file, and a header patched to declare
// 20000 x 20000 over a 4 x 4 file's data is refused too (it used to allocate 6.4 GB first).
TEST(image_exr_io, DeclaredSizesAreBoundedBeforeAllocating) {
    ScratchDir dir;
    write_foreign_exr(dir / "wide.exr", 0, 0, 16385, 1, {"R", "G", "B"});
    expect_user_error([&] { read_exr(dir / "wide.exr"); }, dir / "wide.exr",
                      "declares 16385x1 pixels (accepted: each side at most 16384)");
    write_foreign_exr(dir / "widest.exr", 0, 0, 16384, 1, {"R", "G", "B"});
    EXPECT_EQ(read_exr(dir / "widest.exr").width, 16384);

    write_exr(dir / "small.exr", make_test_image(4, 4));
    std::vector<unsigned char> bytes = test::read_bytes(dir / "small.exr");
    const std::string name("dataWindow\0box2i\0", 17);
    const auto at = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
    ASSERT_NE(at, bytes.end());
    // After the name and type: the size (16), then x_min, y_min, x_max, y_max as 32-bit integers.
    const std::int32_t last = 19999;
    std::memcpy(&*at + name.size() + 4 + 8, &last, 4);
    std::memcpy(&*at + name.size() + 4 + 12, &last, 4);
    test::write_text(dir / "patched.exr", std::string(bytes.begin(), bytes.end()));
    expect_user_error([&] { read_exr(dir / "patched.exr"); }, dir / "patched.exr", "");
}

TEST(image_exr_io, MissingInputIsUserError) {
    ScratchDir dir;
    expect_user_error([&] { read_exr(dir / "absent.exr"); }, dir / "absent.exr", "does not exist");
    expect_user_error([&] { read_exr(dir.path()); }, dir.path(), "is a directory");
}

TEST(image_exr_io, InconsistentImageIsInternalError) {
    ScratchDir dir;
    ImageRGBA32F image = make_test_image(2, 2, {"caustic"});
    image.layers[0].rgb.pop_back();
    EXPECT_THROW(write_exr(dir / "bad.exr", image), InternalError);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.exr"));
}

}  // namespace
}  // namespace vkw
