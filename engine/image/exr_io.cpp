// OpenEXR read/write through the general Imf::InputFile / Imf::OutputFile API
// (RgbaOutputFile cannot carry the extra layers).
#include "engine/image/exr_io.hpp"

#include <Iex.h>
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCheckFile.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "engine/core/errors.hpp"
#include "engine/core/message_text.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/exr_header_scan.hpp"
#include "engine/image/file_paths.hpp"

namespace vkw {
namespace {

using ChannelNames = std::span<const char* const>;

constexpr std::array<const char*, 4> kRgba = {"R", "G", "B", "A"};
constexpr std::array<const char*, 3> kRgb = {"R", "G", "B"};

// The largest side read: the largest image any vkwater command writes (--width, --height). A
// larger declared size is refused before a pixel is allocated (a 20000 x 20000 header would
// otherwise take 6.4 GB of float RGBA).
constexpr std::int64_t kMaxReadSide = 16384;

// Largest finite half; anything bigger would become infinity when converted.
constexpr float kHalfMax = 65504.0f;

std::size_t bytes_per_value(Imf::PixelType type) { return type == Imf::HALF ? sizeof(half) : sizeof(float); }

// Points one slice per channel at an interleaved buffer (channels.size() values per pixel,
// pixel (0, 0) at `base` corresponding to the window's top-left corner). Used by both the
// writer and the reader so the layout is defined in one place.
void add_interleaved_slices(Imf::FrameBuffer& frame_buffer, const std::string& prefix, ChannelNames channels,
                            Imf::PixelType type, const void* base, const Imath::Box2i& window, double fill_value) {
    const std::size_t value_bytes = bytes_per_value(type);
    const std::size_t pixel_bytes = value_bytes * channels.size();
    for (std::size_t c = 0; c < channels.size(); ++c) {
        const void* first = static_cast<const char*>(base) + c * value_bytes;
        frame_buffer.insert(prefix + channels[c],
                            Imf::Slice::Make(type, first, window, pixel_bytes, 0, 1, 1, fill_value));
    }
}

// --- writing ---------------------------------------------------------------------------

// One interleaved buffer of the image together with its EXR channel names.
struct Plane {
    std::string prefix;  // "" for the main image, "<layer>." for an extra layer
    ChannelNames channels;
    std::span<const float> values;
};

std::vector<Plane> planes_of(const ImageRGBA32F& image) {
    std::vector<Plane> planes{{"", kRgba, image.rgba}};
    for (const ExtraLayer& layer : image.layers) planes.push_back({layer.name + ".", kRgb, layer.rgb});
    return planes;
}

std::size_t count_nonfinite(std::span<const float> values) {
    return static_cast<std::size_t>(
        std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }));
}

// Non-finite values pass through unchanged (NaN stays NaN, inf stays inf) so a broken pixel
// stays recognisable in the file instead of turning into a plausible number.
std::vector<half> to_half_clamped(std::span<const float> values, std::size_t& clamped) {
    std::vector<half> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        float v = values[i];
        if (std::isfinite(v) && std::fabs(v) > kHalfMax) {
            v = std::copysign(kHalfMax, v);
            ++clamped;
        }
        out[i] = half(v);
    }
    return out;
}

}  // namespace

ExrWriteReport write_exr(const std::filesystem::path& path, const ImageRGBA32F& image, ExrPixelType pixel_type) {
    require_consistent_image(image);
    require_writable_file_path(path);

    const Imf::PixelType type = pixel_type == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
    // The default header carries no timestamp or other varying attribute, so with a fixed
    // compression the bytes depend on the pixels alone.
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::addChromaticities(header, Imf::Chromaticities());  // the default: Rec. 709 primaries, D65 white
    for (const ImageAttribute& attribute : image.attributes) {
        if (attribute.name.empty() || header.find(attribute.name) != header.end()) {
            throw InternalError("write_exr: attribute '" + attribute.name + "' is empty or given twice");
        }
        header.insert(attribute.name, Imf::StringAttribute(attribute.value));
    }
    const Imath::Box2i window = header.dataWindow();

    ExrWriteReport report;
    Imf::FrameBuffer frame_buffer;
    // Converted copies for Half; each inner vector's storage stays put while the outer grows.
    std::vector<std::vector<half>> half_planes;
    for (const Plane& plane : planes_of(image)) {
        report.nonfinite_values += count_nonfinite(plane.values);
        const void* base = plane.values.data();
        if (type == Imf::HALF) {
            half_planes.push_back(to_half_clamped(plane.values, report.clamped_values));
            base = half_planes.back().data();
        }
        for (const char* channel : plane.channels) {
            header.channels().insert(plane.prefix + channel, Imf::Channel(type));
        }
        add_interleaved_slices(frame_buffer, plane.prefix, plane.channels, type, base, window, 0.0);
    }

    // Encoded in memory, then written whole (checked_write.hpp): no partial file under the name.
    std::string bytes;
    try {
        Imf::StdOSStream stream;
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame_buffer);
            file.writePixels(image.height);
        }  // the file's destructor writes the line offset table
        bytes = stream.str();
    } catch (const std::exception& e) {  // Iex::BaseExc derives from std::exception
        throw UserError("cannot write " + quoted_path(path) + ": " + one_line(e.what()));
    }
    write_file_checked(path, bytes);
    return report;
}

// --- reading ---------------------------------------------------------------------------

namespace {

void require_full_resolution(const std::filesystem::path& path, const Imf::ChannelList& channels,
                             const std::string& name) {
    const Imf::Channel* channel = channels.findChannel(name);
    if (channel != nullptr && (channel->xSampling != 1 || channel->ySampling != 1)) {
        throw UserError("cannot read " + quoted_path(path) + ": channel '" + name +
                        "' is subsampled, which is not supported");
    }
}

bool has_any_channel(const Imf::ChannelList& channels, const std::string& prefix, ChannelNames names) {
    return std::any_of(names.begin(), names.end(),
                       [&](const char* n) { return channels.findChannel(prefix + n) != nullptr; });
}

void refuse_oversized(const std::filesystem::path& path, std::int64_t width, std::int64_t height) {
    if (width > kMaxReadSide || height > kMaxReadSide) {
        throw UserError("cannot read " + quoted_path(path) + ": declares " + std::to_string(width) + "x" +
                        std::to_string(height) + " pixels (accepted: each side at most " +
                        std::to_string(kMaxReadSide) + ")");
    }
}

ImageRGBA32F read_pixels(const std::filesystem::path& path, Imf::InputFile& file) {
    auto fail = [&](const std::string& why) { throw UserError("cannot read " + quoted_path(path) + ": " + why); };

    const Imath::Box2i window = file.header().dataWindow();
    const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
    const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
    if (width <= 0 || height <= 0 || width > INT_MAX || height > INT_MAX) {
        fail("invalid data window " + std::to_string(width) + "x" + std::to_string(height));
    }
    refuse_oversized(path, width, height);

    const Imf::ChannelList& channels = file.header().channels();
    for (const char* name : kRgb) {
        if (channels.findChannel(name) == nullptr) fail(std::string("missing channel '") + name + "'");
    }

    ImageRGBA32F image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);

    std::set<std::string> layer_names;
    channels.layers(layer_names);
    for (const std::string& name : layer_names) {
        // Layers without colour channels (e.g. "depth.Z") are not ours to interpret.
        if (has_any_channel(channels, name + ".", kRgb)) image.layers.push_back({name, {}});
    }
    for (const char* name : kRgba) require_full_resolution(path, channels, name);
    for (const ExtraLayer& layer : image.layers) {
        for (const char* name : kRgb) require_full_resolution(path, channels, layer.name + "." + name);
    }

    // The pixels are read a strip of rows at a time into storage reserved for all of them, each
    // strip's values made only when it is read: a header may declare up to kMaxReadSide^2 pixels
    // over a few hundred bytes of data, and such a file, cut short, then fails at its first
    // missing chunk instead of after its whole image (up to 4 GiB) has been zeroed. 256 rows is a
    // whole number of every compression's chunk height (1, 16, 32 or 256 scanlines).
    constexpr int kStripRows = 256;
    const std::size_t row_pixels = static_cast<std::size_t>(width);
    image.rgba.reserve(image.pixel_count() * 4);
    for (ExtraLayer& layer : image.layers) layer.rgb.reserve(image.pixel_count() * 3);
    for (int first = window.min.y; first <= window.max.y; first += kStripRows) {
        const int last = std::min(window.max.y, first + kStripRows - 1);
        const std::size_t strip_pixels = row_pixels * static_cast<std::size_t>(last - first + 1);
        const Imath::Box2i strip(Imath::V2i(window.min.x, first), Imath::V2i(window.max.x, last));
        // Every slice is FLOAT: OpenEXR converts half and uint on the way in.
        Imf::FrameBuffer frame_buffer;
        image.rgba.resize(image.rgba.size() + strip_pixels * 4);
        // Fill value 1 makes a missing A read as opaque.
        add_interleaved_slices(frame_buffer, "", kRgba, Imf::FLOAT,
                               image.rgba.data() + image.rgba.size() - strip_pixels * 4, strip, 1.0);
        for (ExtraLayer& layer : image.layers) {
            layer.rgb.resize(layer.rgb.size() + strip_pixels * 3);
            add_interleaved_slices(frame_buffer, layer.name + ".", kRgb, Imf::FLOAT,
                                   layer.rgb.data() + layer.rgb.size() - strip_pixels * 3, strip, 0.0);
        }
        file.setFrameBuffer(frame_buffer);
        file.readPixels(first, last);
    }
    for (auto it = file.header().begin(); it != file.header().end(); ++it) {
        if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) {
            image.attributes.push_back({it.name(), text->value()});
        }
    }
    return image;
}

// An OpenEXR input stream over a file's bytes in memory. It does not offer them as memory-mapped:
// OpenEXR 3.1's scanline reader would then decode an uncompressed chunk in place, reading the
// whole line's bytes from where the chunk starts even when the chunk declares fewer, past the end
// of the bytes (a 484-byte file from the fuzzer did that). Copied out, each chunk lands in a
// buffer as large as its lines.
class MemoryInput : public Imf::IStream {
public:
    MemoryInput(std::span<const char> bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}

    // As OpenEXR's file streams do: a read past the end throws, and the result says whether bytes are left.
    bool read(char c[], int n) override {
        if (n < 0 || position_ > bytes_.size() || static_cast<std::uint64_t>(n) > bytes_.size() - position_) {
            throw Iex::InputExc("unexpected end of file");
        }
        std::copy_n(bytes_.data() + position_, n, c);
        position_ += static_cast<std::uint64_t>(n);
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = position; }

private:
    std::span<const char> bytes_;
    std::uint64_t position_ = 0;
};

// The whole file, as read_exr's checks and reader take it.
std::vector<char> read_file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes(std::filesystem::file_size(path));
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
        throw UserError("cannot read " + quoted_path(path) + ": the file could not be read to its end");
    }
    return bytes;
}

}  // namespace

ImageRGBA32F read_exr(const std::filesystem::path& path) {
    require_readable_file_path(path);
    // The file is read once: the header walk, OpenEXR's checker and its reader all take these
    // bytes (the checker alone opened the file four times, and the fuzzer spent its time there).
    return read_exr_bytes(read_file_bytes(path), path);
}

ImageRGBA32F read_exr_bytes(std::span<const char> bytes, const std::filesystem::path& path) {
    // Checking the magic number first gives "not an OpenEXR file" instead of a library message.
    if (bytes.size() < 4 || !Imf::isImfMagic(bytes.data())) {
        throw UserError("cannot read " + quoted_path(path) + ": not an OpenEXR file");
    }
    // OpenEXR allocates what each header attribute declares before reading it: the sizes are
    // checked against the file first (exr_header_scan.hpp).
    ExrWindowSize largest;
    if (const auto problem = exr_header_problem(bytes, &largest)) {
        throw UserError("cannot read " + quoted_path(path) + ": a corrupt OpenEXR file (" + *problem + ")");
    }
    // Before OpenEXR's checker, which allocates line buffers as wide as the data window.
    refuse_oversized(path, largest.width, largest.height);
    // OpenEXR's own validator reads every part of the file with bounded memory and time; the
    // library's readers trust what a header declares, so a corrupt file is refused here first.
    // Its core check too: it refuses chunks whose sizes do not add up, such as an uncompressed
    // chunk shorter than its lines, which the reader would fill from beyond the chunk.
    if (Imf::checkOpenEXRFile(bytes.data(), bytes.size(), /*reduceMemory=*/true, /*reduceTime=*/true,
                              /*enableCoreCheck=*/true)) {
        throw UserError("cannot read " + quoted_path(path) + ": a corrupt or truncated OpenEXR file");
    }
    try {
        MemoryInput stream(bytes, path.string());
        Imf::InputFile file(stream);
        return read_pixels(path, file);
    } catch (const UserError&) {
        throw;
    } catch (const std::exception& e) {  // Iex::BaseExc (truncated/corrupt data), std::bad_alloc
        throw UserError("cannot read " + quoted_path(path) + ": " + one_line(e.what()));
    }
}

}  // namespace vkw
