// framegraph_bench: what the frame graph costs on the CPU.
//  1. compile() of a 30-pass graph (culling, ordering, barriers, aliasing estimate);
//  2. recording the test chain (compute -> sample into attachment -> copy) through the
//     graph against the same commands and barriers written by hand;
//  3. pool's frame on the CPU as the renderer makes it every frame: the needs' decision, the
//     frame constants, the declaration and the compilation (scenes/pool.json at 800x600), and
//     the heap allocations they make (this program counts every operator new).
// Prints a table of medians; nothing is asserted (speed is measured, not tested).
// `--cpu-only` stops after step 3's CPU-only rows and makes no Vulkan device: for a profiler, as
// `valgrind --tool=callgrind --collect-atstart=no --toggle-collect='vkw::decide_frame_needs*'
// --toggle-collect='vkw::build_frame_graph*' --toggle-collect='vkw::fg::FrameGraph::compile*'
// build/tools/benchmarks/framegraph_bench --cpu-only`.
#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/pipeline.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/present/readback.hpp"
#include "tools/benchmarks/chain_graph.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

// Every heap allocation of this program, counted (the replaceable global operator new: the sized
// and aligned forms of new and all forms of delete forward to these two pairs).
namespace {
std::atomic<size_t> heap_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    heap_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace vkw;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

double median_ms(int runs, const std::function<void()>& work) {
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        const auto start = Clock::now();
        work();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    return median(std::move(times));
}

// 30 passes: 10 rounds of (compute writes a buffer, compute writes an image from it,
// graphics samples that image into an attachment); the last attachment is the output.
void declare_thirty_passes(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle buffer;
        fg::ImageHandle image;
        fg::ImageHandle target;
    };
    fg::ImageHandle previous;
    for (int round = 0; round < 10; ++round) {
        const std::string n = std::to_string(round);
        const auto& a = graph.add_pass<Data>(
            "simulate " + n, fg::PassKind::Compute,
            [&](fg::PassBuilder& b, Data& d) {
                if (previous.valid()) b.sample(previous);
                d.buffer = b.write_storage(b.create_buffer("particles " + n, {1 << 20}));
            },
            [](const Data&, fg::PassContext&) {});
        const auto& c = graph.add_pass<Data>(
            "splat " + n, fg::PassKind::Compute,
            [&](fg::PassBuilder& b, Data& d) {
                b.read_storage(a.buffer);
                d.image = b.write_storage(
                    b.create_image("density " + n, {VK_FORMAT_R32_SFLOAT, fg::SizeClass::OutputRelative, 0.5f}));
            },
            [](const Data&, fg::PassContext&) {});
        const auto& g = graph.add_pass<Data>(
            "shade " + n, fg::PassKind::Graphics,
            [&](fg::PassBuilder& b, Data& d) {
                b.sample(c.image);
                d.target = b.color_attachment(b.create_image("shaded " + n, {VK_FORMAT_R16G16B16A16_SFLOAT}));
            },
            [](const Data&, fg::PassContext&) {});
        previous = g.target;
    }
    graph.request_output(previous);
}

constexpr uint32_t kSize = 256;
constexpr VkDeviceSize kBytes = VkDeviceSize{kSize} * kSize * 16;

void image_barrier(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                   VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

// The test chain written by hand, as a careful Vulkan programmer would without a graph.
struct HandWrittenChain {
    Image pattern, doubled;
    Buffer readback;
    VkSampler sampler = VK_NULL_HANDLE;
    std::unique_ptr<Pipeline> compute, graphics;
    const Context& context;

    explicit HandWrittenChain(const Context& c)
        : pattern(
              c, {kSize, kSize, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
              "pattern"),
          doubled(c,
                  {kSize, kSize, VK_FORMAT_R32G32B32A32_SFLOAT,
                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                  "doubled"),
          readback(c, {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback"),
          context(c) {
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        VKW_CHECK(vkCreateSampler(c.device(), &info, nullptr, &sampler), "sampler");
        ComputePipelineDesc cd{chain::kPatternShader,
                               {{{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT}}}};
        compute = std::make_unique<Pipeline>(c, cd, "hand compute");
        GraphicsPipelineDesc gd;
        gd.vertex_shader = "common/fullscreen.vert";
        gd.fragment_shader = chain::kCopyShader;
        gd.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
        gd.color_formats = {VK_FORMAT_R32G32B32A32_SFLOAT};
        graphics = std::make_unique<Pipeline>(c, gd, "hand graphics");
    }
    ~HandWrittenChain() { vkDestroySampler(context.device(), sampler, nullptr); }

    void record(VkCommandBuffer cmd) const {
        image_barrier(cmd, pattern.handle(), VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute->handle());
        VkDescriptorImageInfo storage{VK_NULL_HANDLE, pattern.view(), VK_IMAGE_LAYOUT_GENERAL};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        write.pImageInfo = &storage;
        context.push_descriptor_set()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute->layout(), 0, 1, &write);
        vkCmdDispatch(cmd, kSize / 8, kSize / 8, 1);
        image_barrier(cmd, pattern.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        image_barrier(cmd, doubled.handle(), VK_PIPELINE_STAGE_2_NONE, 0,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = doubled.view();
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {kSize, kSize}};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color;
        vkCmdBeginRendering(cmd, &rendering);
        const VkViewport viewport{0, float(kSize), float(kSize), -float(kSize), 0, 1};
        const VkRect2D scissor{{0, 0}, {kSize, kSize}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, graphics->handle());
        VkDescriptorImageInfo sampled{sampler, pattern.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = &sampled;
        context.push_descriptor_set()(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, graphics->layout(), 0, 1, &write);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        image_barrier(cmd, doubled.handle(), VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kSize, kSize, 1};
        vkCmdCopyImageToBuffer(cmd, doubled.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1,
                               &region);
    }
};

// Times only the recording (begin .. end of the command buffer), never the GPU.
double median_record_ms(const Context& context, VkCommandPool pool, int runs,
                        const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VKW_CHECK(vkAllocateCommandBuffers(context.device(), &alloc, &cmd), "bench command buffer");
    const double ms = median_ms(runs, [&] {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        vkBeginCommandBuffer(cmd, &begin);
        record(cmd);
        vkEndCommandBuffer(cmd);
        vkResetCommandBuffer(cmd, 0);
    });
    vkFreeCommandBuffers(context.device(), pool, 1, &cmd);
    return ms;
}

}  // namespace

int main(int argc, char** argv) {
    const bool cpu_only = argc == 2 && std::string(argv[1]) == "--cpu-only";
    if (argc > 2 || (argc == 2 && !cpu_only)) {
        std::fprintf(stderr, "usage: framegraph_bench [--cpu-only]\n");
        return 1;
    }
    const int runs = 201;
    const double declare_ms = median_ms(runs, [] {
        fg::FrameGraph graph;
        declare_thirty_passes(graph);
    });
    const double declare_compile_ms = median_ms(runs, [] {
        fg::FrameGraph graph;
        declare_thirty_passes(graph);
        graph.compile(1920, 1080);
    });
    std::printf("| measurement | median of %d runs |\n| --- | --- |\n", runs);
    std::printf("| declare a 30-pass graph | %.3f ms |\n", declare_ms);
    std::printf("| compile it (culling, order, barriers, aliasing estimate) | %.3f ms |\n",
                declare_compile_ms - declare_ms);

    // Pool's frame, step by step (no device: the passes' lambdas only capture).
    const Scene pool_scene = load_scene(std::string(VKWATER_SOURCE_DIR) + "/scenes/pool.json");
    constexpr uint32_t kWidth = 800, kHeight = 600;
    const double aspect = double(kWidth) / kHeight;
    const double needs_ms = median_ms(runs, [&] { (void)decide_frame_needs(pool_scene, aspect); });
    const double constants_ms = median_ms(runs, [&] { (void)make_frame_constants(pool_scene, kWidth, kHeight); });
    const FrameConstants constants = make_frame_constants(pool_scene, kWidth, kHeight);
    passes::CausticReadRegionCache read_regions;  // as the renderer keeps it while the camera stays
    // `last`: as the renderer does, the last frame's graph, whose compilation the next one takes
    // over (FrameGraph::compile); without it every frame compiles afresh.
    // `spare`: as the renderer does, the graph before the last one, whose storage the next
    // declaration fills again (FrameGraph::clear).
    std::unique_ptr<fg::FrameGraph> last, spare;
    const auto declare_pool = [&](bool compile, bool take_over = true) {
        std::unique_ptr<fg::FrameGraph> graph = std::move(spare);
        if (graph) {
            graph->clear();
        } else {
            graph = std::make_unique<fg::FrameGraph>();
        }
        decide_frame_needs(pool_scene, aspect, graph->needs_to_decide());
        build_frame_graph(*graph, pool_scene, &constants, kWidth, kHeight, VK_NULL_HANDLE, nullptr, nullptr, nullptr,
                          {}, &read_regions);
        if (compile) {
            graph->compile(kWidth, kHeight, take_over ? last.get() : nullptr);
            std::swap(last, graph);
        }
        if (graph) graph->clear();
        spare = std::move(graph);
    };
    const double pool_declare_ms = median_ms(runs, [&] { declare_pool(false); });
    const double pool_fresh_ms = median_ms(runs, [&] { declare_pool(true, false); });
    const double pool_compile_ms = median_ms(runs, [&] { declare_pool(true); });
    std::printf("| pool at 800x600: decide the needs | %.3f ms |\n", needs_ms);
    std::printf("| pool: the frame constants | %.3f ms |\n", constants_ms);
    std::printf("| pool: declare its graph (the needs included) | %.3f ms |\n", pool_declare_ms);
    std::printf("| pool: compile it afresh | %.3f ms |\n", pool_fresh_ms - pool_declare_ms);
    // The compilation taken over costs less than the noise of the declaration's median: the sum.
    std::printf("| pool: declare and compile it, taking the last frame's compilation over | %.3f ms |\n",
                pool_compile_ms);
    // The warm loop above leaves `spare` as the renderer's frames do: the next declaration fills it.
    const size_t allocations_before = heap_allocations.load();
    declare_pool(true);
    const size_t recycled_allocations = heap_allocations.load() - allocations_before;
    spare.reset();
    declare_pool(true);
    const size_t fresh_allocations = heap_allocations.load() - allocations_before - recycled_allocations;
    std::printf("| pool: heap allocations of one such frame, declared into a new graph | %zu |\n", fresh_allocations);
    std::printf("| pool: the same, declared into the storage of the graph before the last | %zu |\n",
                recycled_allocations);
    fg::FrameNeeds last_needs = decide_frame_needs(pool_scene, aspect);
    const size_t before_needs = heap_allocations.load();
    decide_frame_needs(pool_scene, aspect, last_needs);
    std::printf("| pool: heap allocations of its needs alone, decided into the last frame's | %zu |\n",
                heap_allocations.load() - before_needs);
    if (cpu_only) return 0;

    Context context(ContextOptions{});
    VkCommandPool pool;
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = context.queue_family();
    VKW_CHECK(vkCreateCommandPool(context.device(), &pool_info, nullptr, &pool), "bench pool");
    {
        HandWrittenChain hand(context);
        Buffer readback(context, {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "graph readback");
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        passes::add_readback_pass(graph, chain::add_chain(graph), readback.handle(), kBytes);
        graph.compile(kSize, kSize);
        fg::FrameExecutor executor(context, graph, pipelines, {.timing = fg::TimingMode::None});
        const double by_hand = median_record_ms(context, pool, runs, [&](VkCommandBuffer cmd) { hand.record(cmd); });
        const double by_graph =
            median_record_ms(context, pool, runs, [&](VkCommandBuffer cmd) { executor.record(cmd); });
        const size_t passes = graph.compiled().order.size();
        std::printf("| record the chain by hand (%zu passes) | %.4f ms |\n", passes, by_hand);
        std::printf("| record it through the frame graph | %.4f ms |\n", by_graph);
        std::printf("| graph overhead per pass | %.4f ms |\n", (by_graph - by_hand) / double(passes));
        std::printf("device: %s\n", context.device_name().c_str());
    }
    {
        // The same through the renderer, whose figure `vkwater render` prints (it also finds its
        // cached device objects, its readback targets and the calibration pass): frames of 64x48,
        // the first five left out (they create).
        Renderer renderer(context);
        std::vector<double> times;
        for (int frame = 0; frame < 25; ++frame) {
            renderer.render(pool_scene, {64, 48, false, fg::TimingMode::Fences});
            if (frame >= 5) times.push_back(renderer.last_declare_ms());
        }
        std::printf("| pool through the renderer: needs, declaration, compilation | %.3f ms |\n", median(times));
        // Whether the renderer's figure is the caches or the code: pool's needs, declaration and
        // compilation timed right after an 800x600 frame that llvmpipe's threads rendered, then the
        // same again at once, in the same process.
        // Each step also alone right after its own frame, to see which of them the cold caches slow.
        std::vector<double> after_frame, again, needs_after_frame, declaration_after_frame;
        fg::FrameNeeds needs_storage = decide_frame_needs(pool_scene, aspect);
        for (int frame = 0; frame < 27; ++frame) {
            renderer.render(pool_scene, {kWidth, kHeight, false, fg::TimingMode::None});
            if (frame < 3) continue;  // it creates
            switch (frame % 3) {
                case 0:
                    after_frame.push_back(median_ms(1, [&] { declare_pool(true); }));
                    again.push_back(median_ms(1, [&] { declare_pool(true); }));
                    break;
                case 1:
                    needs_after_frame.push_back(
                        median_ms(1, [&] { decide_frame_needs(pool_scene, aspect, needs_storage); }));
                    break;
                case 2: declaration_after_frame.push_back(median_ms(1, [&] { declare_pool(false); })); break;
            }
        }
        std::printf("| pool's needs, declaration, compilation right after an 800x600 frame | %.3f ms |\n",
                    median(after_frame));
        std::printf("| the same again at once | %.3f ms |\n", median(again));
        std::printf("| pool's needs alone right after an 800x600 frame | %.3f ms |\n", median(needs_after_frame));
        std::printf("| pool's needs and declaration (no compilation) right after an 800x600 frame | %.3f ms |\n",
                    median(declaration_after_frame));
    }
    vkDestroyCommandPool(context.device(), pool, nullptr);
    return 0;
}
