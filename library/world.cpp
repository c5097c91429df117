// vkwater::World (include/vkwater/world.hpp): a scene and the renderer that records its frames into
// a host's command buffer, on a vkw::Context that borrows the host's device.
#include <vkwater/world.hpp>

#include <vkwater/scene.hpp>

#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/scene/range.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/context.hpp"
#include "library/host_targets.hpp"
#include "library/status_from_exception.hpp"
#include "passes/caustics/caustic_layer.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/whole_image_copy.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/present/host_composite.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <string>

namespace vkwater {

struct World::State {
    std::unique_ptr<vkw::Context> context;
    vkw::Scene scene;
    // One renderer per frame in flight, each with its own frame images, sharing the pipelines; frame
    // i is recorded by renderers[i % size].
    std::vector<std::unique_ptr<vkw::Renderer>> renderers;
    size_t next_frame = 0;

    // Declares and compiles the frame (or reuses the compiled one) with the host's targets imported.
    vkw::fg::FrameExecutor& prepare(const Frame& frame, vkw::fg::TimingMode timing);
};

namespace {

glm::dvec3 to_glm(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }
std::array<double, 3> from_glm(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

vkw::Camera scene_camera_from(const Camera& camera, const vkw::Camera& defaults) {
    vkw::Camera out = defaults;  // exposure and the rest of the scene's camera stay
    out.position = to_glm(camera.position);
    out.target = to_glm(camera.target);
    out.fov_y_deg = camera.fov_y_deg;
    out.near_plane = camera.near_plane;
    out.far_plane = camera.far_plane;
    return out;
}

// The host's camera and clock, checked as the scene loader checks a file's (the same ranges), since
// they reach the frame without passing through it.
void check_camera_and_time(const Camera& camera, double time_seconds) {
    const auto refuse = [](const std::string& field, double value, const std::string& accepted) {
        throw vkw::UserError("vkwater::Frame: " + field + " " + vkw::format_number(value) + " (accepted: " + accepted +
                             ")");
    };
    const auto finite = [](const std::array<double, 3>& v) {
        return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    };
    if (!finite(camera.position) || !finite(camera.target) || camera.position == camera.target) {
        throw vkw::UserError(
            "vkwater::Frame: camera.position and camera.target (accepted: finite points, not the same one)");
    }
    if (!(camera.fov_y_deg > 1.0 && camera.fov_y_deg < 179.0)) {
        refuse("camera.fov_y_deg", camera.fov_y_deg, "1 < value < 179 degrees");
    }
    if (!(camera.near_plane > 0.0 && std::isfinite(camera.near_plane))) {
        refuse("camera.near_plane", camera.near_plane, "a finite value > 0 m");
    }
    if (!(camera.far_plane > camera.near_plane && std::isfinite(camera.far_plane))) {
        refuse("camera.far_plane", camera.far_plane, "a finite value > camera.near_plane");
    }
    if (!std::isfinite(time_seconds)) refuse("time_seconds", time_seconds, "a finite number of seconds");
}

std::array<float, 16> column_major(const glm::dmat4& m) {
    const glm::mat4 single(m);
    std::array<float, 16> out;
    std::memcpy(out.data(), glm::value_ptr(single), sizeof(out));
    return out;
}

}  // namespace

World::World(std::unique_ptr<State> state) : state_(std::move(state)) {}

World::~World() = default;

Result<std::unique_ptr<World>> World::load(const HostDevice& device, const std::string& scene_file,
                                           const WorldOptions& options) {
    return create(device, options, [&](State& state) { state.scene = vkw::load_scene(scene_file, options.overrides); });
}

Result<std::unique_ptr<World>> World::load(const HostDevice& device, const Scene& scene, const WorldOptions& options) {
    return create(device, options, [&](State& state) {
        state.scene = vkw::parse_scene(scene_json(scene), "in-memory scene", options.overrides);
    });
}

Result<std::unique_ptr<World>> World::parse(const HostDevice& device, const std::string& scene_json,
                                            const std::string& name, const WorldOptions& options) {
    return create(device, options,
                  [&](State& state) { state.scene = vkw::parse_scene(scene_json, name, options.overrides); });
}

Result<std::unique_ptr<World>> World::create(const HostDevice& device, const WorldOptions& options,
                                             const std::function<void(State&)>& read_scene) {
    auto state = std::make_unique<State>();
    const Status status = detail::run_guarded([&] {
        if (options.frames_in_flight < 1 || options.frames_in_flight > 8) {
            throw vkw::UserError("vkwater::WorldOptions: frames_in_flight " + std::to_string(options.frames_in_flight) +
                                 " (accepted: 1 to 8)");
        }
        read_scene(*state);
        if (!state->scene.water) {
            throw vkw::UserError(state->scene.source.string() + ": water: missing (a world needs water to draw)");
        }
        vkw::BorrowedDevice borrowed{device.instance,  device.physical_device, device.device,
                                     device.queue,     device.queue_family,    device.enabled_features,
                                     device.allocator, device.debug_utils};
        state->context = std::make_unique<vkw::Context>(borrowed);
        // The frames in flight share their pipelines and the scene's static device data (the
        // receiver meshes, the ocean's spectrum): one copy on the device, however many frames.
        const auto pipelines = std::make_shared<vkw::fg::PipelineStore>();
        const auto uploads = std::make_shared<vkw::SceneUploads>(*state->context);
        for (uint32_t i = 0; i < options.frames_in_flight; ++i) {
            state->renderers.push_back(std::make_unique<vkw::Renderer>(*state->context, pipelines, uploads));
        }
    });
    if (!status) return status;
    return std::unique_ptr<World>(new World(std::move(state)));
}

Camera World::scene_camera() const {
    const vkw::Camera& camera = state_->scene.camera;
    return {from_glm(camera.position), from_glm(camera.target), camera.fov_y_deg, camera.near_plane, camera.far_plane};
}

double World::scene_time() const { return state_->scene.water->time; }

CameraMatrices World::matrices(const Camera& camera, uint32_t width, uint32_t height) {
    const vkw::Camera scene_camera = scene_camera_from(camera, vkw::Camera{});
    // vkwater draws with a y-flipped viewport; the host's matrices carry that flip instead, so that a
    // standard viewport (0, 0, width, height) puts its pixels where vkwater's are.
    glm::dmat4 flip_y(1.0);
    flip_y[1][1] = -1.0;
    const double aspect = double(width) / double(height == 0 ? 1 : height);
    return {column_major(vkw::view_matrix(scene_camera)),
            column_major(flip_y * vkw::projection_matrix(scene_camera, aspect))};
}

vkw::fg::FrameExecutor& World::State::prepare(const Frame& frame, vkw::fg::TimingMode timing) {
    const detail::HostTargets targets = detail::check_host_targets(*context, frame);
    check_camera_and_time(frame.camera, frame.time_seconds);
    scene.camera = scene_camera_from(frame.camera, scene.camera);
    scene.water->time = frame.time_seconds;

    vkw::RenderOptions options;
    options.width = frame.color.width;
    options.height = frame.color.height;
    options.timing = timing;
    vkw::FrameOutput output;
    output.caustic_layer = targets.caustic_layer.has_value();
    output.add_passes = [&targets](vkw::fg::FrameGraph& graph, vkw::fg::ImageHandle hdr) {
        const vkw::fg::ImageHandle color = graph.import_image("host colour", targets.color);
        const vkw::fg::ImageHandle depth = graph.import_image("host depth", targets.depth);
        const vkw::fg::ImageHandle scene_depth = graph.blackboard().get(vkw::keys::kSceneDepth);
        graph.request_output(vkw::passes::add_host_composite_pass(graph, hdr, scene_depth, color, depth));
        if (targets.caustic_layer) {
            const vkw::fg::ImageHandle layer = graph.import_image("host caustic layer", *targets.caustic_layer);
            vkw::passes::add_whole_image_copy_pass(graph, "caustic layer to the host",
                                                   graph.blackboard().get(vkw::keys::kCausticLayer), layer);
        }
    };
    vkw::Renderer& renderer = *renderers[next_frame % renderers.size()];
    vkw::fg::FrameExecutor& executor = renderer.prepare_frame(scene, options, output);
    ++next_frame;  // prepared: the next frame takes the next set
    return executor;
}

Status World::record(VkCommandBuffer cmd, const Frame& frame) {
    return detail::run_guarded([&] {
        if (cmd == VK_NULL_HANDLE) throw vkw::UserError("World::record: cmd: a command buffer must be given");
        state_->prepare(frame, vkw::fg::TimingMode::None).record(cmd);
    });
}

Result<FrameTimings> World::time_frame(const Frame& frame) {
    FrameTimings timings;
    const Status status = detail::run_guarded([&] {
        const vkw::fg::FrameReport report = state_->prepare(frame, vkw::fg::TimingMode::Auto).execute();
        timings.method = report.method == vkw::fg::TimingMode::Timestamps ? "timestamps"
                         : report.method == vkw::fg::TimingMode::Fences   ? "fences"
                                                                          : "whole frame";
        timings.total_ms = report.total_ms;
        for (const vkw::fg::PassTime& pass : report.passes) timings.passes.push_back({pass.pass, pass.ms});
    });
    if (!status) return status;
    return timings;
}

}  // namespace vkwater
