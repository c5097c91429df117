#include "tools/vkwater/sequence/sequence_manifest.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/scene/json_text.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace vkw::cli {
namespace {

constexpr const char* kFormat = "vkwater frame sequence 1";

// An exclusive flock on the folder's lock file for as long as it lives. The manifest itself is
// replaced by rename on every write, so the lock is on a file that stays.
class FolderLock {
public:
    explicit FolderLock(const std::filesystem::path& path) {
        fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
        if (fd_ < 0) throw UserError("cannot open " + quoted_path(path) + ": " + std::strerror(errno));
        while (::flock(fd_, LOCK_EX) != 0) {
            if (errno == EINTR) continue;
            const std::string why = std::strerror(errno);
            ::close(fd_);
            throw UserError("cannot lock " + quoted_path(path) + ": " + why);
        }
    }
    ~FolderLock() { ::close(fd_); }  // closing releases the lock
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int fd_ = -1;
};

nlohmann::ordered_json to_json(const FrameRecord& frame) {
    return {{"frame", frame.frame},          {"file", frame.file},        {"waterTime", frame.water_time_s},
            {"pixelHash", frame.pixel_hash}, {"frameMs", frame.frame_ms}, {"wallMs", frame.wall_ms},
            {"device", frame.device}};
}

// The first key of `expected` whose value `found` does not share, as "settings.width", with both values.
std::string first_difference(const nlohmann::json& expected, const nlohmann::json& found, const std::string& path) {
    if (expected.is_object() && found.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            const std::string where = path.empty() ? key : path + "." + key;
            if (!found.contains(key)) return where + " is missing (this run: " + value.dump() + ")";
            std::string difference = first_difference(value, found.at(key), where);
            if (!difference.empty()) return difference;
        }
        for (const auto& [key, value] : found.items()) {
            if (!expected.contains(key))
                return (path.empty() ? key : path + "." + key) + " is not a setting of this run";
        }
        return {};
    }
    if (expected == found) return {};
    return path + " is " + found.dump() + " (this run: " + expected.dump() + ")";
}

}  // namespace

SequenceManifest::SequenceManifest(std::filesystem::path folder, std::string scene, nlohmann::json identity)
    : path_(folder / "manifest.json"),
      lock_path_(folder / "manifest.json.lock"),
      scene_(std::move(scene)),
      identity_(std::move(identity)) {}

std::map<int64_t, FrameRecord> SequenceManifest::recorded() const {
    const FolderLock lock(lock_path_);
    return read_and_check();
}

std::map<int64_t, FrameRecord> SequenceManifest::read_and_check() const {
    std::map<int64_t, FrameRecord> frames;
    std::error_code error;
    if (!std::filesystem::exists(path_, error)) return frames;
    std::ifstream in(path_, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw UserError("cannot read " + quoted_path(path_));
    const std::string not_ours = quoted_path(path_) + ": not a vkwater sequence manifest (";
    const std::string remedy = "; render into another folder, or remove the manifest to start over";
    if (json_nesting_depth(text.str()) > kMaxJsonNesting) throw UserError(not_ours + "nested too deep)" + remedy);
    const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
    if (json.is_discarded() || !json.is_object() || json.value("format", "") != kFormat) {
        throw UserError(not_ours + "its format is not '" + kFormat + "')" + remedy);
    }
    nlohmann::json found_identity = nlohmann::json::object();
    for (const auto& [key, value] : identity_.items()) {
        if (json.contains(key)) found_identity[key] = json.at(key);
    }
    const std::string difference = first_difference(identity_, found_identity, "");
    if (!difference.empty()) {
        throw UserError(quoted_path(path_) + ": records another sequence: " + difference + remedy);
    }
    try {
        for (const nlohmann::json& entry : json.at("frames")) {
            FrameRecord frame;
            frame.frame = entry.at("frame").get<int64_t>();
            frame.file = entry.at("file").get<std::string>();
            frame.water_time_s = entry.at("waterTime").get<double>();
            frame.pixel_hash = entry.at("pixelHash").get<std::string>();
            frame.frame_ms = entry.at("frameMs").get<double>();
            frame.wall_ms = entry.at("wallMs").get<double>();
            frame.device = entry.at("device").get<std::string>();
            frames[frame.frame] = std::move(frame);
        }
    } catch (const nlohmann::json::exception& e) {
        throw UserError(not_ours + "its frames: " + e.what() + ")" + remedy);
    }
    return frames;
}

void SequenceManifest::record(const FrameRecord& frame) const {
    const FolderLock lock(lock_path_);
    std::map<int64_t, FrameRecord> frames = read_and_check();
    frames[frame.frame] = frame;
    // In the order a reader wants: what it is, what made it, then the frames.
    nlohmann::ordered_json json = {{"format", kFormat}, {"scene", scene_}};
    for (const auto& [key, value] : identity_.items()) json[key] = value;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& [number, record] : frames) list.push_back(to_json(record));
    json["frames"] = std::move(list);
    // Replace, not throw, on bytes that are not UTF-8 (a path can hold any): the record must be written.
    write_file_checked(path_, json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

}  // namespace vkw::cli
