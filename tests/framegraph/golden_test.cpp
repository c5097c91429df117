// Golden text dumps of two mock water frames (about a dozen passes each, with culled
// passes): FrameGraph::dump_barriers() followed by describe(), compared with
// tests/framegraph/golden/<name>.txt.
//
// To regenerate after an intended change, run the tests with VKWATER_UPDATE_GOLDEN=1:
//   VKWATER_UPDATE_GOLDEN=1 ./build/tests/framegraph/test_framegraph --gtest_filter='framegraph_golden*'
// then read the diff of golden/ before committing it.
#include "tests/framegraph/framegraph_test_support.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace vkw::fg::test {
namespace {

const std::filesystem::path kGoldenDir = std::filesystem::path(VKWATER_SOURCE_DIR) / "tests/framegraph/golden";

ImageInfo half_res(VkFormat format) { return {format, SizeClass::OutputRelative, 0.5f}; }
ImageInfo full_res(VkFormat format) { return {format, SizeClass::OutputRelative, 1.0f}; }

// The passes both frames share: constants uploaded by a copy, then a compute surface.
struct Common {
    BufferHandle constants, surface;
};

Common add_constants_and_surface(FrameGraph& graph) {
    Common common;
    add_pass(graph, "upload_constants", PassKind::Transfer, [&](PassBuilder& builder) {
        common.constants = builder.copy_destination(builder.create_buffer("constants", {256}));
    });
    add_pass(graph, "surface_sim", PassKind::Compute, [&](PassBuilder& builder) {
        builder.uniform_buffer(common.constants);
        common.surface = builder.write_storage(builder.create_buffer("surface", {128 * 128 * 16}));
    });
    return common;
}

// Above water, every effect on; a debug pass nobody reads and godrays (not needed from
// above) are culled. The frame ends in a copy to a readback buffer.
void build_water_frame(FrameGraph& graph) {
    const BufferHandle readback = graph.import_buffer("readback", readback_buffer(256 * 256 * 4));
    const Common common = add_constants_and_surface(graph);
    ImageHandle light_position, light_depth, caustics, blurred, hdr, depth, ldr;
    BufferHandle photons;
    add_pass(graph, "light_maps", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.uniform_buffer(common.constants, kVertexShader);
        builder.vertex_buffer(common.surface);
        light_position = builder.color_attachment(builder.create_image("light_position", small_image()));
        light_depth =
            builder.depth_stencil_attachment(builder.create_image("light_depth", small_image(VK_FORMAT_D32_SFLOAT)));
    });
    add_pass(graph, "photon_trace", PassKind::Compute, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.read_storage(common.surface);
        builder.sample(light_position);
        photons = builder.write_storage(builder.create_buffer("photons", {64 * 64 * 32}));
    });
    add_pass(graph, "debug_normals", PassKind::Compute, [&](PassBuilder& builder) {
        builder.read_storage(common.surface);
        (void)builder.write_storage(builder.create_image("normals_debug", small_image()));
    });
    add_pass(graph, "caustic_splat", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.vertex_buffer(photons);
        caustics = builder.color_attachment(builder.create_image("caustics", half_res(VK_FORMAT_R16_SFLOAT)));
    });
    add_pass(graph, "godrays", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        builder.vertex_buffer(photons);
        (void)builder.color_attachment(builder.create_image("godray_lines", half_res(VK_FORMAT_R16_SFLOAT)));
    });
    add_pass(graph, "caustic_blur", PassKind::Compute, [&](PassBuilder& builder) {
        builder.serves(Effect::CausticBlur);
        builder.sample(caustics);
        blurred = builder.write_storage(builder.create_image("caustics_blurred", half_res(VK_FORMAT_R16_SFLOAT)));
    });
    add_pass(graph, "receivers", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.uniform_buffer(common.constants, kVertexShader | kFragment);
        builder.sample(blurred);
        builder.sample(light_depth);
        hdr = builder.color_attachment(builder.create_image("hdr", full_res(VK_FORMAT_R16G16B16A16_SFLOAT)));
        depth = builder.depth_stencil_attachment(builder.create_image("depth", full_res(VK_FORMAT_D32_SFLOAT)));
    });
    add_pass(graph, "water", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::Water);
        builder.uniform_buffer(common.constants, kVertexShader | kFragment);
        builder.vertex_buffer(common.surface);
        hdr = builder.color_attachment(hdr, LoadOp::Load);
        depth = builder.depth_stencil_attachment(depth, LoadOp::Load);
    });
    add_pass(graph, "composite", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.sample(hdr);
        ldr = builder.color_attachment(builder.create_image("ldr", full_res(VK_FORMAT_R8G8B8A8_UNORM)));
    });
    add_pass(graph, "readback", PassKind::Transfer, [&](PassBuilder& builder) {
        builder.copy_source(ldr);
        graph.request_output(builder.copy_destination(readback));
    });
}

// From below the water: camera-medium split, godrays on, blur off by rule, reflection forced
// off. Composite writes an imported swapchain image handed back for presenting.
void build_underwater_frame(FrameGraph& graph) {
    const ImageHandle swapchain =
        graph.import_image("swapchain", ImportedImage{VK_NULL_HANDLE,
                                                      VK_NULL_HANDLE,
                                                      256,
                                                      256,
                                                      VK_FORMAT_R8G8B8A8_UNORM,
                                                      {},
                                                      AccessState{kNone, kNoAccess, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR}});
    const Common common = add_constants_and_surface(graph);
    ImageHandle stencil, caustics, hdr, out;
    BufferHandle photons;
    add_pass(graph, "stencil_split", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::UnderwaterView);
        builder.vertex_buffer(common.surface);
        stencil = builder.depth_stencil_attachment(
            builder.create_image("depth_stencil", full_res(VK_FORMAT_D24_UNORM_S8_UINT)));
    });
    add_pass(graph, "reflection", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::Reflection);
        builder.uniform_buffer(common.constants, kVertexShader);
        (void)builder.color_attachment(builder.create_image("reflection", half_res(VK_FORMAT_R16G16B16A16_SFLOAT)));
    });
    add_pass(graph, "photon_trace", PassKind::Compute, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.read_storage(common.surface);
        photons = builder.write_storage(builder.create_buffer("photons", {64 * 64 * 32}));
    });
    add_pass(graph, "caustic_splat", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.vertex_buffer(photons);
        caustics = builder.color_attachment(builder.create_image("caustics", half_res(VK_FORMAT_R16_SFLOAT)));
    });
    add_pass(graph, "caustic_blur", PassKind::Compute, [&](PassBuilder& builder) {
        builder.serves(Effect::CausticBlur);
        builder.sample(caustics);
        (void)builder.write_storage(builder.create_image("caustics_blurred", half_res(VK_FORMAT_R16_SFLOAT)));
    });
    add_pass(graph, "receivers", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.sample(caustics);
        builder.depth_stencil_read_only(stencil);
        hdr = builder.color_attachment(builder.create_image("hdr", full_res(VK_FORMAT_R16G16B16A16_SFLOAT)));
    });
    add_pass(graph, "godrays", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        builder.vertex_buffer(photons);
        builder.depth_stencil_read_only(stencil);
        hdr = builder.color_attachment(hdr, LoadOp::Load);
    });
    add_pass(graph, "water", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::Water);
        builder.uniform_buffer(common.constants, kVertexShader | kFragment);
        builder.vertex_buffer(common.surface);
        hdr = builder.color_attachment(hdr, LoadOp::Load);
        stencil = builder.depth_stencil_attachment(stencil, LoadOp::Load);
    });
    add_pass(graph, "composite", PassKind::Compute, [&](PassBuilder& builder) {
        builder.sample(hdr);
        out = builder.write_storage(swapchain);
    });
    graph.request_output(out);
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// Compiles, dumps and compares with (or, with VKWATER_UPDATE_GOLDEN=1, rewrites) the golden file.
void check_golden(FrameGraph& graph, const std::string& name) {
    graph.compile(256, 256);
    const std::string dump = "barriers:\n" + graph.dump_barriers() + graph.describe();
    const std::filesystem::path path = kGoldenDir / (name + ".txt");
    const char* update = std::getenv("VKWATER_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        std::filesystem::create_directories(kGoldenDir);
        std::ofstream(path, std::ios::binary) << dump;
        GTEST_SKIP() << "rewrote " << path;
    }
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing; run with VKWATER_UPDATE_GOLDEN=1";
    EXPECT_EQ(dump, read_text(path)) << "differs from " << path << "; if intended, run with VKWATER_UPDATE_GOLDEN=1";
}

TEST(framegraph_golden, WaterFrame) {
    FrameNeeds needs;
    needs.decide(Effect::VolumeCaustics, false, "camera above the water");
    FrameGraph graph(needs);
    build_water_frame(graph);
    check_golden(graph, "water_frame");
}

TEST(framegraph_golden, UnderwaterFrame) {
    FrameNeeds needs;
    needs.decide(Effect::UnderwaterView, true, "camera below the water");
    needs.decide(Effect::CausticBlur, false, "caustic_blur.radius = 0");
    needs.decide(Effect::Reflection, false, "effects.reflection.mode = off", /*forced=*/true);
    FrameGraph graph(needs);
    build_underwater_frame(graph);
    check_golden(graph, "underwater_frame");
}

}  // namespace
}  // namespace vkw::fg::test
