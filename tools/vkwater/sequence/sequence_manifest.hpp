// DIR/manifest.json of a frame sequence: what made the frames (the scene's hash, the settings) and,
// per frame, its file, its water time, the hash of its pixels and its times. Every process that
// renders into DIR (the tasks of a batch array, a re-run after a failure) adds its frames to the one
// file under a lock, so the folder's manifest is complete when the last task ends, with no merge.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace vkw::cli {

struct FrameRecord {
    int64_t frame = 0;
    std::string file;  // the file name, in the manifest's folder
    double water_time_s = 0.0;
    std::string pixel_hash;  // engine/image/pixel_hash.hpp, of the pixels as the file stores them
    double frame_ms = 0.0;   // the frame's device time (fences or timestamps)
    double wall_ms = 0.0;    // render, readback and writing the file
    std::string device;
};

class SequenceManifest {
public:
    // `identity`: what every frame of the folder must share, {"sceneHash": ..., "settings": {...}}.
    // The scene's path is recorded too but not compared: a task may name it from another folder.
    SequenceManifest(std::filesystem::path folder, std::string scene, nlohmann::json identity);

    // The frames an existing manifest records (none when there is no manifest yet). vkw::UserError
    // when the file is not a sequence manifest, or records another sequence: it names the first
    // setting that differs.
    std::map<int64_t, FrameRecord> recorded() const;

    // Adds `frame` (replacing an earlier record of the same frame number) under the folder's lock,
    // to the manifest as it is on disk then, and writes it whole by rename.
    void record(const FrameRecord& frame) const;

    const std::filesystem::path& path() const { return path_; }

private:
    std::map<int64_t, FrameRecord> read_and_check() const;
    std::filesystem::path path_;
    std::filesystem::path lock_path_;
    std::string scene_;
    nlohmann::json identity_;
};

}  // namespace vkw::cli
