// The embedding library (include/vkwater/) on a device the test lends it, as a host engine would:
// the frame recorded into the host's command buffer and targets equals the CLI renderer's image
// wherever the host drew nothing, the host's nearer pixels survive, every Vulkan object goes
// through the host's allocator, and a mistake in the host's targets is a Status naming it.
#include <vkwater/scene.hpp>
#include <vkwater/world.hpp>
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/device_features.hpp"
#include "engine/vk/resources.hpp"
#include "examples/embed_host/pool_scene.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace {

using vkw::Buffer;
using vkw::Image;

const std::string kPool = std::string(VKWATER_SOURCE_DIR) + "/scenes/pool.json";
constexpr uint32_t kWidth = 160, kHeight = 120;
// The host's own object, nearer than anything vkwater draws: a rectangle of depth 1 (the near
// plane, reverse Z) and a colour no scene produces.
constexpr uint32_t kBoxX0 = 40, kBoxX1 = 90, kBoxY0 = 30, kBoxY1 = 70;
constexpr float kBoxColor[4] = {0.25f, -1.0f, 7.0f, 1.0f};

bool in_box(uint32_t x, uint32_t y) { return x >= kBoxX0 && x < kBoxX1 && y >= kBoxY0 && y < kBoxY1; }

// Counts the host allocator's live allocations: what vkwater makes through it must all be freed.
struct CountingAllocator {
    std::mutex mutex;
    std::unordered_map<void*, size_t> live;
    std::atomic<uint64_t> total{0};

    static void* allocate(void* user, size_t size, size_t alignment, VkSystemAllocationScope) {
        auto* self = static_cast<CountingAllocator*>(user);
        void* p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        std::lock_guard lock(self->mutex);
        self->live[p] = size;
        ++self->total;
        return p;
    }
    static void* reallocate(void* user, void* original, size_t size, size_t alignment, VkSystemAllocationScope scope) {
        auto* self = static_cast<CountingAllocator*>(user);
        if (!original) return allocate(user, size, alignment, scope);
        if (size == 0) {
            release(user, original);
            return nullptr;
        }
        size_t old_size = 0;
        {
            std::lock_guard lock(self->mutex);
            old_size = self->live.at(original);
        }
        void* p = allocate(user, size, alignment, scope);
        std::memcpy(p, original, std::min(old_size, size));
        release(user, original);
        return p;
    }
    static void release(void* user, void* memory) {
        if (!memory) return;
        auto* self = static_cast<CountingAllocator*>(user);
        {
            std::lock_guard lock(self->mutex);
            self->live.erase(memory);
        }
        std::free(memory);
    }
    VkAllocationCallbacks callbacks() {
        VkAllocationCallbacks c{};
        c.pUserData = this;
        c.pfnAllocation = allocate;
        c.pfnReallocation = reallocate;
        c.pfnFree = release;
        return c;
    }
};

class WorldTest : public vkw::test::GpuTest {
protected:
    void TearDown() override {
        tear_down_host_objects();
        GpuTest::TearDown();  // destroys the device: the host's objects go first
    }
    void tear_down_host_objects() {
        color_ = {};
        depth_ = {};
        color_in_ = {};
        depth_in_ = {};
        color_out_ = {};
        depth_out_ = {};
        caustic_ = {};
        caustic_out_ = {};
    }

    vkwater::HostDevice host_device(const VkAllocationCallbacks* allocator = nullptr) {
        // The features the test's device was created with (vkw::Context enables this very request).
        vkw::request_device_features(context().physical_device(), features_);
        return {context().instance(),     context().physical_device(), context().device(), context().queue(),
                context().queue_family(), &features_.features,         allocator,          true};
    }

    // The host's targets, filled as a host would have drawn them: the scene cleared (colour 0,
    // depth 0 = far) and the box; each then in TRANSFER_DST, as the upload leaves it.
    void make_targets() {
        color_ = Image(
            context(),
            {kWidth, kHeight, VK_FORMAT_R32G32B32A32_SFLOAT,
             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
            "host colour");
        depth_ = Image(context(),
                       {kWidth, kHeight, VK_FORMAT_D32_SFLOAT,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                       "host depth");
        const size_t pixels = size_t{kWidth} * kHeight;
        const auto host_buffer = [&](VkDeviceSize bytes, VkBufferUsageFlags usage, const char* name) {
            return Buffer(context(), {bytes, usage, true}, name);
        };
        color_in_ = host_buffer(pixels * 16, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "host colour upload");
        depth_in_ = host_buffer(pixels * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "host depth upload");
        color_out_ = host_buffer(pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "host colour readback");
        depth_out_ = host_buffer(pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "host depth readback");
        auto* color = static_cast<float*>(color_in_.mapped());
        auto* depth = static_cast<float*>(depth_in_.mapped());
        for (uint32_t y = 0; y < kHeight; ++y) {
            for (uint32_t x = 0; x < kWidth; ++x) {
                const size_t i = size_t{y} * kWidth + x;
                for (int c = 0; c < 4; ++c) color[4 * i + c] = in_box(x, y) ? kBoxColor[c] : (c == 3 ? 1.0f : 0.0f);
                depth[i] = in_box(x, y) ? 1.0f : 0.0f;
            }
        }
    }

    static void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                        VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                        VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = src_stage;
        b.srcAccessMask = src_access;
        b.dstStageMask = dst_stage;
        b.dstAccessMask = dst_access;
        b.oldLayout = from;
        b.newLayout = to;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image;
        b.subresourceRange = {aspect, 0, 1, 0, 1};
        VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        info.imageMemoryBarrierCount = 1;
        info.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &info);
    }

    static void copy(VkCommandBuffer cmd, VkBuffer buffer, VkImage image, VkImageAspectFlags aspect, bool to_image) {
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {kWidth, kHeight, 1};
        if (to_image) {
            vkCmdCopyBufferToImage(cmd, buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        } else {
            vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
        }
    }

    vkwater::Frame frame(const vkwater::World& world) const {
        vkwater::Frame frame;
        frame.camera = world.scene_camera();
        frame.time_seconds = world.scene_time();
        const vkwater::ImageState uploaded{VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                           VK_ACCESS_2_TRANSFER_WRITE_BIT};
        const vkwater::ImageState read_back{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                            VK_ACCESS_2_TRANSFER_READ_BIT};
        frame.color = {color_.handle(), color_.view(), VK_FORMAT_R32G32B32A32_SFLOAT, kWidth, kHeight,
                       uploaded,        read_back};
        frame.depth = {depth_.handle(), depth_.view(), VK_FORMAT_D32_SFLOAT, kWidth, kHeight, uploaded, read_back};
        if (caustic_.handle()) {
            // Written whole by its copy: it enters holding nothing.
            frame.caustic_layer = {
                caustic_.handle(), caustic_.view(), VK_FORMAT_R32G32B32A32_SFLOAT, kWidth, kHeight, {}, read_back};
        }
        return frame;
    }

    // Uploads the host's targets, records `frames` of `world`'s frames after them into the same
    // command buffer (as a host with that many frames in flight would have them run back to back)
    // and reads both back. Every frame's targets enter and leave in the upload's state, so that the
    // frames are alike (another state would be another compiled frame); the readback's barrier is
    // the host's own.
    vkwater::Status run_frame(vkwater::World& world, int frames = 1) {
        vkwater::Status status;
        vkwater::Frame host_frame = frame(world);
        host_frame.color.after = host_frame.color.before;
        host_frame.depth.after = host_frame.depth.before;
        context().submit_and_wait(
            [&](VkCommandBuffer cmd) {
                barrier(cmd, color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
                barrier(cmd, depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
                copy(cmd, color_in_.handle(), color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, true);
                copy(cmd, depth_in_.handle(), depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, true);
                for (int i = 0; i < frames; ++i) {
                    status = world.record(cmd, host_frame);
                    if (!status) return;
                }
                const auto to_readback = [&](const Image& image, VkImageAspectFlags aspect) {
                    barrier(cmd, image.handle(), aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT);
                };
                to_readback(color_, VK_IMAGE_ASPECT_COLOR_BIT);
                to_readback(depth_, VK_IMAGE_ASPECT_DEPTH_BIT);
                copy(cmd, color_out_.handle(), color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, false);
                copy(cmd, depth_out_.handle(), depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, false);
                if (caustic_.handle())
                    copy(cmd, caustic_out_.handle(), caustic_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, false);
            },
            "host frame");
        return status;
    }

    // The host's colour read back equals the renderer's image of `scene` outside the box, bit for
    // bit, and the box kept the host's colour and depth.
    void expect_renderers_image_outside_the_box(const std::string& scene);

    const float* color_pixels() const { return static_cast<const float*>(color_out_.mapped()); }
    const float* depth_pixels() const { return static_cast<const float*>(depth_out_.mapped()); }

    vkw::DeviceFeatureChain features_;
    Image color_, depth_, caustic_;
    Buffer color_in_, depth_in_, color_out_, depth_out_, caustic_out_;
};

TEST_F(WorldTest, HostFrameEqualsTheRenderersImageOutsideTheHostsNearerPixels) {
    auto world = vkwater::World::load(host_device(), kPool);
    ASSERT_TRUE(world) << world.status().message;
    make_targets();
    const vkwater::Status status = run_frame(*world.value());
    ASSERT_TRUE(status) << status.message;

    expect_renderers_image_outside_the_box(kPool);
}

void WorldTest::expect_renderers_image_outside_the_box(const std::string& scene) {
    vkw::Renderer renderer(context());
    vkw::RenderOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.timing = vkw::fg::TimingMode::None;
    const vkw::ImageRGBA32F reference = renderer.render(vkw::load_scene(scene), options).image;

    // Outside the box the same passes ran on the same device from the same SPIR-V, and the composite
    // copies each texel: the images are equal bit for bit (tolerance 0, alpha excepted: the host gets 1).
    size_t outside = 0, box = 0, lit = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float* got = color_pixels() + 4 * (size_t{y} * kWidth + x);
            const float* want = reference.pixel(int(x), int(y));
            if (in_box(x, y)) {
                ++box;
                for (int c = 0; c < 4; ++c) ASSERT_EQ(got[c], kBoxColor[c]) << x << "," << y;
                ASSERT_EQ(depth_pixels()[size_t{y} * kWidth + x], 1.0f);
                continue;
            }
            ++outside;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(got[c], want[c]) << x << "," << y << " channel " << c;
            ASSERT_EQ(got[3], 1.0f);
            if (got[0] + got[1] + got[2] > 0.0f) ++lit;
            // The host's depth now holds vkwater's: the water and floor are between the planes.
            const float depth = depth_pixels()[size_t{y} * kWidth + x];
            ASSERT_TRUE(depth >= 0.0f && depth < 1.0f) << depth;
        }
    }
    EXPECT_EQ(box, size_t{kBoxX1 - kBoxX0} * (kBoxY1 - kBoxY0));
    EXPECT_EQ(lit, outside);  // pool has no black pixel: a blank frame would fail here
}

// A scene built in code goes through the file's loader: pool in structs renders pool.json's image
// bit for bit.
TEST_F(WorldTest, ASceneBuiltInCodeRendersAsItsFile) {
    auto world = vkwater::World::load(host_device(), embed_host::pool_scene());
    ASSERT_TRUE(world) << world.status().message;
    make_targets();
    const vkwater::Status status = run_frame(*world.value());
    ASSERT_TRUE(status) << status.message;
    expect_renderers_image_outside_the_box(kPool);
}

// The structs pool does not use (a gradient sky, the medium's coefficients, the three receiver
// shapes, Gerstner steepness) reach the loader as the scene file that says the same would: the two
// worlds' frames are equal bit for bit, and not blank.
TEST_F(WorldTest, EveryStructReachesTheLoaderAsItsJsonField) {
    vkwater::Scene scene;
    scene.camera = {{0.5, 1.5, 3.5}, {0.0, -1.0, 0.0}, 55.0, 0.1, 100.0};
    scene.sun = {50.0, 120.0, {2.0, 1.8, 1.5}};
    scene.sky.gradient = vkwater::Sky::Gradient{{0.2, 0.3, 0.6}, {0.7, 0.7, 0.8}, {{0.1, 0.1, 0.1}}, 0.7};
    scene.floor = {-2.0, {0.4, 0.5, 0.3}, 6.0};
    vkwater::Water water;
    water.level = 0.1;
    water.ior = 1.34;
    water.half_extent = 5.0;
    water.grid_resolution = 64;
    water.time = 0.25;
    water.waves = {{0.02, 0.8, 10.0, 30.0, 0.5}, {0.01, 0.45, 100.0, 0.0, 0.0}};
    scene.water = water;
    scene.medium = {"", {0.3, 0.1, 0.05}, {0.1, 0.1, 0.12}, 0.8};
    vkwater::Receiver box;
    box.half_size = {0.3, 0.6, 0.3};
    box.translation = {-0.8, -1.0, -0.5};
    box.rotation_deg = {0.0, 25.0, 0.0};
    box.albedo = {0.8, 0.2, 0.2};
    vkwater::Receiver sphere;
    sphere.shape = vkwater::Receiver::Shape::Sphere;
    sphere.radius = 0.35;
    sphere.translation = {0.7, -1.2, 0.2};
    sphere.scale = {1.0, 0.6, 1.0};
    sphere.name = "ball";
    vkwater::Receiver plane;
    plane.shape = vkwater::Receiver::Shape::Plane;
    plane.half_size = {0.5, 0.0, 0.8};
    plane.translation = {0.0, -1.9, 1.0};
    scene.receivers = {box, sphere, plane};
    const std::string file_text = R"({
      "camera": {"position": [0.5, 1.5, 3.5], "target": [0, -1, 0], "fov_y_deg": 55, "near": 0.1, "far": 100},
      "sun": {"elevation_deg": 50, "azimuth_deg": 120, "irradiance": [2, 1.8, 1.5]},
      "sky": {"model": "gradient", "zenith": [0.2, 0.3, 0.6], "horizon": [0.7, 0.7, 0.8],
              "ground": [0.1, 0.1, 0.1], "exponent": 0.7},
      "floor": {"height": -2, "albedo": [0.4, 0.5, 0.3], "half_extent": 6},
      "water": {"level": 0.1, "ior": 1.34, "half_extent": 5, "grid_resolution": 64, "time": 0.25,
                "waves": {"model": "sum", "components": [
                  {"amplitude": 0.02, "wavelength": 0.8, "direction_deg": 10, "phase_deg": 30, "steepness": 0.5},
                  {"amplitude": 0.01, "wavelength": 0.45, "direction_deg": 100}]}},
      "medium": {"sigma_a": [0.3, 0.1, 0.05], "sigma_s": [0.1, 0.1, 0.12], "g": 0.8},
      "receivers": [
        {"type": "box", "half_size": [0.3, 0.6, 0.3], "translation": [-0.8, -1, -0.5], "rotation_deg": [0, 25, 0],
         "albedo": [0.8, 0.2, 0.2]},
        {"type": "sphere", "name": "ball", "radius": 0.35, "translation": [0.7, -1.2, 0.2], "scale": [1, 0.6, 1]},
        {"type": "plane", "half_size": [0.5, 0.8], "translation": [0, -1.9, 1]}]
    })";
    make_targets();
    auto from_structs = vkwater::World::load(host_device(), scene);
    ASSERT_TRUE(from_structs) << from_structs.status().message;
    ASSERT_TRUE(run_frame(*from_structs.value()));
    const size_t values = size_t{kWidth} * kHeight * 4;
    const std::vector<float> structs_image(color_pixels(), color_pixels() + values);
    auto from_text = vkwater::World::parse(host_device(), file_text, "structs.json");
    ASSERT_TRUE(from_text) << from_text.status().message;
    ASSERT_TRUE(run_frame(*from_text.value()));
    size_t lit = 0;
    for (size_t i = 0; i < values; ++i) {
        ASSERT_EQ(structs_image[i], color_pixels()[i]) << "value " << i;  // the same passes, bit for bit
        if (i % 4 != 3 && structs_image[i] > 0.0f) ++lit;
    }
    EXPECT_GT(lit, values / 2);
}

// Infinite water in the structs is the file's "half_extent": "infinite", whatever half_extent holds.
TEST(SceneStructs, InfiniteWaterIsTheFilesWord) {
    vkwater::Scene scene = embed_host::pool_scene();
    scene.water->infinite = true;
    scene.water->half_extent = 3.0;
    const std::string text = vkwater::scene_json(scene);
    EXPECT_NE(text.find(R"("half_extent": "infinite")"), std::string::npos) << text;
    EXPECT_EQ(text.find(R"("half_extent": 3)"), std::string::npos) << text;
}

// A value out of range in the structs is the loader's message, naming the field as a file's would.
TEST_F(WorldTest, AStructValueOutOfRangeIsNamedAsItsField) {
    vkwater::Scene scene = embed_host::pool_scene();
    scene.sun.irradiance[1] = 1e40;
    const auto bright = vkwater::World::load(host_device(), scene);
    ASSERT_FALSE(bright);
    EXPECT_EQ(bright.status().kind, vkwater::ErrorKind::InvalidInput);
    EXPECT_NE(bright.status().message.find("in-memory scene: sun.irradiance[1]: 1e+40 is out of range"),
              std::string::npos)
        << bright.status().message;
    scene = embed_host::pool_scene();
    scene.camera.fov_y_deg = std::nan("");
    const auto not_a_number = vkwater::World::load(host_device(), scene);
    ASSERT_FALSE(not_a_number);
    EXPECT_NE(not_a_number.status().message.find("camera.fov_y_deg"), std::string::npos)
        << not_a_number.status().message;
    scene = embed_host::pool_scene();
    scene.water.reset();
    const auto dry = vkwater::World::load(host_device(), scene);
    ASSERT_FALSE(dry);
    EXPECT_NE(dry.status().message.find("in-memory scene: water: missing"), std::string::npos) << dry.status().message;
}

// The optional outputs: the caustic layer copied into a host image equals the renderer's layer bit
// for bit, and a timed frame reports each pass, the composite into the host's targets among them.
TEST_F(WorldTest, TheCausticLayerAndThePassTimesReachTheHost) {
    auto world = vkwater::World::load(host_device(), kPool);
    ASSERT_TRUE(world) << world.status().message;
    make_targets();
    // A view needs a usage a view serves (sampling), besides the copies in and out.
    caustic_ = Image(context(),
                     {kWidth, kHeight, VK_FORMAT_R32G32B32A32_SFLOAT,
                      VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
                     "host caustic layer");
    caustic_out_ = Buffer(context(), {size_t{kWidth} * kHeight * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true},
                          "host caustic layer readback");
    const vkwater::Status status = run_frame(*world.value());
    ASSERT_TRUE(status) << status.message;

    vkw::Renderer renderer(context());
    vkw::RenderOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.timing = vkw::fg::TimingMode::None;
    options.caustic_layer = true;
    const vkw::ImageRGBA32F reference = renderer.render(vkw::load_scene(kPool), options).image;
    ASSERT_EQ(reference.layers.size(), 1u);
    const std::vector<float>& want = reference.layers[0].rgb;
    const auto* got = static_cast<const float*>(caustic_out_.mapped());
    float low = got[0], high = got[0];
    for (size_t i = 0; i < size_t{kWidth} * kHeight; ++i) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(got[4 * i + c], want[3 * i + c]) << "pixel " << i << " channel " << c;
        low = std::min(low, got[4 * i]);
        high = std::max(high, got[4 * i]);
    }
    EXPECT_LT(low, high) << "pool's caustics vary over the floor: a constant layer is no layer";

    vkwater::Frame timed = frame(*world.value());  // the targets are where the readback left them
    timed.color.before = timed.color.after;
    timed.depth.before = timed.depth.after;
    const auto timings = world.value()->time_frame(timed);
    ASSERT_TRUE(timings) << timings.status().message;
    EXPECT_EQ(timings.value().method, "fences");  // lavapipe: a CPU device
    EXPECT_GT(timings.value().total_ms, 0.0);
    const auto& passes = timings.value().passes;
    EXPECT_TRUE(std::any_of(passes.begin(), passes.end(),
                            [](const vkwater::PassTiming& p) { return p.pass == "host composite" && p.ms > 0.0; }));
}

// A host with two frames in flight: two frames recorded back to back into one command buffer, so
// that synchronization validation sees them together. With frames_in_flight 2 they share none of
// vkwater's own images and buffers, validation finds nothing and the picture is right; with 1 the
// second frame reuses the first's without waiting for it, and validation reports the hazards (which
// is why a host with one frame in flight must wait for each frame before submitting the next).
TEST_F(WorldTest, FramesInFlightShareNoneOfTheFramesImages) {
    const std::string calm = std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json";
    {
        auto world = vkwater::World::load(host_device(), calm, {.frames_in_flight = 2});
        ASSERT_TRUE(world) << world.status().message;
        make_targets();
        ASSERT_TRUE(run_frame(*world.value(), 2));
    }
    expect_renderers_image_outside_the_box(calm);
    {
        auto world = vkwater::World::load(host_device(), calm, {.frames_in_flight = 1});
        ASSERT_TRUE(world) << world.status().message;
        ASSERT_TRUE(run_frame(*world.value(), 2));
    }
    tear_down_host_objects();
    const std::vector<std::string> messages = finish_and_collect_validation();
    const bool hazard = std::any_of(messages.begin(), messages.end(),
                                    [](const std::string& m) { return m.find("SYNC-HAZARD") != std::string::npos; });
    EXPECT_TRUE(hazard) << messages.size() << " messages, none a hazard";
}

TEST_F(WorldTest, EveryObjectGoesThroughTheHostsAllocatorAndIsFreed) {
    CountingAllocator counter;
    const VkAllocationCallbacks callbacks = counter.callbacks();
    {
        auto world = vkwater::World::load(host_device(&callbacks), kPool);
        ASSERT_TRUE(world) << world.status().message;
        make_targets();
        ASSERT_TRUE(run_frame(*world.value()));
        EXPECT_GT(counter.total.load(), 0u);
    }
    std::lock_guard lock(counter.mutex);
    EXPECT_TRUE(counter.live.empty()) << counter.live.size() << " allocations left after the world";
}

TEST_F(WorldTest, MistakesAreStatusesThatNameThem) {
    const auto missing = vkwater::World::load(host_device(), "no/such/scene.json");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.status().kind, vkwater::ErrorKind::InvalidInput);
    EXPECT_NE(missing.status().message.find("no/such/scene.json"), std::string::npos) << missing.status().message;

    const auto no_frames = vkwater::World::load(host_device(), kPool, {.frames_in_flight = 0});
    ASSERT_FALSE(no_frames);
    EXPECT_NE(no_frames.status().message.find("frames_in_flight 0 (accepted: 1 to 8)"), std::string::npos)
        << no_frames.status().message;

    const auto bad_field = vkwater::World::load(host_device(), kPool, {.overrides = {"camera.fov_y_deg=500"}});
    ASSERT_FALSE(bad_field);
    EXPECT_NE(bad_field.status().message.find("camera.fov_y_deg"), std::string::npos) << bad_field.status().message;

    auto world = vkwater::World::load(host_device(), kPool);
    ASSERT_TRUE(world) << world.status().message;
    make_targets();
    vkwater::Frame frame_8bit = frame(*world.value());
    frame_8bit.color.format = VK_FORMAT_R8G8B8A8_UNORM;
    vkwater::Frame frame_small_depth = frame(*world.value());
    frame_small_depth.depth.width = kWidth / 2;
    vkwater::Frame frame_wide = frame(*world.value());
    frame_wide.camera.fov_y_deg = 200.0;
    vkwater::Frame frame_no_cmd = frame(*world.value());
    const std::pair<const vkwater::Frame*, std::string> cases[] = {
        {&frame_8bit, "color: format RGBA8_UNORM"},
        {&frame_small_depth, "depth: size 80x120"},
        {&frame_wide, "camera.fov_y_deg 200 (accepted: 1 < value < 179 degrees)"}};
    for (const auto& [bad, named] : cases) {
        context().submit_and_wait(
            [&](VkCommandBuffer cmd) {
                const vkwater::Status status = world.value()->record(cmd, *bad);
                EXPECT_EQ(status.kind, vkwater::ErrorKind::InvalidInput);
                EXPECT_NE(status.message.find(named), std::string::npos) << status.message;
            },
            "refused frame");
    }
    const vkwater::Status no_cmd = world.value()->record(VK_NULL_HANDLE, frame_no_cmd);
    EXPECT_EQ(no_cmd.kind, vkwater::ErrorKind::InvalidInput);
}

}  // namespace
