// embed_host_offscreen SCENE_JSON OUT_PREFIX [--width W] [--height H] [--validation] [--frames N]
//
// A host engine without a window that draws its own geometry (an orange box) and has vkwater draw a
// scene's water into the same colour and depth targets, in one command buffer per frame. It writes
// OUT_PREFIX.color.pfm (the last frame: linear radiance, the box where it is nearer than the water)
// and OUT_PREFIX.box_mask.pfm (1 where the host drew the box, read from its depth before vkwater's).
// Exit codes: 0; 1 for what the user can fix (arguments, scene file), or for any validation
// message; 2 for the device or an internal failure.
#include "arguments.hpp"
#include "barriers.hpp"
#include "box.hpp"
#include "errors.hpp"
#include "frame_commands.hpp"
#include "gpu_memory.hpp"
#include "host_device.hpp"
#include "host_pass.hpp"
#include "pfm.hpp"

#include <vkwater/world.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace embed_host;

constexpr const char* kUsage =
    "usage: embed_host_offscreen SCENE_JSON OUT_PREFIX [--width W] [--height H] [--validation] [--frames N]";

struct Args {
    std::string scene;
    std::string out_prefix;
    uint32_t width = 320;
    uint32_t height = 240;
    uint32_t frames = 1;
    bool validation = false;
};

Args parse_args(int argc, char** argv) {
    Args args;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw HostError(arg + ": a value must follow\n" + kUsage, kExitInvalidInput);
            return argv[++i];
        };
        if (arg == "--width") {
            args.width = parse_count(arg, value(), 16384, kUsage);
        } else if (arg == "--height") {
            args.height = parse_count(arg, value(), 16384, kUsage);
        } else if (arg == "--frames") {
            args.frames = parse_count(arg, value(), 100000, kUsage);
        } else if (arg == "--validation") {
            args.validation = true;
        } else if (arg.starts_with("-")) {
            throw HostError("unknown option " + arg + "\n" + kUsage, kExitInvalidInput);
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.size() != 2) throw HostError(kUsage, kExitInvalidInput);
    args.scene = positional[0];
    args.out_prefix = positional[1];
    return args;
}

// Where the copies read the targets from, and what the host hands them over in.
constexpr vkwater::ImageState kCopySource{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                          VK_ACCESS_2_TRANSFER_READ_BIT};
// What a real host does with its depth after vkwater: draw more (transparent things) tested against
// it. This sample draws nothing more, but asks for the state such a host would.
constexpr vkwater::ImageState kDepthForMoreGeometry{
    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};

// The whole of `image` (in TRANSFER_SRC_OPTIMAL) into `buffer`, tightly packed.
void copy_to_buffer(VkCommandBuffer cmd, const Image& image, const ReadbackBuffer& buffer) {
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect, 0, 0, 1};
    region.imageExtent = {image.width, image.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
}

struct Summary {
    std::string device;
    uint32_t width = 0, height = 0, frames = 0;
    double ms_per_frame = 0.0;
    size_t box_pixels = 0;
    size_t non_finite = 0;
    float max_radiance = 0.0f;
    std::string color_file, mask_file;
};

Summary run(const Args& args) {
    HostVulkan host(HostOptions{args.validation, {}, {}});
    host.create_device();

    vkwater::Result<std::unique_ptr<vkwater::World>> loaded = vkwater::World::load(host.lend(), args.scene);
    check(loaded.status());
    const std::unique_ptr<vkwater::World> world = std::move(loaded.value());

    const uint32_t width = args.width, height = args.height;
    const vkwater::Camera camera = world->scene_camera();
    // The host draws with vkwater's matrices, so that its depth and vkwater's compare.
    const vkwater::CameraMatrices matrices = vkwater::World::matrices(camera, width, height);
    const Mat4 model = box_model(camera);

    // RGBA32F, so that the PFM holds exactly what vkwater wrote; TRANSFER_SRC for the readbacks.
    const Image color(host, VK_FORMAT_R32G32B32A32_SFLOAT, width, height,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    const Image depth(host, VK_FORMAT_D32_SFLOAT, width, height,
                      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                      VK_IMAGE_ASPECT_DEPTH_BIT);
    const ReadbackBuffer color_readback(host, VkDeviceSize(width) * height * 4 * sizeof(float));
    const ReadbackBuffer depth_readback(host, VkDeviceSize(width) * height * sizeof(float));
    const BoxPipeline box(host.device(), color.format, depth.format);
    FrameCommands commands(host.device(), host.queue_family());

    // The targets' last use, which the next frame's clears wait for: nothing yet.
    vkwater::ImageState color_last{}, depth_last{};
    double total_ms = 0.0;
    for (uint32_t i = 0; i < args.frames; ++i) {
        VkCommandBuffer cmd = commands.begin();
        record_host_pass(cmd, color, depth, color_last, depth_last, box, matrices, model);

        // The box mask: the host's depth before vkwater's (> 0 where the box was drawn).
        transition(cmd, depth.image, depth.aspect, kDepthAfterHostPass, kCopySource);
        copy_to_buffer(cmd, depth, depth_readback);

        // vkwater's frame, recorded into the host's command buffer. `before`: the states the host
        // left its targets in; `after`: those its next commands need, for which vkwater makes its
        // writes available. The same clock every frame, so that the output does not depend on --frames.
        vkwater::Frame frame;
        frame.camera = camera;
        frame.time_seconds = world->scene_time();
        frame.color = as_target(color, kColorAfterHostPass, kCopySource);
        frame.depth = as_target(depth, kCopySource, kDepthForMoreGeometry);
        check(world->record(cmd, frame));

        copy_to_buffer(cmd, color, color_readback);  // no barrier: vkwater left it as frame.color.after
        copies_to_host(cmd);

        const auto start = std::chrono::steady_clock::now();
        commands.submit(host.queue());
        commands.wait();
        total_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        color_last = frame.color.after;
        depth_last = frame.depth.after;
    }

    Summary summary;
    summary.device = host.device_name();
    summary.width = width;
    summary.height = height;
    summary.frames = args.frames;
    summary.ms_per_frame = total_ms / args.frames;

    const size_t pixels = size_t(width) * height;
    const auto* rgba = static_cast<const float*>(color_readback.data());
    const auto* depths = static_cast<const float*>(depth_readback.data());
    std::vector<float> rgb(pixels * 3), mask(pixels * 3);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) {
            const float value = rgba[p * 4 + c];
            rgb[p * 3 + c] = value;
            if (!std::isfinite(value)) {
                ++summary.non_finite;
            } else {
                summary.max_radiance = std::max(summary.max_radiance, value);
            }
        }
        const float in_box = depths[p] > 0.0f ? 1.0f : 0.0f;
        std::fill_n(mask.begin() + std::ptrdiff_t(p * 3), 3, in_box);
        summary.box_pixels += in_box > 0.0f;
    }
    summary.color_file = args.out_prefix + ".color.pfm";
    summary.mask_file = args.out_prefix + ".box_mask.pfm";
    auto write = [&](const std::string& path, const std::vector<float>& image) {
        if (!write_pfm(path, width, height, image)) {
            throw HostError(path + ": cannot be written (" + std::strerror(errno) + ")", kExitInvalidInput);
        }
    };
    write(summary.color_file, rgb);
    write(summary.mask_file, mask);
    return summary;
}

}  // namespace

int main(int argc, char** argv) {
    Summary summary;
    try {
        summary = run(parse_args(argc, argv));
    } catch (const HostError& error) {
        std::fprintf(stderr, "embed_host_offscreen: %s\n", error.what());
        return error.exit_code();
    } catch (const std::exception& error) {  // std::bad_alloc and the like
        std::fprintf(stderr, "embed_host_offscreen: %s\n", error.what());
        return kExitInternal;
    }
    // Counted after the device and instance are gone, so that what their destruction reported counts.
    const uint32_t messages = validation_message_count();
    std::printf(
        "embed_host_offscreen: %ux%u on '%s', %u frame(s), %.1f ms per frame (submit to fence), box %zu px, "
        "colour max %.3g with %zu non-finite, %u validation message(s); wrote %s and %s\n",
        summary.width, summary.height, summary.device.c_str(), summary.frames, summary.ms_per_frame, summary.box_pixels,
        double(summary.max_radiance), summary.non_finite, messages, summary.color_file.c_str(),
        summary.mask_file.c_str());
    return messages > 0 ? kExitInvalidInput : 0;
}
