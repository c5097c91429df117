#include "tools/vkwater/sequence/frame_pattern.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <cctype>

namespace vkw::cli {
namespace {

const char* const kAccepted =
    " (accepted: one %d or %0Nd, N from 1 to 9, in the file name, '%%' for a literal '%', and the extension .exr; "
    "e.g. out/pool_%04d.exr)";

}  // namespace

FramePattern::FramePattern(const std::string& pattern) {
    const auto refuse = [&](const std::string& why) { throw UserError("--out '" + pattern + "': " + why + kAccepted); };
    const std::filesystem::path path(pattern);
    folder_ = path.parent_path();
    name_pattern_ = path.filename().string();
    if (folder_.string().find('%') != std::string::npos) refuse("a '%' in the folder; a sequence writes one folder");
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".exr") refuse("a sequence's frames are .exr files");

    bool found = false;
    std::string* part = &before_;
    for (size_t i = 0; i < name_pattern_.size(); ++i) {
        const char c = name_pattern_[i];
        if (c != '%') {
            *part += c;
            continue;
        }
        if (i + 1 < name_pattern_.size() && name_pattern_[i + 1] == '%') {
            *part += '%';
            ++i;
            continue;
        }
        // %d or %0Nd
        size_t j = i + 1;
        int width = 0;
        if (j + 2 < name_pattern_.size() && name_pattern_[j] == '0' && name_pattern_[j + 1] >= '1' &&
            name_pattern_[j + 1] <= '9' && name_pattern_[j + 2] == 'd') {
            width = name_pattern_[j + 1] - '0';
            j += 2;
        }
        if (j >= name_pattern_.size() || name_pattern_[j] != 'd') refuse("a '%' that is neither %d, %0Nd nor %%");
        if (found) refuse("more than one frame number");
        found = true;
        width_ = width;
        part = &after_;
        i = j;
    }
    if (!found) refuse("no frame number in the file name");
}

std::filesystem::path FramePattern::file_for(int64_t frame) const {
    std::string digits = std::to_string(frame);
    if (digits.size() < static_cast<size_t>(width_)) digits.insert(0, static_cast<size_t>(width_) - digits.size(), '0');
    return folder_ / (before_ + digits + after_);
}

}  // namespace vkw::cli
