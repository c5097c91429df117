// The embedded path's cost against the CLI's frame, as a ratio measured in one run: the same scene
// at the same size on one device, rendered by vkw::Renderer (the CLI's frame: its passes and a
// readback) and by vkwater::World (the same passes and a composite into host targets, recorded
// into a host command buffer), interleaved A B A B, each timed on the CPU clock from submission
// to the fence, median of rounds. Usage: embed_overhead SCENE [WIDTH HEIGHT ROUNDS]
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/device_features.hpp"
#include "engine/vk/resources.hpp"
#include "passes/frame/renderer.hpp"

#include <vkwater/world.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: embed_overhead SCENE [WIDTH HEIGHT ROUNDS]\n");
        return 1;
    }
    const std::string scene_file = argv[1];
    const uint32_t width = argc > 3 ? uint32_t(std::atoi(argv[2])) : 320;
    const uint32_t height = argc > 3 ? uint32_t(std::atoi(argv[3])) : 240;
    const int rounds = argc > 4 ? std::atoi(argv[4]) : 7;

    vkw::Context context(vkw::ContextOptions{});
    vkw::DeviceFeatureChain features;
    vkw::request_device_features(context.physical_device(), features);
    const vkwater::HostDevice host{context.instance(),     context.physical_device(), context.device(), context.queue(),
                                   context.queue_family(), &features.features,        nullptr,          false};
    auto world = vkwater::World::load(host, scene_file);
    if (!world) {
        std::fprintf(stderr, "%s\n", world.status().message.c_str());
        return 1;
    }

    const vkw::Image color(context,
                           {width, height, VK_FORMAT_R32G32B32A32_SFLOAT,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                           "host colour");
    const vkw::Image depth(context, {width, height, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT},
                           "host depth");
    vkwater::Frame frame;
    frame.camera = world.value()->scene_camera();
    frame.time_seconds = world.value()->scene_time();
    // The targets enter each frame holding nothing (as after a host that clears them in vkwater's
    // composite's place) and leave it ready to be read: the comparison's readback counterpart.
    frame.color = {color.handle(),
                   color.view(),
                   VK_FORMAT_R32G32B32A32_SFLOAT,
                   width,
                   height,
                   {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
                   {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT}};
    frame.depth = {depth.handle(),
                   depth.view(),
                   VK_FORMAT_D32_SFLOAT,
                   width,
                   height,
                   {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
                   {VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT}};

    const vkw::Scene scene = vkw::load_scene(scene_file);
    vkw::Renderer renderer(context);
    vkw::RenderOptions options;
    options.width = width;
    options.height = height;
    options.timing = vkw::fg::TimingMode::None;

    std::vector<double> cli_ms, embedded_ms;
    for (int round = -1; round < rounds; ++round) {  // round -1 warms both up (pipelines, resources)
        Clock::time_point start = Clock::now();
        renderer.render(scene, options);
        const double a = ms_since(start);
        vkwater::Status status;
        start = Clock::now();
        context.submit_and_wait([&](VkCommandBuffer cmd) { status = world.value()->record(cmd, frame); }, "embedded");
        const double b = ms_since(start);
        if (!status) {
            std::fprintf(stderr, "%s\n", status.message.c_str());
            return 2;
        }
        if (round < 0) continue;
        cli_ms.push_back(a);
        embedded_ms.push_back(b);
    }
    std::vector<double> ratios;
    for (size_t i = 0; i < cli_ms.size(); ++i) ratios.push_back(embedded_ms[i] / cli_ms[i]);
    std::printf("| %s | %ux%u | %.1f | %.1f | %.3f |\n", scene_file.c_str(), width, height, median(cli_ms),
                median(embedded_ms), median(ratios));
    return 0;
}
