// The "did you mean" hint for unknown fields.
#include <gtest/gtest.h>

#include "engine/scene/suggest.hpp"

namespace vkw {
namespace {

const std::vector<std::string> kCameraKeys = {"position", "target", "fov_y_deg", "near", "far", "exposure"};

TEST(scene_suggest, EditDistance) {
    EXPECT_EQ(edit_distance("", ""), 0u);
    EXPECT_EQ(edit_distance("near", "near"), 0u);
    EXPECT_EQ(edit_distance("naer", "near"), 1u);  // adjacent swap counts once
    EXPECT_EQ(edit_distance("positon", "position"), 1u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
}

TEST(scene_suggest, ClosestKey) {
    EXPECT_EQ(closest_key("fovy", kCameraKeys), "fov_y_deg");       // prefix, ignoring '_'
    EXPECT_EQ(closest_key("fov", kCameraKeys), "fov_y_deg");        // prefix
    EXPECT_EQ(closest_key("FOV_Y_DEG", kCameraKeys), "fov_y_deg");  // case
    EXPECT_EQ(closest_key("positon", kCameraKeys), "position");
    EXPECT_EQ(closest_key("taget", kCameraKeys), "target");
    EXPECT_EQ(closest_key("exposure_ev", kCameraKeys), "exposure");  // the valid key is a prefix
    EXPECT_EQ(closest_key("fa", kCameraKeys), "far");
    EXPECT_EQ(closest_key("colour", kCameraKeys), std::nullopt);
    EXPECT_EQ(closest_key("ab", kCameraKeys), std::nullopt);  // two edits from "far" is no evidence
    EXPECT_EQ(closest_key("x", {}), std::nullopt);
    // A short word two edits away is no evidence ("size" would become "time").
    EXPECT_EQ(closest_key("size", {"level", "half_extent", "time", "ior"}), std::nullopt);
    EXPECT_EQ(closest_key("tme", {"level", "half_extent", "time", "ior"}), "time");  // one edit
    EXPECT_EQ(closest_key("exposrue", kCameraKeys), "exposure");                     // a long word may be two off
}

}  // namespace
}  // namespace vkw
