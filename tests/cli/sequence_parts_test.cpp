// A sequence's parts without a device: frame ranges, shards, the file name pattern.
#include "engine/core/errors.hpp"
#include "tools/vkwater/sequence/frame_pattern.hpp"
#include "tools/vkwater/sequence/frame_selection.hpp"

#include <gtest/gtest.h>

#include <set>

namespace vkw::cli {
namespace {

TEST(FrameRange, ListsItsFramesInclusively) {
    EXPECT_EQ(parse_frame_range("0:3").frames(), (std::vector<int64_t>{0, 1, 2, 3}));
    EXPECT_EQ(parse_frame_range("10:20:5").frames(), (std::vector<int64_t>{10, 15, 20}));
    EXPECT_EQ(parse_frame_range("10:21:5").frames(), (std::vector<int64_t>{10, 15, 20}));
    EXPECT_EQ(parse_frame_range("7:7").frames(), (std::vector<int64_t>{7}));
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

}  // namespace
}  // namespace vkw::cli
