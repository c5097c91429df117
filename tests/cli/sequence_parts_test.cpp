// A sequence's parts without a device: frame ranges, shards, the file name pattern.
#include "engine/core/errors.hpp"
#include "tools/vkwater/sequence/frame_pattern.hpp"
#include "tools/vkwater/sequence/frame_selection.hpp"
#include "tools/vkwater/sequence/sequence_manifest.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <thread>

namespace vkw::cli {
namespace {

TEST(FrameRange, ListsItsFramesInclusively) {
    EXPECT_EQ(parse_frame_range("0:3").frames(), (std::vector<int64_t>{0, 1, 2, 3}));
    EXPECT_EQ(parse_frame_range("10:20:5").frames(), (std::vector<int64_t>{10, 15, 20}));
    EXPECT_EQ(parse_frame_range("10:21:5").frames(), (std::vector<int64_t>{10, 15, 20}));
    EXPECT_EQ(parse_frame_range("7:7").frames(), (std::vector<int64_t>{7}));
    EXPECT_EQ(parse_frame_range("10:21:5").count(), 3);
    EXPECT_EQ(parse_frame_range("0:10000000").count(), 10000001);
    for (const char* bad : {"", "3", "a:b", "1:", ":4", "-1:3", "0:3:", "0:3:1:1", " 0:3", "0:3 ", "0x1:3", "5:2",
                            "0:3:0", "0:10000001"}) {
        EXPECT_THROW(parse_frame_range(bad), UserError) << bad;
    }
}

// The shards of any split cover the range once: no frame twice, none left out, and their sizes
// differ by one at most.
TEST(Shard, TheTasksOfAnArrayCoverTheRangeOnce) {
    const FrameRange range = parse_frame_range("3:40:3");
    const std::vector<int64_t> all = range.frames();
    const size_t total = all.size();
    for (uint32_t count : {1u, 2u, 4u, 5u, 13u, 14u, 20u}) {
        std::multiset<int64_t> seen;
        for (uint32_t index = 0; index < count; ++index) {
            const std::vector<int64_t> mine =
                parse_shard(std::to_string(index) + "/" + std::to_string(count)).frames_of(range);
            EXPECT_LE(mine.size(), total / count + 1);
            EXPECT_GE(mine.size(), total / count);
            seen.insert(mine.begin(), mine.end());
        }
        EXPECT_EQ(seen, std::multiset<int64_t>(all.begin(), all.end())) << count;
    }
    for (const char* bad : {"", "1", "2/2", "0/0", "-1/2", "1/2/3", "a/b", "0/100001"}) {
        EXPECT_THROW(parse_shard(bad), UserError) << bad;
    }
}

TEST(FramePattern, NamesEachFrame) {
    EXPECT_EQ(FramePattern("out/pool_%04d.exr").file_for(7), "out/pool_0007.exr");
    EXPECT_EQ(FramePattern("out/pool_%04d.exr").file_for(123456), "out/pool_123456.exr");
    EXPECT_EQ(FramePattern("f%d.EXR").file_for(12), "f12.EXR");
    EXPECT_EQ(FramePattern("a/100%%_%02d.exr").file_for(3), "a/100%_03.exr");
    EXPECT_EQ(FramePattern("out/pool_%04d.exr").folder(), "out");
    EXPECT_EQ(FramePattern("out/pool_%04d.exr").name_pattern(), "pool_%04d.exr");
    for (const char* bad : {"x.exr", "x_%d_%d.exr", "x_%04d.png", "x_%4d.exr", "x_%010d.exr", "x_%s.exr", "x_%.exr",
                            "d%d/x_%d.exr", "x_%00d.exr", "x_%d"}) {
        EXPECT_THROW(FramePattern{bad}, UserError) << bad;
    }
}

// Tasks that finish frames at the same moment all end up in the one manifest: each adds its frame
// under the folder's lock to the file as it is then (without the lock, concurrent read-modify-write
// loses frames). Threads stand in for processes: each opens the lock file itself, and flock locks
// per open file.
TEST(SequenceManifest, ConcurrentTasksLoseNoFrame) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / "vkwater_manifest_concurrent";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const nlohmann::json identity = {{"sceneHash", "0123"}, {"settings", {{"width", 8}}}};
    constexpr int kTasks = 6;
    constexpr int kFramesEach = 25;
    std::vector<std::thread> tasks;
    for (int task = 0; task < kTasks; ++task) {
        tasks.emplace_back([&, task] {
            const SequenceManifest manifest(folder, "scene.json", identity);
            for (int i = 0; i < kFramesEach; ++i) {
                const int64_t frame = int64_t(i) * kTasks + task;
                manifest.record({frame, "f" + std::to_string(frame) + ".exr", 0.0, "hash", 1.0, 2.0, "device"});
            }
        });
    }
    for (std::thread& task : tasks) task.join();
    const std::map<int64_t, FrameRecord> frames = SequenceManifest(folder, "scene.json", identity).recorded();
    ASSERT_EQ(frames.size(), size_t(kTasks * kFramesEach));
    EXPECT_EQ(frames.begin()->first, 0);
    EXPECT_EQ(frames.rbegin()->first, kTasks * kFramesEach - 1);
    // Another sequence's settings are refused, naming the first that differs.
    const nlohmann::json other = {{"sceneHash", "0123"}, {"settings", {{"width", 9}}}};
    try {
        SequenceManifest(folder, "scene.json", other).recorded();
        FAIL() << "another sequence's manifest was accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("settings.width is 8 (this run: 9)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vkw::cli
