#include "tools/vkwater/view/viewer.hpp"

#include "tools/vkwater/console.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/range.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/shader_module.hpp"
#include "engine/window/frames_in_flight.hpp"
#include "engine/window/glfw_window.hpp"
#include "engine/window/imgui_layer.hpp"
#include "engine/window/screenshot.hpp"
#include "passes/frame/accumulate.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "passes/present/present_graph.hpp"
#include "passes/present/present_handoff.hpp"
#include "tools/vkwater/image_provenance.hpp"
#include "tools/vkwater/view/camera_controller.hpp"
#include "tools/vkwater/view/frame_stats.hpp"
#include "tools/vkwater/view/parameter_panel.hpp"
#include "tools/vkwater/view/stats_overlay.hpp"
#include "tools/vkwater/view/view_budget.hpp"
#include "tools/vkwater/view/view_script.hpp"
#include "tools/vkwater/view/window_input.hpp"

#include <malloc.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <thread>

namespace vkw::window {
namespace {

// The bytes malloc has handed out and not taken back: every thread's arena (the driver's worker
// threads allocate in their own) and the chunks it mapped on its own. Unlike the resident set, this
// is blind to freed memory the allocator keeps, so a leak shows at once instead of first filling
// the holes that freed memory left.
size_t heap_bytes_in_use() {
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Scripted runs advance the water's clock by one 60 Hz frame per frame, so that they repeat.
constexpr double kScriptedFrameSeconds = 1.0 / 60.0;
// A window system that does not resize within this long is refused (a script waits for it).
constexpr double kResizeTimeoutSeconds = 5.0;
// How long a script's wait-file waits before it gives up.
constexpr double kWaitFileTimeoutSeconds = 60.0;

// The scene fields the panel edits, to undo a setting the renderer refuses.
struct PanelSnapshot {
    Sun sun;
    std::optional<Water> water;
    Medium medium;
    EffectsSettings effects;
    double fov_y_deg, exposure;

    explicit PanelSnapshot(const Scene& scene)
        : sun(scene.sun),
          water(scene.water),
          medium(scene.medium),
          effects(scene.effects),
          fov_y_deg(scene.camera.fov_y_deg),
          exposure(scene.camera.exposure) {}
    void restore(Scene& scene) const {
        scene.sun = sun;
        scene.water = water;
        scene.medium = medium;
        scene.effects = effects;
        scene.camera.fov_y_deg = fov_y_deg;
        scene.camera.exposure = exposure;
    }
};

// A scripted glide from one pose to another.
struct CameraMove {
    glm::dvec3 from_position, from_target, to_position, to_target;
    uint64_t start_frame;
    uint32_t frames;
};

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options);
    ~Viewer();
    void run();
    std::shared_ptr<ValidationLog> validation_log() const { return context_->shared_validation_log(); }

private:
    void load_scene_state();
    void recreate_swapchain(VkExtent2D size);
    std::unique_ptr<PresentGraph> make_present_graph(uint32_t image, VkBuffer readback);
    void run_script_commands();
    void run_command(const ScriptCommand& command);
    void update_ui_and_camera(double wall_dt);
    void serve_requests();
    fg::FrameExecutor& prepare_scene_frame(uint32_t sub_frame = 0);
    fg::FrameReport run_earlier_sub_frames(bool timed);
    bool render_frame();
    void note_pass_list(const fg::FrameGraph& graph);
    double choose_budget_ms() const;
    void start_budget();
    // Where the camera has come to rest after moving, the budget's previews made again there.
    void refresh_budget_previews();
    // The frame's size: the window's, or the options' before it has one.
    VkExtent2D output_extent() const {
        return swapchain_ ? swapchain_->extent() : VkExtent2D{options_.width, options_.height};
    }
    void feed_budget(double interval_ms);
    void budget_setting_changed();  // the budget chose another setting for the next frame

    ViewerOptions options_;
    bool scripted_ = false;
    // Declaration order is teardown order reversed: the window outlives the device, the
    // device everything made on it, and the present pipelines the present graphs.
    std::unique_ptr<GlfwWindow> window_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<Swapchain> swapchain_;
    std::unique_ptr<FramesInFlight> frames_;
    std::unique_ptr<Renderer> renderer_;
    fg::PipelineStore present_pipelines_;
    std::unique_ptr<ImGuiLayer> imgui_;
    Image window_hdr_;             // the hand-off image: the frame's HDR colour, the swapchain's size
    PixelFilter filter_;           // --spp, or under a budget the samples it chose (at most --spp's)
    uint32_t most_samples_ = 1;    // --spp
    Image sub_frame_sum_;          // with a box filter: the sub-frames' running sum, window_hdr_'s size
    uint64_t hdr_generation_ = 0;  // names window_hdr_ in the renderer's configuration
    std::vector<std::unique_ptr<PresentGraph>> present_graphs_;  // one per swapchain image
    passes::PresentTonemapSettings tonemap_;

    std::unique_ptr<Scene> scene_;
    std::unique_ptr<Scene> previous_scene_;  // kept alive: the renderer keys receivers by address
    std::vector<std::string> overrides_;     // --set, then the script's set commands
    Camera loaded_camera_;                   // the camera of the last load, to see what a set changed
    double loaded_time_ = 0.0;
    CameraController camera_;
    std::optional<CameraMove> move_;
    double water_time_ = 0.0;
    ViewControls controls_;
    ParameterPanel panel_;
    std::optional<PanelSnapshot> before_panel_;  // this frame's scene before the panel edited it
    std::unique_ptr<WindowInput> input_;
    ViewScript script_;
    size_t next_command_ = 0;

    FrameStats stats_;
    double budget_ms_ = 0.0;              // 0: no budget
    std::unique_ptr<ViewBudget> budget_;  // with a budget, for the scene as loaded
    uint64_t frame_ = 0;                  // frames shown so far: the number of the next one
    uint64_t timing_due_ = FrameStats::kWarmupFrames;
    std::vector<std::string> pass_list_;           // the scene graph's living passes, last frame
    fg::FrameExecutor* scene_executor_ = nullptr;  // valid until the next prepare or reload
    std::optional<Clock::time_point> last_frame_start_;
    bool last_frame_waited_ = false;                  // it waited on purpose: its interval is not counted
    bool disturbed_ = false;                          // this frame recreated or reloaded something
    std::vector<std::filesystem::path> screenshots_;  // requested for this frame
    uint32_t screenshot_count_ = 0;
    std::string message_;
};

Viewer::Viewer(const ViewerOptions& options) : options_(options) {
    scripted_ = options_.frames > 0 || !options_.script.empty();
    filter_ = pixel_filter_from_spp(options_.spp);
    most_samples_ = filter_.samples;
    if (options_.temporal && filter_.is_box()) {
        throw UserError("--spp " + std::to_string(options_.spp) +
                        ": --temporal jitters its frames within the pixel itself (accepted: --spp 1 with it)");
    }
    controls_.paused = options_.paused;
    controls_.temporal = options_.temporal;
    overrides_ = options_.overrides;
    load_scene_state();  // a bad scene fails before any window opens
    if (!options_.script.empty()) {
        script_ = load_view_script(options_.script);
        if (options_.frames > 0) check_script_fits(script_, options_.frames);
        for (const ScriptCommand& command : script_.commands) {
            if (command.verb != ScriptVerb::Screenshot) continue;
            require_writable_file_path(command.text);
            require_writable_file_path(std::filesystem::path(command.text).replace_extension(".png"));
        }
    }

    window_ = std::make_unique<GlfwWindow>(options_.width, options_.height, "vkwater view: " + options_.scene.string());
    ContextOptions context_options;
    context_options.validation = options_.validation;
    context_options.device_name = options_.device;
    context_options.instance_extensions = GlfwWindow::required_instance_extensions();
    context_options.swapchain = true;
    context_ = std::make_unique<Context>(context_options);
    std::printf("device: %s%s\n", context_->device_name().c_str(), options_.validation ? " (with validation)" : "");
    budget_ms_ = choose_budget_ms();
    // Under a budget a slow scene is the budget's to turn down: its line says so instead.
    if (options_.cpu_frame_note && context_->is_cpu_device() && budget_ms_ == 0.0) {
        const std::string note = options_.cpu_frame_note(*scene_, options_.width, options_.height);
        if (!note.empty()) std::printf("note: %s\n", note.c_str());
    }
    if (budget_ms_ > 0.0) {
        std::printf("budget: %.4g ms a frame (%s; --budget-ms sets another, 0 turns it off)\n", budget_ms_,
                    options_.budget_ms          ? "--budget-ms"
                    : context_->is_cpu_device() ? "the default on a CPU device"
                                                : "the default: the display's refresh interval");
    }
    swapchain_ =
        std::make_unique<Swapchain>(*context_, window_->create_surface(context_->instance()), options_.present);
    frames_ = std::make_unique<FramesInFlight>(*context_);
    renderer_ = std::make_unique<Renderer>(*context_);
    imgui_ = std::make_unique<ImGuiLayer>(*context_, window_->handle(), FramesInFlight::kSlots);
    input_ = std::make_unique<WindowInput>(*window_);
    recreate_swapchain(window_->framebuffer_size());
    if (budget_ms_ > 0.0) start_budget();  // its previews render with the renderer at the window's aspect
}

Viewer::~Viewer() {
    if (context_) vkDeviceWaitIdle(context_->device());
}

void Viewer::load_scene_state() {
    auto next = std::make_unique<Scene>(
        load_scene(options_.scene, overrides_, {.allow_outside_paths = options_.allow_outside_paths}));
    const bool first = !scene_;
    if (first) cli::print_warnings(scene_warnings(*next));
    // A set that moved the file's camera or clock moves the viewer's; any other keeps them.
    if (first || next->camera.position != loaded_camera_.position || next->camera.target != loaded_camera_.target) {
        camera_.set_pose(next->camera.position, next->camera.target);
        move_.reset();
    }
    loaded_camera_ = next->camera;
    const double time = next->water ? next->water->time : 0.0;
    if (first || time != loaded_time_) water_time_ = time;
    loaded_time_ = time;
    previous_scene_ = std::move(scene_);
    scene_ = std::move(next);
    panel_.reset(*scene_);
    if (budget_ms_ > 0.0) start_budget();  // the budget's top is the scene as loaded
}

double Viewer::choose_budget_ms() const {
    if (options_.budget_ms) {
        if (*options_.budget_ms > 0.0 && options_.render_scale != 1.0) {
            throw UserError("--render-scale " + format_number(options_.render_scale) +
                            ": --budget-ms chooses the resolution scale itself (accepted: one of the two)");
        }
        return *options_.budget_ms;  // with --spp N, up to N samples per pixel
    }
    // Scripted runs repeat exactly (a screenshot equals vkwater render's image); a chosen
    // resolution scale or sample count is the user's setting.
    if (scripted_ || options_.render_scale != 1.0 || filter_.is_box()) return 0.0;
    if (context_->is_cpu_device()) return kCpuBudgetMs;
    const double refresh = window_->refresh_interval_ms();
    return refresh > 0.0 ? refresh : kGpuBudgetMs;
}

void Viewer::start_budget() {
    // At the viewer's camera: after a reload it keeps its pose unless the file's camera moved.
    scene_->camera.position = camera_.position();
    scene_->camera.target = camera_.target();
    vkDeviceWaitIdle(context_->device());  // the previews may replace what the frames in flight use
    budget_ = std::make_unique<ViewBudget>(budget_ms_, *renderer_, *scene_, most_samples_,
                                           [this] { return output_extent(); });
}

void Viewer::refresh_budget_previews() {
    if (!budget_ || !budget_->camera_rested(frame_)) return;
    vkDeviceWaitIdle(context_->device());
    if (budget_->measure_again()) budget_setting_changed();
    disturbed_ = true;  // this frame's interval holds the previews
}

void Viewer::feed_budget(double interval_ms) {
    if (budget_ && budget_->controller().add_frame(interval_ms)) budget_setting_changed();
}

void Viewer::budget_setting_changed() {
    // Its first frame makes new pipelines and targets (not a fair interval), and its passes are
    // timed soon, to refit the cost model where it now runs.
    disturbed_ = true;
    if (options_.timing_every > 0) timing_due_ = std::min(timing_due_, frame_ + 3);
    if (cli::verbose()) {
        std::printf("frame %llu: budget chose %s (%s)\n", static_cast<unsigned long long>(frame_),
                    budget::describe_quality(budget_->controller().current()).c_str(),
                    budget_->controller().status().c_str());
    }
}

std::unique_ptr<PresentGraph> Viewer::make_present_graph(uint32_t image, VkBuffer readback) {
    PresentImages images;
    images.hdr.image = window_hdr_.handle();
    images.hdr.view = window_hdr_.view();
    images.hdr.width = swapchain_->extent().width;
    images.hdr.height = swapchain_->extent().height;
    images.hdr.format = window_hdr_.desc().format;
    images.swapchain_image = swapchain_->image(image);
    images.swapchain_view = swapchain_->view(image);
    images.swapchain_format = swapchain_->format();
    return std::make_unique<PresentGraph>(
        *context_, present_pipelines_, images, &tonemap_, [this](VkCommandBuffer cmd) { imgui_->record(cmd); },
        readback);
}

void Viewer::recreate_swapchain(VkExtent2D size) {
    frames_->wait_all();
    present_graphs_.clear();
    swapchain_->recreate(size);
    frames_->set_image_count(swapchain_->image_count());
    const VkExtent2D extent = swapchain_->extent();
    if (window_hdr_.desc().width != extent.width || window_hdr_.desc().height != extent.height) {
        window_hdr_ =
            Image(*context_,
                  {extent.width, extent.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                   VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                  "window HDR");
        ++hdr_generation_;
        if (most_samples_ > 1) {  // a budget may turn the box filter off and on again
            sub_frame_sum_ = Image(
                *context_, {extent.width, extent.height, VK_FORMAT_R32G32B32A32_SFLOAT, passes::kSubFrameSumUsage},
                "sub-frame sum");
        }
    }
    for (uint32_t i = 0; i < swapchain_->image_count(); ++i)
        present_graphs_.push_back(make_present_graph(i, VK_NULL_HANDLE));
    tonemap_.encode_srgb = !swapchain_->encodes_srgb();
    if (imgui_->connected_format() != swapchain_->format()) {
        imgui_->connect(present_graphs_.front()->overlay_render_pass(), swapchain_->format());
    }
    disturbed_ = true;
}

void Viewer::run_script_commands() {
    while (next_command_ < script_.commands.size() && script_.commands[next_command_].frame <= frame_) {
        run_command(script_.commands[next_command_++]);
    }
    if (!move_) return;
    const uint64_t done = frame_ - move_->start_frame;
    if (done >= move_->frames) {
        camera_.set_pose(move_->to_position, move_->to_target);  // exactly the pose asked for
        move_.reset();
        return;
    }
    const double t = static_cast<double>(done) / move_->frames;
    camera_.set_pose(glm::mix(move_->from_position, move_->to_position, t),
                     glm::mix(move_->from_target, move_->to_target, t));
}

void Viewer::run_command(const ScriptCommand& command) {
    switch (command.verb) {
        case ScriptVerb::Camera:
            camera_.set_pose(command.position, command.target);
            move_.reset();
            break;
        case ScriptVerb::Move:
            move_ = CameraMove{camera_.position(), camera_.target(), command.position,
                               command.target,     frame_,           command.frames};
            break;
        case ScriptVerb::Resize:
            if (!window_->resize(command.width, command.height, kResizeTimeoutSeconds)) {
                throw InternalError(script_.name + ": line " + std::to_string(command.line) +
                                    ": the window system did not resize the window to " +
                                    std::to_string(command.width) + "x" + std::to_string(command.height) + " within " +
                                    std::to_string(int(kResizeTimeoutSeconds)) + " s");
            }
            window_->take_resized();
            recreate_swapchain(window_->framebuffer_size());
            break;
        case ScriptVerb::Set:
            overrides_.push_back(command.text);
            load_scene_state();
            break;
        case ScriptVerb::Screenshot: screenshots_.emplace_back(command.text); break;
        case ScriptVerb::Pause: controls_.paused = true; break;
        case ScriptVerb::Resume: controls_.paused = false; break;
        case ScriptVerb::Time: water_time_ = command.seconds; break;
        case ScriptVerb::Mode: controls_.camera_mode = command.mode; break;
        case ScriptVerb::ReloadShaders: controls_.reload_shaders = true; break;
        case ScriptVerb::WaitFile: {
            const Clock::time_point start = Clock::now();
            while (!std::filesystem::exists(command.text)) {
                if (ms_since(start) > kWaitFileTimeoutSeconds * 1000.0) {
                    throw UserError(script_.name + ": line " + std::to_string(command.line) + ": '" + command.text +
                                    "' did not appear within " + std::to_string(int(kWaitFileTimeoutSeconds)) +
                                    " s (accepted: a file that some other process creates)");
                }
                window_->poll_events();  // stay responsive to the window system meanwhile
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
            break;
        }
        case ScriptVerb::Heap:
            std::printf("heap: frame %llu, %zu bytes in use\n", static_cast<unsigned long long>(frame_),
                        heap_bytes_in_use());
            break;
    }
}

void Viewer::update_ui_and_camera(double wall_dt) {
    imgui_->new_frame();
    const CameraInput input = input_->read(wall_dt, imgui_->wants_mouse(), imgui_->wants_keyboard(), controls_);
    before_panel_.emplace(*scene_);
    if (controls_.show_panels) {
        const fg::FrameNeeds* needs = scene_executor_ ? &scene_executor_->graph().needs() : nullptr;
        panel_.draw(*scene_, needs, controls_);
        OverlayInfo info;
        info.device = context_->device_name();
        info.present_mode = present_mode_name(swapchain_->mode());
        info.extent = swapchain_->extent();
        info.stats = &stats_;
        info.graph = scene_executor_ ? &scene_executor_->graph() : nullptr;
        if (scene_->water && std::find(pass_list_.begin(), pass_list_.end(), "caustic photons") != pass_list_.end()) {
            info.photon_grid = scene_->water->grid_resolution;  // the renderer traces one photon per cell
            info.photons = uint64_t{info.photon_grid} * info.photon_grid;
        }
        info.realize_count = renderer_->realize_count();
        info.message = message_;
        info.camera_mode = controls_.camera_mode;
        info.camera_position = camera_.position();
        info.camera_in_water = scene_->water && camera_.position().y < scene_->water->level;
        info.paused = controls_.paused;
        if (budget_) {
            info.budget = {budget_->controller().status(), budget::describe_quality(budget_->controller().current())};
        }
        draw_stats_overlay(info);
    }
    imgui_->finish_frame();

    camera_.set_mode(controls_.camera_mode);
    if (!move_) camera_.update(input);
    // The water's clock: fixed steps in scripted runs, the wall clock otherwise.
    const double step = scripted_ ? kScriptedFrameSeconds : std::min(wall_dt, 0.1);
    if (!controls_.paused) water_time_ += step * controls_.time_speed;
    if (controls_.paused && controls_.step) water_time_ += kScriptedFrameSeconds;
    controls_.step = false;
    scene_->camera.position = camera_.position();
    scene_->camera.target = camera_.target();
    if (scene_->water) scene_->water->time = water_time_;
    tonemap_.exposure = static_cast<float>(scene_->camera.exposure);
}

void Viewer::serve_requests() {
    if (controls_.reload_shaders) {
        // The next frame re-reads every .spv file: no pipeline survives, the graphs recompile.
        frames_->wait_all();
        renderer_->reload_shaders();
        scene_executor_ = nullptr;
        present_pipelines_ = fg::PipelineStore{};
        controls_.reload_shaders = false;
        disturbed_ = true;
        std::printf("reloaded shaders from %s\n", shader_directory().c_str());
    }
    if (controls_.screenshot) {
        screenshots_.emplace_back(options_.screenshot_prefix + "-" + std::to_string(screenshot_count_++) + ".exr");
        controls_.screenshot = false;
    }
}

fg::ImportedImage imported_image(const Image& image) {
    fg::ImportedImage imported;
    imported.image = image.handle();
    imported.view = image.view();
    imported.width = image.desc().width;
    imported.height = image.desc().height;
    imported.format = image.desc().format;
    return imported;
}

// With a box filter, sub-frame `sub_frame` of the frame: its camera shifted to its stratum's
// centre, its colour added into the running sum, and the sum handed to the window (every
// sub-frame's graph the same but for the caustic map's passes, so that two sets of device objects
// serve them all; the window shows only the last one's).
fg::FrameExecutor& Viewer::prepare_scene_frame(uint32_t sub_frame) {
    RenderOptions options;
    options.width = swapchain_->extent().width;
    options.height = swapchain_->extent().height;
    options.render_scale = options_.render_scale;
    // The panel's switch (--temporal at start); a box filter jitters its sub-frames itself.
    options.temporal.enabled = controls_.temporal && !filter_.is_box();
    if (budget_) budget_->apply(options);
    // The hand-off image is imported: a new one (a new size) is a new graph.
    const FrameOutput output{[this, sub_frame](fg::FrameGraph& graph, fg::ImageHandle hdr) {
        if (filter_.is_box()) {
            hdr = passes::add_sub_frame_accumulation(graph, hdr, imported_image(sub_frame_sum_), sub_frame,
                                                     filter_.samples);
        }
        passes::add_present_handoff_pass(graph, hdr, imported_image(window_hdr_));
    }};
    const glm::dvec2 centre_shift = scene_->camera.image_shift_ndc;
    if (filter_.is_box()) {
        options.sub_frame_shifts = sub_frame_shifts(filter_, options.width, options.height);
        options.caustic_map_carry = sub_frame == 0 ? CausticMapCarry::Keep : CausticMapCarry::Reuse;
        scene_->camera.image_shift_ndc = options.sub_frame_shifts[sub_frame];
    }
    if (options.temporal.enabled) {
        scene_->camera.image_shift_ndc = renderer_->next_temporal_shift(options.width, options.height);
    }
    try {
        scene_executor_ = &renderer_->prepare_frame(*scene_, options, output);
    } catch (const UserError& error) {
        // A setting the device cannot take (a water grid too large for its memory): in a
        // script that is the user's error; in the panel the setting is undone and named.
        scene_->camera.image_shift_ndc = centre_shift;
        if (scripted_ || !before_panel_) throw;
        before_panel_->restore(*scene_);
        message_ = std::string("refused: ") + error.what();
        if (filter_.is_box()) scene_->camera.image_shift_ndc = options.sub_frame_shifts[sub_frame];
        if (options.temporal.enabled) {
            scene_->camera.image_shift_ndc = renderer_->next_temporal_shift(options.width, options.height);
        }
        scene_executor_ = &renderer_->prepare_frame(*scene_, options, output);
    }
    scene_->camera.image_shift_ndc = centre_shift;  // the frame's declaration has read it
    return *scene_executor_;
}

// With a box filter, every sub-frame but the last, each run alone (the window's submission holds
// the last); their pass times when `timed`.
fg::FrameReport Viewer::run_earlier_sub_frames(bool timed) {
    fg::FrameReport report;
    if (!filter_.is_box()) return report;
    frames_->wait_all();  // the frame in flight still reads the sum and the hand-off image
    for (uint32_t i = 0; i + 1 < filter_.samples; ++i) {
        const fg::FrameReport sub = prepare_scene_frame(i).execute();
        if (timed) add_sub_frame_times(report, sub);
    }
    return report;
}

void Viewer::note_pass_list(const fg::FrameGraph& graph) {
    std::vector<std::string> names;
    for (uint32_t pass : graph.compiled().order) names.push_back(graph.passes()[pass].name);
    // A new pass list is timed on the next frame, once its new passes have made their pipelines.
    if (names != pass_list_ && options_.timing_every > 0) timing_due_ = std::min(timing_due_, frame_ + 1);
    pass_list_ = std::move(names);
}

bool Viewer::render_frame() {
    const Clock::time_point start = Clock::now();
    const bool screenshot = !screenshots_.empty();
    const bool timing = options_.timing_every > 0 && frame_ >= timing_due_ && frame_ >= FrameStats::kWarmupFrames;
    // The frame's samples: the budget's choice holds for all of its sub-frames.
    if (budget_) filter_ = pixel_filter_from_spp(budget_->controller().current().samples);
    fg::FrameReport report = run_earlier_sub_frames(timing);
    fg::FrameExecutor& executor = prepare_scene_frame(filter_.samples - 1);
    note_pass_list(executor.graph());

    FramesInFlight::Slot& slot = frames_->next_slot();
    uint32_t image = 0;
    const SwapchainStatus acquired = swapchain_->acquire(slot.acquired, image);
    if (acquired == SwapchainStatus::OutOfDate) {
        recreate_swapchain(window_->framebuffer_size());
        return false;
    }
    if (timing || screenshot) frames_->wait_all();                // these frames run alone
    if (timing) add_sub_frame_times(report, executor.execute());  // each pass alone, timed (fences on CPU devices)
    frames_->begin(slot);
    if (!timing) executor.record(slot.cmd);
    Buffer readback;
    std::unique_ptr<PresentGraph> screenshot_graph;
    if (screenshot) {
        const VkExtent2D extent = swapchain_->extent();
        readback = Buffer(
            *context_,
            {VkDeviceSize{extent.width} * extent.height * 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
            "screenshot readback");
        screenshot_graph = make_present_graph(image, readback.handle());
        screenshot_graph->record(slot.cmd);
    } else {
        present_graphs_[image]->record(slot.cmd);
    }
    const Clock::time_point submitted = Clock::now();
    frames_->submit(slot, image);
    if (timing || screenshot) {
        frames_->wait_all();
        if (timing) {
            const double present_ms = ms_since(submitted);
            stats_.add_timing(report, present_ms, frame_);
            if (budget_) {
                std::vector<fg::PassTime> passes = report.passes;
                passes.push_back({"present", present_ms, 0});  // the window's own passes: a fixed cost
                budget_->controller().add_pass_times(passes);
            }
            timing_due_ = frame_ + options_.timing_every;
        }
    }
    const SwapchainStatus presented = swapchain_->present(frames_->rendered(image), image);

    if (last_frame_start_) {
        const double interval = std::chrono::duration<double, std::milli>(start - *last_frame_start_).count();
        const bool counted = !last_frame_waited_ && frame_ > FrameStats::kWarmupFrames;
        stats_.add_frame(interval, !last_frame_waited_);
        if (counted) feed_budget(interval);
    }
    last_frame_start_ = start;
    last_frame_waited_ = timing || screenshot || disturbed_;
    disturbed_ = false;

    for (const std::filesystem::path& exr : screenshots_) {
        const VkExtent2D extent = swapchain_->extent();
        try {
            char time[96];
            std::snprintf(time, sizeof time, "%.2f ms, the mean frame interval over the last frames (wall clock)",
                          stats_.recent_frame_ms());
            const std::filesystem::path png = write_screenshot(
                exr, static_cast<const float*>(readback.mapped()), extent.width, extent.height, tonemap_.exposure,
                cli::image_attributes({options_.scene, overrides_, "real-time (vkwater view)", filter_.describe(),
                                       context_->device_name(), time},
                                      scene_->camera));
            std::printf("frame %llu: wrote %s (linear HDR, %ux%u) and %s\n", static_cast<unsigned long long>(frame_),
                        exr.c_str(), extent.width, extent.height, png.c_str());
        } catch (const UserError& error) {
            if (scripted_) throw;     // (a script's paths were checked before the window opened)
            message_ = error.what();  // F12 in an unwritable folder: say so, keep the session
        }
    }
    screenshots_.clear();
    if (acquired == SwapchainStatus::Suboptimal || presented != SwapchainStatus::Ok) {
        recreate_swapchain(window_->framebuffer_size());
    }
    return true;
}

void Viewer::run() {
    Clock::time_point last = Clock::now();
    while (options_.frames == 0 || frame_ < options_.frames) {
        window_->poll_events();
        if (window_->should_close()) break;
        const VkExtent2D size = window_->framebuffer_size();
        if (size.width == 0 || size.height == 0) {
            window_->wait_events();  // minimised: nothing to draw until it comes back
            continue;
        }
        if (window_->take_resized() || size.width != swapchain_->extent().width ||
            size.height != swapchain_->extent().height) {
            recreate_swapchain(size);
        }
        run_script_commands();
        const Clock::time_point now = Clock::now();
        const double wall_dt = std::chrono::duration<double>(now - last).count();
        last = now;
        update_ui_and_camera(wall_dt);
        serve_requests();
        refresh_budget_previews();
        if (render_frame()) ++frame_;
    }
    frames_->wait_all();
    std::printf("%s", stats_.summary(frame_).c_str());
    if (budget_) {
        std::printf("%s; settings at exit: %s (%llu changes)\n", budget_->controller().status().c_str(),
                    budget_->current_arguments().c_str(),
                    static_cast<unsigned long long>(budget_->controller().changes()));
    }
    std::printf("frame graph device objects made %zu times; present mode %s\n", renderer_->realize_count(),
                present_mode_name(swapchain_->mode()));
    // The view at exit as vkwater render takes it, to render the same picture offscreen.
    const glm::dvec3 p = camera_.position(), t = camera_.target();
    std::printf("camera at exit (%s): --set camera.position=[%.9g,%.9g,%.9g] --set camera.target=[%.9g,%.9g,%.9g]\n",
                camera_mode_name(controls_.camera_mode), p.x, p.y, p.z, t.x, t.y, t.z);
}

}  // namespace

void run_viewer(const ViewerOptions& options) {
    std::shared_ptr<ValidationLog> validation_log;
    {
        Viewer viewer(options);
        validation_log = viewer.validation_log();
        viewer.run();
    }  // the device is torn down here: teardown can report validation messages too
    if (validation_log->failure_count() > 0) {
        throw InternalError(std::to_string(validation_log->failure_count()) +
                            " validation message(s); see above. Every error or warning fails a --validation run");
    }
}

}  // namespace vkw::window
