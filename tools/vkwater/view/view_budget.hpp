// The viewer's frame-time budget (vkwater view --budget-ms): the controller for the scene as
// loaded (tools/vkwater/budget/budget_controller.hpp), the scene fields it turns, and its previews
// of the on/off knobs (tools/vkwater/budget_previews.hpp), made where the budget starts and again
// wherever the camera comes to rest after moving: what a knob loses depends on what is seen.
#pragma once

#include "passes/frame/renderer.hpp"
#include "tools/vkwater/budget/budget_controller.hpp"

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>

namespace vkw::window {

class ViewBudget {
public:
    // Frames the camera must hold one pose before the previews are made again there.
    static constexpr uint64_t kPreviewRestFrames = 30;

    // Starts on `scene` as loaded, at its camera: the previews, then the controller. `scene` and
    // `renderer` outlive this; `output` is the frame's size, read whenever it is needed. The device
    // must be idle (the previews may replace what frames in flight use), as for measure_again().
    ViewBudget(double budget_ms, Renderer& renderer, Scene& scene, uint32_t samples,
               std::function<VkExtent2D()> output);

    // Before each frame: the scene's own knob fields, then the budget's setting over them (the last
    // frame's setting may have been lower; while the budget runs it owns these fields, and a panel
    // edit of one gives way to it), and its resolution scale into `options`.
    void apply(RenderOptions& options);
    // Once a frame, after the viewer has set the scene's camera: whether the camera has rested
    // kPreviewRestFrames frames away from where the previews were made.
    bool camera_rested(uint64_t frame);
    // The previews made again at the scene's camera, and the budget retargeted to them (the device
    // must be idle). Returns whether the budget left its setting for another.
    bool measure_again();

    budget::BudgetController& controller() { return *controller_; }
    const budget::BudgetController& controller() const { return *controller_; }
    // The arguments that give vkwater render the current setting.
    std::string current_arguments() const;

private:
    struct CameraPose {
        glm::dvec3 position{0.0}, target{0.0};
        bool operator==(const CameraPose&) const = default;
    };
    CameraPose camera_pose() const { return {scene_.camera.position, scene_.camera.target}; }
    budget::Quality measured_top();  // the scene's own knob fields in place

    Renderer& renderer_;
    Scene& scene_;
    uint32_t samples_;
    std::function<VkExtent2D()> output_;
    budget::SceneKnobFields knobs_at_load_;  // what it gives back when it steps up
    std::unique_ptr<budget::BudgetController> controller_;
    CameraPose previews_pose_;  // where the previews were made
    CameraPose last_pose_;      // the camera's pose in the last frame,
    uint64_t pose_since_ = 0;   // and the frame it has held it since
};

}  // namespace vkw::window
