// The viewer's frame-time budget (view_budget.hpp).
#include "tools/vkwater/view/view_budget.hpp"

#include "tools/vkwater/budget_previews.hpp"

namespace vkw::window {

ViewBudget::ViewBudget(double budget_ms, Renderer& renderer, Scene& scene, uint32_t samples,
                       std::function<VkExtent2D()> output)
    : renderer_(renderer),
      scene_(scene),
      samples_(samples),
      output_(std::move(output)),
      knobs_at_load_(budget::knob_fields(scene)) {
    controller_ = std::make_unique<budget::BudgetController>(
        budget_ms, measured_top(),
        [this](const budget::Quality& q) {
            const VkExtent2D extent = output_();
            return budget::cost_drivers(scene_, q, extent.width, extent.height);
        },
        [this] { return double(output_().height); });
}

budget::Quality ViewBudget::measured_top() {
    previews_pose_ = camera_pose();
    const VkExtent2D extent = output_();
    return cli::measured_top(renderer_, scene_, extent.width, extent.height, samples_);
}

void ViewBudget::apply(RenderOptions& options) {
    budget::restore_knob_fields(knobs_at_load_, scene_);
    budget::apply_quality(controller_->current(), controller_->top(), scene_);
    options.render_scale = controller_->current().render_scale;
}

bool ViewBudget::camera_rested(uint64_t frame) {
    const CameraPose pose = camera_pose();
    if (pose != last_pose_) {
        last_pose_ = pose;
        pose_since_ = frame;
    }
    return pose != previews_pose_ && frame >= pose_since_ + kPreviewRestFrames;
}

bool ViewBudget::measure_again() {
    // The scene's own knobs, as the previews and the top read them (the next frame's apply() sets
    // the budget's setting again).
    budget::restore_knob_fields(knobs_at_load_, scene_);
    return controller_->retarget(measured_top());
}

std::string ViewBudget::current_arguments() const {
    return budget::describe_arguments(budget::quality_arguments(controller_->current(), controller_->top(), scene_));
}

}  // namespace vkw::window
