// `vkwater view` run as a user runs it, under a virtual X server (xvfb-run -a) on the default
// device: a 120-frame script that resizes the window, crosses the water surface and toggles
// the caustics, with validation; the viewer's own EXR screenshot of a still frame against
// `vkwater render` of the same scene and camera; bad input, each with its exit code (README:
// 1 for the user's mistakes, 2 for the machine's, such as no display) and one clear line.
#include "engine/image/exr_io.hpp"
#include "tools/metrics/metrics.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <glm/glm.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / "vkwater_view_test";
    fs::create_directories(dir);
    return dir / name;
}

fs::path write_text(const std::string& name, const std::string& text) {
    const fs::path path = scratch(name);
    std::ofstream(path) << text;
    return path;
}

const std::string kScenes = std::string(VKWATER_SOURCE_DIR) + "/scenes/";

struct Outcome {
    int exit_code = -1;
    std::string output;  // stdout and stderr
};

// Runs the vkwater executable with `arguments`, on a fresh virtual display or on none. The
// output goes through a file of the test's own: ctest runs tests side by side.
Outcome vkwater(const std::string& arguments, bool with_display = true) {
    const fs::path log = scratch(std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".log");
    const std::string prefix = with_display ? "xvfb-run -a " : "env -u DISPLAY -u WAYLAND_DISPLAY ";
    const std::string command = prefix + "'" VKWATER_CLI "' " + arguments + " > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    Outcome outcome;
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::ostringstream text;
    text << std::ifstream(log).rdbuf();
    outcome.output = text.str();
    return outcome;
}

bool has_xvfb_run() { return std::system("command -v xvfb-run > /dev/null 2>&1") == 0; }

// The summary's line for a pass (vkwater view prints one per pass timed), or "".
std::string summary_line(const std::string& output, const std::string& pass) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("  " + pass + " ", 0) == 0) return line;
    }
    return "";
}

class ViewWindow : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(has_xvfb_run()) << "xvfb-run is missing (Debian: xvfb xauth; tools/install-deps.sh installs them)";
    }
};

TEST_F(ViewWindow, ScriptedRunResizesCrossesTheSurfaceAndTogglesCausticsWithoutValidationMessages) {
    const fs::path under = scratch("under_water.exr"), last = scratch("last.exr");
    fs::remove(under);
    fs::remove(last);
    // calm.json: flat water at y = 0 over a floor at y = -2. The camera glides from 1 m above
    // the surface to 0.8 m below it over frames 10-60 (crossing near frame 38, where the near
    // plane straddles the surface), flies back up over frames 90-110.
    const fs::path script = write_text("cross.txt",
                                       "0: camera 0 1.0 3   0 -1.0 -1\n"
                                       "10: move 0 -0.8 3   0 -1.5 -1  50\n"
                                       "20: set effects.caustics.mode=off\n"
                                       "30: resize 200 150\n"
                                       "40: screenshot " +
                                           under.string() +
                                           "\n"
                                           "45: set effects.caustics.mode=on\n"
                                           "60: mode fly\n"
                                           "70: resize 160 120\n"
                                           "80: set effects.caustics.mode=auto\n"
                                           "90: move 0 0.6 2   0 -0.5 -2  20\n"
                                           "115: screenshot " +
                                           last.string() + "\n");
    const Outcome run = vkwater("view " + kScenes +
                                "calm.json --set water.grid_resolution=64 --width 160 --height 120 "
                                "--frames 120 --script " +
                                script.string() + " --validation --pass-timing-every 10");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.output.find("validation error"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("validation warning"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("(with validation)"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("frames: 120;"), std::string::npos) << run.output;
    // Under the water the camera-medium split ran; with the caustics off for a while, their passes
    // ran in fewer timing frames than the others.
    EXPECT_NE(summary_line(run.output, "camera medium"), "") << run.output;
    EXPECT_NE(summary_line(run.output, "caustic photons").find("(ran in"), std::string::npos) << run.output;
    EXPECT_EQ(summary_line(run.output, "sky").find("(ran in"), std::string::npos) << run.output;
    // Each screenshot has the window's size of its frame.
    const vkw::ImageRGBA32F under_image = vkw::read_exr(under), last_image = vkw::read_exr(last);
    EXPECT_EQ(under_image.width, 200);
    EXPECT_EQ(under_image.height, 150);
    EXPECT_EQ(last_image.width, 160);
    EXPECT_EQ(last_image.height, 120);
    EXPECT_TRUE(fs::exists(fs::path(last).replace_extension(".png")));
}

TEST_F(ViewWindow, SwitchingToTheSeedsMethodsLiveStaysValidationClean) {
    // The methods the panel's "Methods" section switches: camera-space splats (their view and
    // flux follow the window's size, so a resize rebuilds them), the procedural caustic, Optical Phenomena c. 2008's
    // surface shading, and back.
    const fs::path script = write_text("methods.txt",
                                       "5: set effects.caustics.splat=camera-space\n"
                                       "15: resize 200 150\n"
                                       "25: set effects.water.fresnel=power\n"
                                       "30: set effects.water.depth_blend={}\n"
                                       "35: set effects.caustics.splat=light-space\n"
                                       "36: set effects.caustics.method=procedural\n");
    const Outcome run = vkwater("view " + kScenes +
                                "pool.json --set water.grid_resolution=64 --width 160 --height 120 "
                                "--frames 45 --script " +
                                script.string() + " --validation --pass-timing-every 5");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.output.find("validation error"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("validation warning"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("frames: 45;"), std::string::npos) << run.output;
    EXPECT_NE(summary_line(run.output, "camera caustic splats").find("(ran in"), std::string::npos) << run.output;
    EXPECT_NE(summary_line(run.output, "caustic procedural"), "") << run.output;
}

TEST_F(ViewWindow, ScreenshotOfAStillFrameEqualsTheOffscreenRender) {
    const fs::path shot = scratch("still.exr"), rendered = scratch("rendered.exr");
    fs::remove(shot);
    // pool.json: waves and caustics; a camera pose of the script's own, the clock stopped at
    // the file's time, a reduced grid for speed.
    const std::string settings = " --set water.grid_resolution=64 --width 160 --height 120";
    const fs::path script = write_text("still.txt",
                                       "0: camera 0.3 0.9 3.1   -0.2 -1.4 -1.8\n"
                                       "2: screenshot " +
                                           shot.string() + "\n");
    const Outcome view =
        vkwater("view " + kScenes + "pool.json" + settings + " --paused --frames 3 --script " + script.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const Outcome render = vkwater("render " + kScenes + "pool.json" + settings +
                                       " --set camera.position=[0.3,0.9,3.1] --set camera.target=[-0.2,-1.4,-1.8]"
                                       " --out " +
                                       rendered.string(),
                                   false);
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const vkw::metrics::Metrics error = vkw::metrics::compare_images(vkw::read_exr(shot), vkw::read_exr(rendered));
    // The bound, relMSE < 1e-4. Both images come from the same passes with the same constants, so
    // they agree bit for bit (relMSE 0 measured). Defects the bound catches, measured on this
    // frame with vkwater render and compare: the water's clock one 60 Hz frame off, relMSE
    // 1.4e-3; the camera and its target 3 mm higher, 7e-4; the camera alone 3 mm higher,
    // 2.9e-4 (this test fails then); 1 mm gives 8e-5, about the bound's resolution.
    // The exposure does not enter: the EXR is the radiance before display.
    EXPECT_LT(error.rel_mse, 1e-4);
    // The screenshot records how it was made, as the render does: the viewer's own camera pose.
    const vkw::ImageRGBA32F image = vkw::read_exr(shot);
    auto value = [&](const std::string& name) {
        for (const vkw::ImageAttribute& a : image.attributes) {
            if (a.name == name) return a.value;
        }
        return std::string("(missing)");
    };
    EXPECT_EQ(value("vkwater/renderer"), "real-time (vkwater view)");
    EXPECT_EQ(value("vkwater/overrides"), "water.grid_resolution=64");
    EXPECT_NE(value("vkwater/camera").find("position [0.3"), std::string::npos) << value("vkwater/camera");
    EXPECT_NE(value("software").find("vkwater "), std::string::npos);
}

TEST_F(ViewWindow, ShaderReloadRereadsTheSpvFiles) {
    // A private copy of the compiled shaders, in which the test replaces the sky's between
    // two frames: the script holds the viewer at frame 3 until the replacement is in place.
    const fs::path shaders = scratch("shaders");
    fs::remove_all(shaders);
    fs::copy(fs::path(VKWATER_BINARY_DIR) / "shaders", shaders, fs::copy_options::recursive);
    const fs::path before = scratch("before_reload.exr"), after = scratch("after_reload.exr"), go = scratch("go");
    for (const fs::path& path : {before, fs::path(before).replace_extension(".png"), after, go}) fs::remove(path);
    const fs::path script = write_text("reload.txt", "2: screenshot " + before.string() +
                                                         "\n"
                                                         "3: wait-file " +
                                                         go.string() +
                                                         "\n"
                                                         "3: reload-shaders\n"
                                                         "3: screenshot " +
                                                         after.string() + "\n");
    const std::string command = "VKWATER_SHADER_DIR='" + shaders.string() + "' xvfb-run -a '" VKWATER_CLI "' view " +
                                kScenes +
                                "pool.json --set water.grid_resolution=64 --width 160 --height 120 --paused "
                                "--frames 5 --pass-timing-every 0 --validation --script " +
                                script.string() + " 2>&1";
    FILE* viewer = ::popen(command.c_str(), "r");
    ASSERT_NE(viewer, nullptr);
    // The PNG is written after the EXR: once it is there, frame 2 is complete.
    for (int i = 0; i < 6000 && !fs::exists(fs::path(before).replace_extension(".png")); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    // pool.json's camera is above the water: the sky pass runs its per-frame-medium variant.
    fs::copy_file(shaders / "tests" / "sky_doubled.frag.spv", shaders / "sky" / "sky.frag.frame.spv",
                  fs::copy_options::overwrite_existing);
    std::ofstream(go) << "go";
    std::string output;
    char buffer[4096];
    while (size_t n = std::fread(buffer, 1, sizeof buffer, viewer)) output.append(buffer, n);
    const int status = ::pclose(viewer);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
    EXPECT_NE(output.find("reloaded shaders from " + shaders.string()), std::string::npos) << output;

    // The sky pass now writes twice the radiance (exact in fp32). In pool.json's view the top
    // rows are the sky alone: exactly doubled. The lower half is the water near the camera,
    // drawn over the sky pass (it reflects the sky through its own shader): unchanged, bit
    // for bit. (The rows between, near the horizon, mix both.)
    const vkw::ImageRGBA32F one = vkw::read_exr(before), two = vkw::read_exr(after);
    ASSERT_EQ(one.width, 160);
    ASSERT_EQ(two.width, 160);
    ASSERT_EQ(one.height, 120);
    ASSERT_EQ(two.height, 120);
    for (int y : {0, 5, 9, 60, 90, 119}) {
        for (int x = 0; x < one.width; ++x) {
            const float* a = one.pixel(x, y);
            const float* b = two.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                if (y < 10) {
                    ASSERT_GT(a[c], 0.0f);
                    ASSERT_EQ(b[c], 2.0f * a[c]) << x << "," << y << " channel " << c;
                } else {
                    ASSERT_EQ(b[c], a[c]) << x << "," << y << " channel " << c;
                }
            }
        }
    }
}

// The camera pose the viewer prints at exit, and its mode.
struct ExitPose {
    std::string mode;
    glm::dvec3 position{0.0}, target{0.0};
};
std::optional<ExitPose> exit_pose(const std::string& output) {
    ExitPose pose;
    char mode[16] = {};
    const size_t at = output.find("camera at exit (");
    if (at == std::string::npos) return std::nullopt;
    const int read = std::sscanf(output.c_str() + at,
                                 "camera at exit (%15[a-z]): --set camera.position=[%lf,%lf,%lf] "
                                 "--set camera.target=[%lf,%lf,%lf]",
                                 mode, &pose.position.x, &pose.position.y, &pose.position.z, &pose.target.x,
                                 &pose.target.y, &pose.target.z);
    if (read != 7) return std::nullopt;
    pose.mode = mode;
    return pose;
}

TEST_F(ViewWindow, KeysAndMouseDriveTheCamera) {
    ASSERT_EQ(std::system("command -v xdotool > /dev/null 2>&1"), 0)
        << "xdotool is missing (tools/install-deps.sh installs it)";
    const fs::path prefix = scratch("keys");
    fs::remove(scratch("keys-0.png"));
    // Inside the virtual display: the viewer in the background, then keys and mouse through
    // XTEST. F12's screenshot shows that the viewer is up and reading input before W is held;
    // a held key moves the camera only while frames run.
    const fs::path driver = write_text("drive.sh", R"(#!/bin/sh
"$1" view "$2" --set water.grid_resolution=64 --width 320 --height 240 --paused --validation \
    --screenshot-prefix "$3" &
viewer=$!
window=$(xdotool search --sync --name "vkwater view")
xdotool mousemove --window "$window" 200 120
xdotool key F1 key F12
for i in $(seq 600); do [ -f "$3-0.png" ] && break; sleep 0.1; done
xdotool key Tab keydown w
sleep 1.5
xdotool keyup w
xdotool mousedown 1 mousemove_relative 20 0 mousemove_relative 20 0 mousemove_relative 20 0 mouseup 1
sleep 0.5
xdotool key Escape
wait "$viewer"
)");
    const fs::path log = scratch("keys.log");
    const std::string command = "xvfb-run -a sh '" + driver.string() + "' '" VKWATER_CLI "' " + kScenes +
                                "pool.json '" + prefix.string() + "' > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ostringstream text;
    text << std::ifstream(log).rdbuf();
    const std::string output = text.str();
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;  // Esc closed it
    EXPECT_EQ(output.find("validation error"), std::string::npos) << output;
    EXPECT_TRUE(fs::exists(scratch("keys-0.png"))) << output;  // F12
    const std::optional<ExitPose> pose = exit_pose(output);
    ASSERT_TRUE(pose) << output;
    EXPECT_EQ(pose->mode, "fly") << output;  // Tab
    // W flew along pool.json's view, from (0, 1.2, 4) toward (0, -1.5, -2), at half the
    // distance to the target per second (3.3 m/s) for 1.5 s: about 4.6 m after the easing.
    // 0.3 m still passes if a loaded machine ran only a tenth of the frames in that time.
    const glm::dvec3 start(0.0, 1.2, 4.0), view = glm::normalize(glm::dvec3(0.0, -2.7, -6.0));
    EXPECT_GT(glm::dot(pose->position - start, view), 0.3) << output;
    // The drag of 60 pixels to the right turned the view 15 degrees to the right (+x).
    const glm::dvec3 now = glm::normalize(pose->target - pose->position);
    EXPECT_NEAR(std::atan2(now.x, -now.z) * 180.0 / 3.14159265358979323846, 15.0, 1e-6) << output;
}

// On a CPU device a scene that would run at seconds a frame says so before its first frame, with
// what makes it faster; an ordinary one says nothing. 1024^2 godray beams over an 80-column
// godray image are 3.5 s a frame by the estimate (tools/vkwater/cpu_frame_estimate.hpp).
TEST_F(ViewWindow, ASlowSceneIsAnnouncedOnACpuDevice) {
    const std::string view = "view " + kScenes + "pool.json --frames 1 --width 160 --height 120";
    const Outcome slow = vkwater(view + " --set effects.godrays.grid=1024");
    ASSERT_EQ(slow.exit_code, 0) << slow.output;
    EXPECT_NE(slow.output.find("note: 1048576 photons, 1048576 godray beams over 80 columns: about "),
              std::string::npos)
        << slow.output;
    EXPECT_NE(slow.output.find("effects.godrays.grid makes it faster"), std::string::npos) << slow.output;
    const Outcome ordinary = vkwater(view);
    ASSERT_EQ(ordinary.exit_code, 0) << ordinary.output;
    EXPECT_EQ(ordinary.output.find("note:"), std::string::npos) << ordinary.output;
}

// With a frame-time budget the viewer says so at start, changes its settings under validation
// (each change makes new targets and pipelines) and prints where it ended; a scripted run has no
// budget unless asked, so that it repeats. Which settings a budget reaches depends on the
// machine's speed: pool's own take 20 to 40 ms a frame at 320x240 here, so 5 ms must turn
// something down on lavapipe (on a GPU the scene's own settings may fit, and the test says so).
// --spp 4: each frame shown is the mean of 4 sub-frames, summed on the device in the order and the
// fp32 operations vkwater render --spp 4 takes on the CPU, so the screenshot is that image bit for
// bit (relMSE exactly 0; the point-sampled frame differs from it by relMSE 0.026, so
// a wrong shift or a missing sub-frame cannot pass). Under validation; the device objects are made
// twice (the sub-frame that makes the caustic map, and those that read it) and then reused. With
// --budget-ms the samples are a knob, at most --spp's.
TEST_F(ViewWindow, SupersampledScreenshotEqualsTheOffscreenRenderBitForBit) {
    const fs::path shot = scratch("supersampled.exr"), rendered = scratch("supersampled_render.exr"),
                   point = scratch("point_render.exr");
    fs::remove(shot);
    const std::string settings = " --set water.grid_resolution=64 --width 160 --height 120";
    const std::string pose = " --set camera.position=[0.3,0.9,3.1] --set camera.target=[-0.2,-1.4,-1.8]";
    const fs::path script = write_text("supersampled.txt",
                                       "0: camera 0.3 0.9 3.1   -0.2 -1.4 -1.8\n"
                                       "4: screenshot " +
                                           shot.string() + "\n");
    const Outcome view = vkwater("view " + kScenes + "pool.json" + settings +
                                 " --paused --frames 5 --spp 4 --validation --script " + script.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    EXPECT_NE(view.output.find("device objects made 2 times"), std::string::npos) << view.output;
    const Outcome render =
        vkwater("render " + kScenes + "pool.json" + settings + pose + " --spp 4 --out " + rendered.string(), false);
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const Outcome centres =
        vkwater("render " + kScenes + "pool.json" + settings + pose + " --out " + point.string(), false);
    ASSERT_EQ(centres.exit_code, 0) << centres.output;
    const vkw::ImageRGBA32F image = vkw::read_exr(shot);
    EXPECT_EQ(vkw::metrics::compare_images(image, vkw::read_exr(rendered)).rel_mse, 0.0);
    EXPECT_GT(vkw::metrics::compare_images(image, vkw::read_exr(point)).rel_mse, 1e-4);
    bool filter_recorded = false;
    for (const vkw::ImageAttribute& a : image.attributes) {
        if (a.name == "vkwater/filter") filter_recorded = a.value.rfind("box: 4 samples per pixel", 0) == 0;
    }
    EXPECT_TRUE(filter_recorded);
    // A budget may take up to --spp's samples: on lavapipe 5 ms is out of reach even at one, so it
    // ends there (the options at exit name --spp only above one), under validation throughout
    // its changes of filter.
    const Outcome budgeted =
        vkwater("view " + kScenes + "pool.json" + settings + " --frames 40 --spp 4 --budget-ms 5 --validation");
    ASSERT_EQ(budgeted.exit_code, 0) << budgeted.output;
    const size_t at_exit = budgeted.output.find("settings at exit: ");
    ASSERT_NE(at_exit, std::string::npos) << budgeted.output;
    if (budgeted.output.find("llvmpipe") != std::string::npos) {
        const std::string line = budgeted.output.substr(at_exit, budgeted.output.find('\n', at_exit) - at_exit);
        EXPECT_EQ(line.find("--spp"), std::string::npos) << line;
        EXPECT_EQ(line.find("the scene's own settings"), std::string::npos) << line;
    }
    // A budget no device misses keeps all four samples, and says so.
    const Outcome generous =
        vkwater("view " + kScenes + "pool.json" + settings + " --frames 12 --spp 4 --budget-ms 100000");
    ASSERT_EQ(generous.exit_code, 0) << generous.output;
    EXPECT_NE(generous.output.find("settings at exit: --spp 4 (0 changes)"), std::string::npos) << generous.output;
}

// The budget's previews measure the on/off knobs where the camera is (tools/vkwater/budget_previews.hpp):
// at start, and again once the camera has moved and then rested 30 frames. Box's red box, seen from
// above and reflected, then from a camera turned away from it, where neither lookup shows it. Under
// validation: the previews render between the window's frames.
TEST_F(ViewWindow, TheBudgetsPreviewsAreMadeAgainWhereTheCameraRests) {
    const fs::path script = write_text("budget_previews.txt", "2: camera 6 1.5 6   12 -1 12\n");
    const Outcome view = vkwater("view " + kScenes + "box.json --width 160 --height 120 --frames 40 --budget-ms 1000" +
                                 " --validation --script " + script.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    std::vector<std::string> lines;
    for (size_t at = view.output.find("budget: turned off in"); at != std::string::npos;
         at = view.output.find("budget: turned off in", at + 1)) {
        lines.push_back(view.output.substr(at, view.output.find('\n', at) - at));
    }
    ASSERT_EQ(lines.size(), 2u) << view.output;
    // From the start the reflected box is the reflection lookup's loss; looking away, nothing is.
    ASSERT_NE(lines[0].find("the reflection lookup "), std::string::npos) << lines[0];
    EXPECT_EQ(lines[0].find("the reflection lookup 0,"), std::string::npos) << lines[0];
    EXPECT_NE(lines[1].find("the reflection lookup 0,"), std::string::npos) << lines[1];
}

// --temporal: the view accumulates its frames as vkwater render --frames ... --temporal does, so the
// screenshot of frame 4 is that sequence's frame 4 bit for bit (relMSE exactly 0), and not the
// frame without accumulation (relMSE about 7e-5: the jittered edges of calm's flat water). Under
// validation. Calm's surface does not move, so the view's clock and the sequence's need not agree.
TEST_F(ViewWindow, TemporalScreenshotEqualsTheTemporalSequenceFrameBitForBit) {
    const fs::path shot = scratch("temporal.exr"), point = scratch("temporal_point.exr");
    const fs::path frames = scratch("temporal_frames");
    fs::remove(shot);
    fs::remove_all(frames);
    std::ifstream calm(kScenes + "calm.json");
    std::string text((std::istreambuf_iterator<char>(calm)), std::istreambuf_iterator<char>());
    const std::string direction = "\"direction\": [0, -1, -1]";
    ASSERT_NE(text.find(direction), std::string::npos);
    text.replace(text.find(direction), direction.size(), "\"target\": [0, 2, 2]");  // the view's camera has a target
    const fs::path scene = write_text("calm_target.json", text);
    const std::string size = " --width 160 --height 120";
    const std::string pose = " --set camera.position=[0.3,0.9,3.1] --set camera.target=[-0.2,-1.4,-1.8]";
    const fs::path script =
        write_text("temporal.txt", "0: camera 0.3 0.9 3.1   -0.2 -1.4 -1.8\n4: screenshot " + shot.string() + "\n");
    const Outcome view =
        vkwater("view " + scene.string() + size + " --frames 5 --temporal --validation --script " + script.string());
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const Outcome sequence = vkwater("render " + scene.string() + size + pose + " --frames 0:4 --temporal --out " +
                                         (frames / "calm_%04d.exr").string(),
                                     false);
    ASSERT_EQ(sequence.exit_code, 0) << sequence.output;
    const Outcome plain = vkwater("render " + scene.string() + size + pose + " --out " + point.string(), false);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const vkw::ImageRGBA32F image = vkw::read_exr(shot);
    EXPECT_EQ(vkw::metrics::compare_images(image, vkw::read_exr(frames / "calm_0004.exr")).rel_mse, 0.0);
    EXPECT_GT(vkw::metrics::compare_images(image, vkw::read_exr(point)).rel_mse, 1e-5);
    // With a box filter of its own it is refused: the two would jitter twice.
    const Outcome both = vkwater("view " + scene.string() + size + " --frames 2 --temporal --spp 4");
    EXPECT_EQ(both.exit_code, 1) << both.output;
    EXPECT_NE(both.output.find("--spp 4: --temporal jitters its frames within the pixel itself"), std::string::npos)
        << both.output;
}

TEST_F(ViewWindow, ABudgetIsAnnouncedChangesSettingsCleanlyAndEndsWithThem) {
    const std::string view = "view " + kScenes + "pool.json --width 320 --height 240 --validation";
    const Outcome budgeted = vkwater(view + " --frames 60 --budget-ms 5");
    ASSERT_EQ(budgeted.exit_code, 0) << budgeted.output;
    EXPECT_NE(budgeted.output.find("budget: 5 ms a frame (--budget-ms;"), std::string::npos) << budgeted.output;
    const size_t settings = budgeted.output.find("settings at exit: ");
    ASSERT_NE(settings, std::string::npos) << budgeted.output;
    if (budgeted.output.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(budgeted.output.find("settings at exit: the scene's own settings"), std::string::npos)
            << budgeted.output;
    }
    const Outcome scripted = vkwater(view + " --frames 2");
    ASSERT_EQ(scripted.exit_code, 0) << scripted.output;
    EXPECT_EQ(scripted.output.find("budget"), std::string::npos) << scripted.output;
    const Outcome both = vkwater(view + " --frames 2 --budget-ms 5 --render-scale 0.5");
    EXPECT_EQ(both.exit_code, 1) << both.output;
    EXPECT_NE(both.output.find("--budget-ms chooses the resolution scale itself"), std::string::npos) << both.output;
}

TEST_F(ViewWindow, MissingSceneIsAUserError) {
    const Outcome run = vkwater("view /nonexistent/scene.json --frames 1");
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("cannot open scene file '/nonexistent/scene.json'"), std::string::npos) << run.output;
}

TEST_F(ViewWindow, NoDisplayIsAMachineErrorThatSaysWhatToDo) {
    const Outcome run = vkwater("view " + kScenes + "calm.json --frames 1", false);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("vkwater: no display:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("xvfb-run -a"), std::string::npos) << run.output;
}

TEST_F(ViewWindow, MalformedScriptNamesFileAndLine) {
    const fs::path script = write_text("bad.txt", "0: pause\n5: zoom 2\n");
    const Outcome run = vkwater("view " + kScenes + "calm.json --frames 10 --script " + script.string());
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find(script.string() + ": line 2: unknown command 'zoom'"), std::string::npos) << run.output;
}

TEST_F(ViewWindow, ScriptBeyondTheLastFrameIsRefused) {
    const fs::path script = write_text("late.txt", "200: pause\n");
    const Outcome run = vkwater("view " + kScenes + "calm.json --frames 120 --script " + script.string());
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("line 1: pause at frame 200 would not run within --frames 120"), std::string::npos)
        << run.output;
}

TEST_F(ViewWindow, UnwritableScreenshotIsRefusedBeforeTheWindowOpens) {
    const fs::path script = write_text("unwritable.txt", "1: screenshot /nonexistent/dir/shot.exr\n");
    const Outcome run = vkwater("view " + kScenes + "calm.json --frames 3 --script " + script.string());
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("cannot write '/nonexistent/dir/shot.exr'"), std::string::npos) << run.output;
}

TEST_F(ViewWindow, UnknownPresentModeIsAUserError) {
    const Outcome run = vkwater("view " + kScenes + "calm.json --frames 1 --present vsync");
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("--present"), std::string::npos) << run.output;
}

}  // namespace
