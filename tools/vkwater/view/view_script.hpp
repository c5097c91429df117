// The script of `vkwater view --script FILE`: camera poses, window sizes and scene changes by
// frame, so that a run is repeatable (tests, benchmarks). One command per line:
//
//   FRAME: COMMAND ARGUMENTS      FRAME is the 0-based frame the command runs before
//   # comment                     (also after a command); blank lines are ignored
//
//   camera PX PY PZ TX TY TZ      put the camera at P looking at T (metres)
//   move PX PY PZ TX TY TZ N      glide there over N frames, linearly, arriving at frame FRAME + N
//   resize W H                    resize the window's framebuffer to W x H pixels
//   set KEY=VALUE                 a scene override exactly as --set takes it; the scene is
//                                 reloaded from its file with every --set and every set so far
//   screenshot PATH               after the frame: its linear HDR as OpenEXR at PATH (32-bit
//                                 float) and its displayed picture as PNG beside it (.png)
//   pause | resume                stop or restart the water's clock
//   time SECONDS                  set the water's clock
//   mode orbit|fly                the camera mode
//   reload-shaders                re-read the .spv files (as the F5 key does)
//   wait-file PATH                hold the frame loop until PATH exists (at most 60 s): lets an
//                                 outside step, e.g. a shader rebuild, happen between two frames
//   heap                          print the bytes the process's C heap holds in use, all threads'
//                                 arenas together: "heap: frame F, B bytes in use" (leak checks)
//
// Commands of one frame run in the file's order. Errors are UserErrors naming the file, the
// line, and the accepted form.
#pragma once

#include "tools/vkwater/view/camera_controller.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vkw::window {

enum class ScriptVerb : uint8_t {
    Camera,
    Move,
    Resize,
    Set,
    Screenshot,
    Pause,
    Resume,
    Time,
    Mode,
    ReloadShaders,
    WaitFile,
    Heap
};
const char* script_verb_name(ScriptVerb verb);

struct ScriptCommand {
    uint32_t frame = 0;
    ScriptVerb verb = ScriptVerb::Pause;
    int line = 0;                    // 1-based, for messages
    glm::dvec3 position{0.0};        // camera, move
    glm::dvec3 target{0.0};          // camera, move
    uint32_t frames = 0;             // move
    uint32_t width = 0, height = 0;  // resize
    std::string text;                // set: "key=value"; screenshot, wait-file: the path
    double seconds = 0.0;            // time
    CameraMode mode = CameraMode::Orbit;
};

struct ViewScript {
    std::string name;                     // the file, for messages
    std::vector<ScriptCommand> commands;  // sorted by frame, file order within a frame
    // One past the last frame a command runs before (a move counts its frames).
    uint32_t frames_needed() const;
};

ViewScript parse_view_script(std::string_view text, const std::string& name_for_messages);
ViewScript load_view_script(const std::filesystem::path& file);

// Refuses (UserError) a command that would never run within `frames` frames, naming its line.
void check_script_fits(const ViewScript& script, uint32_t frames);

}  // namespace vkw::window
