// The viewer's panel of scene parameters (Dear ImGui): the sun's elevation and azimuth, the
// waves (model, amplitude scale, wind), the medium (preset or coefficients), the IOR, each
// effect's mode (auto / on / off, with the frame's decision and its reason beside it), the
// quality settings (water grid, FFT grid), the camera's field of view and exposure, and the
// water's clock. It edits the Scene in place, and every widget keeps to the range the scene
// loader accepts (scenes/README.md), so the edited scene is one a file could state. What
// changes the frame's needs or the graph's shape recompiles the frame graph on the next frame
// (the renderer compares its configuration).
#pragma once

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene.hpp"
#include "tools/vkwater/view/camera_controller.hpp"

namespace vkw::window {

// What the panel and the keys control beyond the scene, and the requests they make.
struct ViewControls {
    CameraMode camera_mode = CameraMode::Orbit;
    bool paused = false;
    double time_speed = 1.0;  // the water's seconds per second of frames
    bool temporal = false;    // temporal accumulation (--temporal; not with a box filter)
    bool show_panels = true;
    // Requests, cleared by the viewer once served.
    bool step = false;  // advance the paused clock by one frame
    bool screenshot = false;
    bool reload_shaders = false;
};

class ParameterPanel {
public:
    // After (re)loading the scene: its waves become the base that the amplitude scale and
    // the wind turn act on.
    void reset(const Scene& scene);
    // Draws the panel; `needs` (may be null) are the last compiled frame's decisions.
    // Returns true when it changed the scene.
    bool draw(Scene& scene, const fg::FrameNeeds* needs, ViewControls& controls);

private:
    bool draw_sun(Scene& scene);
    bool draw_waves(Scene& scene);
    bool draw_medium(Scene& scene);
    bool draw_effects(Scene& scene, const fg::FrameNeeds* needs);
    bool draw_quality(Scene& scene);
    bool draw_methods(Scene& scene);
    void apply_wave_edits(Water& water) const;
    WaveSettings base_waves_;
    double amplitude_scale_ = 1.0;
    double wind_turn_deg_ = 0.0;  // sum of waves: every component's direction turned by this
};

}  // namespace vkw::window
