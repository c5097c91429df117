// The file name of each frame of a sequence: --out DIR/name_%04d.exr, printf-style, as ffmpeg and
// most render tools name image sequences.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace vkw::cli {

class FramePattern {
public:
    // `pattern` holds exactly one frame number, %d or %0Nd (N from 1 to 9), in its file name (not
    // in its folder), "%%" for a literal '%', and ends in .exr (a sequence's frames are the linear
    // HDR images; --png adds previews). vkw::UserError naming --out and what is wrong otherwise.
    explicit FramePattern(const std::string& pattern);

    std::filesystem::path file_for(int64_t frame) const;
    // The folder every frame goes to, and where the sequence's manifest.json lives.
    const std::filesystem::path& folder() const { return folder_; }
    // The file name part as given, e.g. "name_%04d.exr" (recorded in the manifest).
    const std::string& name_pattern() const { return name_pattern_; }

private:
    std::filesystem::path folder_;
    std::string name_pattern_;
    std::string before_;  // the file name before the frame number, with "%%" already made '%'
    std::string after_;
    int width_ = 0;  // pad with zeros to this many digits
};

}  // namespace vkw::cli
