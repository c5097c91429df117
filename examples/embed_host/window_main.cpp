// embed_host_window SCENE_JSON [--frames N] [--validation]
//
// The host of embed_host_offscreen in a window (GLFW): each frame it clears its own HDR colour and
// depth targets and draws its box, has vkwater record the water into them, and blits the colour into
// the swapchain image it presents. It quits when the window is closed, or after N frames when given.
// Exit codes as embed_host_offscreen's.
#include "arguments.hpp"
#include "barriers.hpp"
#include "box.hpp"
#include "errors.hpp"
#include "frame_commands.hpp"
#include "gpu_memory.hpp"
#include "host_device.hpp"
#include "host_pass.hpp"

#include <vkwater/world.hpp>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace embed_host;

constexpr const char* kUsage = "usage: embed_host_window SCENE_JSON [--frames N] [--validation]";
constexpr int kWindowWidth = 800, kWindowHeight = 600;

struct Args {
    std::string scene;
    uint32_t frames = 0;  // 0: until the window is closed
    bool validation = false;
};

Args parse_args(int argc, char** argv) {
    Args args;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--frames" && i + 1 < argc) {
            args.frames = parse_count(arg, argv[++i], 1000000, kUsage);
        } else if (arg == "--validation") {
            args.validation = true;
        } else if (arg.starts_with("-")) {
            throw HostError("unknown option or missing value: " + arg + "\n" + kUsage, kExitInvalidInput);
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.size() != 1) throw HostError(kUsage, kExitInvalidInput);
    args.scene = positional[0];
    return args;
}

std::string glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no description";
}

// GLFW and its window, ended in the reverse order of their making.
struct Glfw {
    Glfw() {
        if (!glfwInit()) throw HostError("glfwInit: " + glfw_error(), kExitInternal);
    }
    ~Glfw() { glfwTerminate(); }
};

struct Window {
    GLFWwindow* window = nullptr;
    Window() {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, no OpenGL context
        // The swapchain is made once, for this size: a real host recreates it (and its targets) on
        // resize, which this sample leaves out.
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        window = glfwCreateWindow(kWindowWidth, kWindowHeight, "vkwater embed_host", nullptr, nullptr);
        if (!window) throw HostError("glfwCreateWindow: " + glfw_error(), kExitInternal);
    }
    ~Window() { glfwDestroyWindow(window); }
};

struct Surface {
    VkInstance instance;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    Surface(VkInstance vk_instance, GLFWwindow* window) : instance(vk_instance) {
        check(glfwCreateWindowSurface(instance, window, nullptr, &surface), "glfwCreateWindowSurface");
    }
    ~Surface() { vkDestroySurfaceKHR(instance, surface, nullptr); }
};

// A FIFO swapchain whose images are blit destinations, a semaphore for the acquisition and one per
// image for its presentation (an image's semaphore is free again once the image is acquired again).
struct Swapchain {
    VkDevice device;
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    std::vector<VkImage> images;
    VkSemaphore acquired = VK_NULL_HANDLE;
    std::vector<VkSemaphore> rendered;

    Swapchain(const HostVulkan& host, VkSurfaceKHR surface) : device(host.device()) {
        try {
            create(host.physical_device(), surface);
        } catch (...) {
            release();  // a constructor that throws runs no destructor
            throw;
        }
    }
    ~Swapchain() { release(); }

    void create(VkPhysicalDevice physical_device, VkSurfaceKHR surface) {
        VkSurfaceCapabilitiesKHR caps;
        check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_device, surface, &caps),
              "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
        if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
            throw HostError("the window's surface cannot be a blit destination", kExitInternal);
        }
        uint32_t count = 0;
        check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &count, nullptr),
              "vkGetPhysicalDeviceSurfaceFormatsKHR");
        std::vector<VkSurfaceFormatKHR> formats(count);
        check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &count, formats.data()),
              "vkGetPhysicalDeviceSurfaceFormatsKHR");
        // An sRGB format, so that the blit encodes the linear colour for the display; the first blit
        // destination otherwise.
        auto blit_destination = [&](const VkSurfaceFormatKHR& f) {
            VkFormatProperties properties;
            vkGetPhysicalDeviceFormatProperties(physical_device, f.format, &properties);
            return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT) != 0;
        };
        auto chosen = std::find_if(formats.begin(), formats.end(), [&](const VkSurfaceFormatKHR& f) {
            return (f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) && blit_destination(f);
        });
        if (chosen == formats.end()) chosen = std::find_if(formats.begin(), formats.end(), blit_destination);
        if (chosen == formats.end()) throw HostError("no surface format is a blit destination", kExitInternal);
        format = chosen->format;
        extent = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent
                                                        : VkExtent2D{uint32_t(kWindowWidth), uint32_t(kWindowHeight)};

        VkSwapchainCreateInfoKHR info{};
        info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
        info.surface = surface;
        info.minImageCount =
            caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount) : caps.minImageCount + 1;
        info.imageFormat = chosen->format;
        info.imageColorSpace = chosen->colorSpace;
        info.imageExtent = extent;
        info.imageArrayLayers = 1;
        info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;  // only ever a blit's destination
        info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.preTransform = caps.currentTransform;
        info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                                  ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                                  : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                                -caps.supportedCompositeAlpha);  // lowest bit
        info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // the one mode every device has; vsync
        info.clipped = VK_TRUE;
        check(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain), "vkCreateSwapchainKHR");
        check(vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr), "vkGetSwapchainImagesKHR");
        images.resize(count);
        check(vkGetSwapchainImagesKHR(device, swapchain, &count, images.data()), "vkGetSwapchainImagesKHR");

        VkSemaphoreCreateInfo semaphore_info{};
        semaphore_info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
        check(vkCreateSemaphore(device, &semaphore_info, nullptr, &acquired), "vkCreateSemaphore");
        rendered.assign(count, VK_NULL_HANDLE);
        for (VkSemaphore& semaphore : rendered) {
            check(vkCreateSemaphore(device, &semaphore_info, nullptr, &semaphore), "vkCreateSemaphore");
        }
    }
    void release() {
        vkDeviceWaitIdle(device);  // presentations may still wait on the semaphores
        for (VkSemaphore semaphore : rendered) vkDestroySemaphore(device, semaphore, nullptr);
        vkDestroySemaphore(device, acquired, nullptr);
        vkDestroySwapchainKHR(device, swapchain, nullptr);
    }
};

// The colour's state for the blit after vkwater.
constexpr vkwater::ImageState kBlitSource{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                                          VK_ACCESS_2_TRANSFER_READ_BIT};

// The HDR colour into the swapchain image, a plain clamp to [0, 1]. A real host tone-maps here
// (exposure and a curve, in a pass of its own): vkwater's colour is linear radiance, not display values.
void blit_to_swapchain(VkCommandBuffer cmd, const Image& color, VkImage swapchain_image, VkExtent2D extent) {
    transition(cmd, swapchain_image, VK_IMAGE_ASPECT_COLOR_BIT,
               {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE},  // after the acquisition
               {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(color.width), int32_t(color.height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {int32_t(extent.width), int32_t(extent.height), 1};
    vkCmdBlitImage(cmd, color.image, kBlitSource.layout, swapchain_image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &region, VK_FILTER_NEAREST);
    // Presentation waits on the submission's semaphore, which comes after every stage: no stage here.
    transition(cmd, swapchain_image, VK_IMAGE_ASPECT_COLOR_BIT,
               {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
               {VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE});
}

struct Summary {
    std::string device;
    VkExtent2D extent{};
    uint32_t frames = 0;
    double ms_per_frame = 0.0;
};

Summary run(const Args& args) {
    const Glfw glfw;
    if (!glfwVulkanSupported()) throw HostError("GLFW finds no Vulkan loader", kExitInternal);
    const Window window;

    HostOptions options{args.validation, {}, {VK_KHR_SWAPCHAIN_EXTENSION_NAME}};
    uint32_t glfw_extension_count = 0;
    const char** glfw_extensions = glfwGetRequiredInstanceExtensions(&glfw_extension_count);
    if (!glfw_extensions) throw HostError("glfwGetRequiredInstanceExtensions: " + glfw_error(), kExitInternal);
    options.instance_extensions.assign(glfw_extensions, glfw_extensions + glfw_extension_count);
    HostVulkan host(options);
    const Surface surface(host.instance(), window.window);
    host.create_device(surface.surface);

    vkwater::Result<std::unique_ptr<vkwater::World>> loaded = vkwater::World::load(host.lend(), args.scene);
    check(loaded.status());
    const std::unique_ptr<vkwater::World> world = std::move(loaded.value());

    const Swapchain swapchain(host, surface.surface);
    const uint32_t width = swapchain.extent.width, height = swapchain.extent.height;
    // RGBA16F: vkwater's HDR colour at half the memory of RGBA32F; TRANSFER_SRC for the blit.
    const Image color(host, VK_FORMAT_R16G16B16A16_SFLOAT, width, height,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    const Image depth(host, VK_FORMAT_D32_SFLOAT, width, height, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                      VK_IMAGE_ASPECT_DEPTH_BIT);
    const BoxPipeline box(host.device(), color.format, depth.format);
    FrameCommands commands(host.device(), host.queue_family());

    const vkwater::Camera camera = world->scene_camera();
    const vkwater::CameraMatrices matrices = vkwater::World::matrices(camera, width, height);
    const Mat4 model = box_model(camera);

    vkwater::ImageState color_last{}, depth_last{};
    uint32_t frames = 0;
    const auto start = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window.window) && (args.frames == 0 || frames < args.frames)) {
        glfwPollEvents();
        // The previous frame is over (vkwater's frames run one at a time), and with it the wait on
        // `acquired`, which the acquisition below signals again.
        VkCommandBuffer cmd = commands.begin();
        uint32_t index = 0;
        const VkResult acquire = vkAcquireNextImageKHR(host.device(), swapchain.swapchain, UINT64_MAX,
                                                       swapchain.acquired, VK_NULL_HANDLE, &index);
        if (acquire != VK_SUBOPTIMAL_KHR) check(acquire, "vkAcquireNextImageKHR");

        record_host_pass(cmd, color, depth, color_last, depth_last, box, matrices, model);
        vkwater::Frame frame;
        frame.camera = camera;
        // The waves move with the wall clock, from the scene's own time.
        frame.time_seconds =
            world->scene_time() + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        frame.color = as_target(color, kColorAfterHostPass, kBlitSource);
        // Nothing reads the depth after vkwater here; it stays an attachment for the next frame's clear.
        frame.depth = as_target(depth, kDepthAfterHostPass, kDepthAfterHostPass);
        check(world->record(cmd, frame));
        blit_to_swapchain(cmd, color, swapchain.images[index], swapchain.extent);
        // The blit's layout transition waits for the acquisition: the semaphore's wait stage is BLIT.
        commands.submit(host.queue(), swapchain.acquired, VK_PIPELINE_STAGE_2_BLIT_BIT, swapchain.rendered[index]);

        VkPresentInfoKHR present{};
        present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
        present.waitSemaphoreCount = 1;
        present.pWaitSemaphores = &swapchain.rendered[index];
        present.swapchainCount = 1;
        present.pSwapchains = &swapchain.swapchain;
        present.pImageIndices = &index;
        const VkResult presented = vkQueuePresentKHR(host.queue(), &present);
        if (presented != VK_SUBOPTIMAL_KHR) check(presented, "vkQueuePresentKHR");

        color_last = frame.color.after;
        depth_last = frame.depth.after;
        ++frames;
    }
    commands.wait();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {host.device_name(), swapchain.extent, frames, frames ? 1000.0 * seconds / frames : 0.0};
}

}  // namespace

int main(int argc, char** argv) {
    Summary summary;
    try {
        summary = run(parse_args(argc, argv));
    } catch (const HostError& error) {
        std::fprintf(stderr, "embed_host_window: %s\n", error.what());
        return error.exit_code();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "embed_host_window: %s\n", error.what());
        return kExitInternal;
    }
    const uint32_t messages = validation_message_count();  // after the device and instance are gone
    std::printf(
        "embed_host_window: %ux%u on '%s', %u frame(s), %.1f ms per frame (wall clock), %u validation "
        "message(s)\n",
        summary.extent.width, summary.extent.height, summary.device.c_str(), summary.frames, summary.ms_per_frame,
        messages);
    return messages > 0 ? kExitInvalidInput : 0;
}
