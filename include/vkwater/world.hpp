// A water world drawn into a host engine's frame: load a scene once, then each frame record the
// water, its caustics and godrays into the host's command buffer and targets.
//
//   vkwater::Result<std::unique_ptr<vkwater::World>> world = vkwater::World::load(device, "scenes/pool.json");
//   ...each frame, in a command buffer the host has begun and will submit:
//   vkwater::Status status = world.value()->record(cmd, frame);
//
// Threading: a World is used by one thread at a time. Its frames may overlap on the GPU up to
// WorldOptions::frames_in_flight (1 by default: each frame's submission waits for the one before).
// docs/embedding.md has the rest.
#pragma once

#include <vkwater/device.hpp>
#include <vkwater/status.hpp>

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vkwater {

struct Scene;  // <vkwater/scene.hpp>

// A pinhole camera in the scene's frame (metres, y up). Its projection is reverse Z: see matrices().
struct Camera {
    std::array<double, 3> position{0.0, 0.0, 0.0};
    std::array<double, 3> target{0.0, 0.0, -1.0};  // a point looked at, != position
    double fov_y_deg = 60.0;                       // full vertical field of view, in (1, 179)
    double near_plane = 0.05;                      // metres, 0 < near_plane < far_plane
    double far_plane = 500.0;
};

// The camera's matrices as vkwater draws with them, column-major (as GLSL and glm): a host draws its
// own geometry with these so that its depth and vkwater's meet. Clip space is Vulkan's (y down,
// depth in [0, 1]) with reverse Z: depth 1 at the near plane, 0 at the far plane.
struct CameraMatrices {
    std::array<float, 16> view{};
    std::array<float, 16> projection{};
};

// A host image and the states it is in before the frame and must be left in after it. vkwater
// derives its barriers from these: it waits for `before` and makes its writes available to `after`.
// `before` must name the stages and accesses of the host's last use: understated (stages NONE after
// a draw), the barrier that orders vkwater after the host is missing, and no layer reports it.
struct ImageState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

struct Target {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D, one mip level, one layer
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 0, height = 0;
    ImageState before;
    ImageState after;
};

struct Frame {
    Camera camera;
    double time_seconds = 0.0;  // the waves' clock
    // Required. Colour: a float colour-attachment format (R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT;
    // COLOR_ATTACHMENT usage); vkwater writes linear radiance in W m^-2 sr^-1, exposure not applied,
    // alpha 1, where its surfaces are nearer than the host's depth. Depth: a depth format (D32_SFLOAT
    // or D24/D16 with DEPTH_STENCIL_ATTACHMENT usage) of the same size, reverse Z, cleared to 0 where
    // the host drew nothing; it is left holding the nearer of the host's and vkwater's depths.
    Target color;
    Target depth;
    // Optional (image null: none): the caustic layer (the caustic irradiance factor on the receivers,
    // docs/model.md), R32G32B32A32_SFLOAT with TRANSFER_DST usage, of the colour target's size.
    Target caustic_layer;
};

struct PassTiming {
    std::string pass;
    double ms = 0.0;
};

struct FrameTimings {
    std::string method;  // "fences" (each pass submitted alone; CPU devices) or "timestamps"
    double total_ms = 0.0;
    std::vector<PassTiming> passes;
};

struct WorldOptions {
    // Changes to the scene, "field.path=value" as the CLI's --set (e.g. "camera.fov_y_deg=75").
    std::vector<std::string> overrides;
    // How many of the host's frames may be on the GPU at once, 1 to 8. record() cycles through this
    // many sets of the frame's own images and buffers, so frame i + frames_in_flight reuses frame i's:
    // the GPU must have finished frame i before that frame's submission starts (the usual contract of
    // frames in flight). Each set costs the frame's transient memory again; pipelines are shared.
    uint32_t frames_in_flight = 1;
};

class World {
public:
    // A scene file (JSON, scenes/README.md).
    static Result<std::unique_ptr<World>> load(const HostDevice& device, const std::string& scene_file,
                                               const WorldOptions& options = {});
    // A scene built in code (<vkwater/scene.hpp>), checked as a file would be; messages name it
    // "in-memory scene".
    static Result<std::unique_ptr<World>> load(const HostDevice& device, const Scene& scene,
                                               const WorldOptions& options = {});
    // The same from JSON text in memory; `name` stands in for the file in messages and glTF paths.
    static Result<std::unique_ptr<World>> parse(const HostDevice& device, const std::string& scene_json,
                                                const std::string& name, const WorldOptions& options = {});
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // The scene file's camera and clock, for a host that starts from them.
    Camera scene_camera() const;
    double scene_time() const;
    static CameraMatrices matrices(const Camera& camera, uint32_t width, uint32_t height);

    // Records the frame into `cmd` (begun by the host, submitted by the host). Checks the targets
    // first: a missing handle, a size or format vkwater cannot use is an InvalidInput naming it.
    Status record(VkCommandBuffer cmd, const Frame& frame);
    // Runs the frame alone on the host's queue (each pass submitted and timed: fences on CPU devices,
    // timestamps elsewhere) and waits; the targets receive the frame as with record().
    Result<FrameTimings> time_frame(const Frame& frame);

private:
    struct State;
    explicit World(std::unique_ptr<State> state);
    static Result<std::unique_ptr<World>> create(const HostDevice& device, const WorldOptions& options,
                                                 const std::function<void(State&)>& read_scene);
    std::unique_ptr<State> state_;
};

}  // namespace vkwater
