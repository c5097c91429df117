// The script format of `vkwater view --script` (tools/vkwater/view/view_script.hpp): every command
// parsed into its fields, commands ordered by frame and by line within a frame, and every
// malformed line refused with the file, the line and the accepted form.
#include "tools/vkwater/view/view_script.hpp"
#include "engine/core/errors.hpp"

#include <gtest/gtest.h>

namespace vkw::window {
namespace {

std::string error_of(const std::string& text) {
    try {
        parse_view_script(text, "s.txt");
    } catch (const UserError& error) {
        return error.what();
    }
    return "no error";
}

TEST(ViewScript, ParsesEveryCommand) {
    const ViewScript script = parse_view_script(R"(# a comment line

7: set description=a b c     # the value keeps its spaces
0: camera 1 2 3  4 5 6.5
0: move -1 0.5 2 0 0 -1 30
3: resize 320 240
7: screenshot out/shot.exr
9: pause
9: resume
10: time 12.5
11: mode fly
12: reload-shaders
12: wait-file /tmp/go
12: heap
)",
                                                "s.txt");
    ASSERT_EQ(script.commands.size(), 12u);
    const auto& c = script.commands;
    // Sorted by frame; within frame 0 and frame 7, in the file's order.
    EXPECT_EQ(c[0].verb, ScriptVerb::Camera);
    EXPECT_EQ(c[0].position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(c[0].target, glm::dvec3(4, 5, 6.5));
    EXPECT_EQ(c[0].line, 4);  // after the comment, the blank line and the set
    EXPECT_EQ(c[1].verb, ScriptVerb::Move);
    EXPECT_EQ(c[1].position, glm::dvec3(-1, 0.5, 2));
    EXPECT_EQ(c[1].frames, 30u);
    EXPECT_EQ(c[2].verb, ScriptVerb::Resize);
    EXPECT_EQ(c[2].frame, 3u);
    EXPECT_EQ(c[2].width, 320u);
    EXPECT_EQ(c[2].height, 240u);
    EXPECT_EQ(c[3].verb, ScriptVerb::Set);
    EXPECT_EQ(c[3].text, "description=a b c");
    EXPECT_EQ(c[4].verb, ScriptVerb::Screenshot);
    EXPECT_EQ(c[4].text, "out/shot.exr");
    EXPECT_EQ(c[5].verb, ScriptVerb::Pause);
    EXPECT_EQ(c[6].verb, ScriptVerb::Resume);
    EXPECT_EQ(c[7].verb, ScriptVerb::Time);
    EXPECT_EQ(c[7].seconds, 12.5);
    EXPECT_EQ(c[8].verb, ScriptVerb::Mode);
    EXPECT_EQ(c[8].mode, CameraMode::Fly);
    EXPECT_EQ(c[9].verb, ScriptVerb::ReloadShaders);
    EXPECT_EQ(c[10].verb, ScriptVerb::WaitFile);
    EXPECT_EQ(c[10].text, "/tmp/go");
    EXPECT_EQ(c[11].verb, ScriptVerb::Heap);
    // The move at frame 0 over 30 frames arrives at frame 30: 31 frames are needed.
    EXPECT_EQ(script.frames_needed(), 31u);
}

TEST(ViewScript, RefusesMalformedLinesNamingFileAndLine) {
    struct Case {
        std::string text, needle;
    };
    const Case cases[] = {
        {"pause", "s.txt: line 1: no 'FRAME:' before the command"},
        {"\n-1: pause", "s.txt: line 2: frame: '-1' is out of range"},
        {"3:", "line 1: no command after 'FRAME:'"},
        {"3: zoom 2", "line 1: unknown command 'zoom' (accepted: FRAME: camera"},
        {"3: camera 1 2 3 4 5", "camera takes 6 arguments, got 5 (accepted: camera PX PY PZ TX TY TZ)"},
        {"3: camera 1 2 3 1 2 3", "the target is the camera position"},
        {"3: camera 1 2 x 4 5 6", "camera position: 'x' is not a finite number"},
        {"3: camera 1 2 nan 4 5 6", "'nan' is not a finite number"},
        {"3: move 0 0 0 0 0 -1 0", "move frames: '0' is out of range (accepted: an integer 1 to"},
        {"3: resize 0 100", "resize width: '0' is out of range (accepted: an integer 1 to 16384)"},
        {"3: resize 100", "resize takes 2 arguments, got 1"},
        {"3: set water.ior", "set needs KEY=VALUE, got 'water.ior'"},
        {"3: mode walk", "unknown camera mode 'walk' (accepted: orbit, fly)"},
        {"3: pause now", "pause takes 0 arguments, got 1"},
        {"3: time soon", "time: 'soon' is not a finite number"},
        {"3: wait-file", "wait-file takes 1 argument, got 0 (accepted: wait-file PATH)"},
        {"3: heap now", "heap takes 0 arguments, got 1"},
        {"3: screenshot shot", "screenshot 'shot' does not end in .exr (accepted: screenshot PATH.exr"},
        {"3: screenshot shot.png", "screenshot 'shot.png' does not end in .exr"},
    };
    for (const Case& c : cases) {
        const std::string message = error_of(c.text);
        EXPECT_NE(message.find(c.needle), std::string::npos) << "script '" << c.text << "' gave: " << message;
    }
}

TEST(ViewScript, RefusesCommandsBeyondTheLastFrame) {
    const ViewScript script = parse_view_script("10: pause\n100: move 0 0 0 0 0 -1 20\n", "s.txt");
    EXPECT_NO_THROW(check_script_fits(script, 121));
    try {
        check_script_fits(script, 120);
        FAIL() << "a move arriving at frame 120 fits no run of 120 frames (0 to 119)";
    } catch (const UserError& error) {
        EXPECT_NE(std::string(error.what())
                      .find("s.txt: line 2: move at frame 100 (+20 frames) would not run within "
                            "--frames 120 (accepted: frames 0 to 119)"),
                  std::string::npos)
            << error.what();
    }
}

// The example shipped for users (docs/viewer.md) parses, and fits the frame count it names.
TEST(ViewScript, TheShippedTourParsesAndFitsItsFrames) {
    const ViewScript script = load_view_script(VKWATER_SOURCE_DIR "/scenes/scripts/pool_tour.txt");
    EXPECT_EQ(script.commands.size(), 10u);
    EXPECT_EQ(script.frames_needed(), 600u);
    check_script_fits(script, 600);
}

TEST(ViewScript, MissingFileIsAUserError) { EXPECT_THROW(load_view_script("/nonexistent/script.txt"), UserError); }

}  // namespace
}  // namespace vkw::window
