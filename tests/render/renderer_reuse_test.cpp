// The renderer declares and compiles its frame graph every frame and keeps the device objects
// while the compiled graph's physical signature holds: a new camera, a running water clock or a
// moved slider (sun, wave amplitude) reach the image and make no pipeline and allocate no memory;
// a new output size makes new objects, and no pipeline is ever created twice.
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/resources.hpp"
#include "passes/common/whole_image_copy.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/render/overhead_scene.hpp"
#include "tests/support/gpu_test.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace vkw::test {
namespace {

using RendererReuse = GpuTest;

TEST_F(RendererReuse, KeepsItsDeviceObjectsWhileTheSignatureHolds) {
    Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    Renderer renderer(context());
    const RenderOptions options{64, 48, true, fg::TimingMode::None};
    const RenderResult first = renderer.render(scene, options);
    const size_t pipelines_after_first = renderer.pipelines().size();
    const Context::CreationCounts after_first = context().creation_counts();
    EXPECT_EQ(renderer.realize_count(), 1u);
    EXPECT_GT(after_first.pipelines, 0u);
    EXPECT_GT(after_first.memory_allocations, 0u);

    scene.camera.target.y += 2.0;  // look up: more sky, less floor
    const RenderResult second = renderer.render(scene, options);
    EXPECT_NE(first.image.rgba, second.image.rgba) << "the new camera did not reach the shaders";

    // The water's clock runs for ten frames, the sun and a wave's amplitude move: every frame
    // is declared anew (its passes capture the new values) and runs on the same objects.
    std::vector<float> previous = second.image.rgba;
    for (int frame = 0; frame < 10; ++frame) {
        scene.water->time += 1.0 / 30.0;
        const bool clock_alone = frame != 4 && frame != 7;
        if (frame == 4) scene.water->waves.components[0].amplitude *= 1.5;
        if (frame == 7) scene.sun.direction = glm::normalize(scene.sun.direction + glm::dvec3(0.05, 0.0, 0.0));
        const size_t taken_over = renderer.compilations_taken_over();
        const RenderResult moving = renderer.render(scene, options);
        EXPECT_NE(moving.image.rgba, previous) << "frame " << frame << ": the change did not reach the image";
        // The clock changes what the passes capture, not what they declare: the last frame's
        // compiled graph is taken over, not derived again.
        if (clock_alone) {
            EXPECT_EQ(renderer.compilations_taken_over(), taken_over + 1)
                << "frame " << frame << ": the clock alone compiled the graph again";
        }
        previous = moving.image.rgba;
    }
    EXPECT_EQ(renderer.realize_count(), 1u);
    EXPECT_EQ(renderer.pipelines().size(), pipelines_after_first);
    EXPECT_EQ(context().creation_counts().pipelines, after_first.pipelines) << "a running frame made a pipeline";
    EXPECT_EQ(context().creation_counts().memory_allocations, after_first.memory_allocations)
        << "a running frame allocated memory";

    renderer.render(scene, {32, 24, true, fg::TimingMode::None});
    EXPECT_EQ(renderer.realize_count(), 2u);
    EXPECT_EQ(renderer.pipelines().size(), pipelines_after_first);
    EXPECT_GT(context().creation_counts().memory_allocations, after_first.memory_allocations)
        << "a new output size needs new targets";
}

// A frame declared anew is the same frame: the image of a renderer that has run other frames
// before (and took its compiled graph over) equals a fresh renderer's, bit for bit. So does the
// third frame's, declared into the storage of the first frame's graph (FrameGraph::clear).
TEST_F(RendererReuse, AnAdoptedGraphRendersWhatAFreshOneRenders) {
    Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    const RenderOptions options{64, 48, true, fg::TimingMode::None};
    Renderer warm(context());
    scene.water->time = 0.25;
    warm.render(scene, options);
    for (const double time : {0.5, 0.75}) {
        scene.water->time = time;
        const RenderResult adopted = warm.render(scene, options);
        EXPECT_EQ(warm.realize_count(), 1u);
        EXPECT_EQ(warm.compilations_taken_over(), time == 0.5 ? 1u : 2u) << "the graph was compiled again";

        Renderer fresh(context());
        const RenderResult made = fresh.render(scene, options);
        EXPECT_EQ(adopted.image.rgba, made.image.rgba) << "at time " << time;
    }
}

// The photon culling's read region depends on the camera and the waves' bounds, not on their
// clock: frames with a running clock reuse it; a new amplitude or camera computes it again (and
// the previous test shows the reused region's image equal to a fresh renderer's).
TEST_F(RendererReuse, ReusesThePhotonCullingRegionWhileTheCameraStays) {
    Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    Renderer renderer(context());
    const RenderOptions options{64, 48, true, fg::TimingMode::None};
    renderer.render(scene, options);
    EXPECT_EQ(renderer.read_regions_computed(), 1u);
    for (int frame = 0; frame < 3; ++frame) {
        scene.water->time += 1.0 / 30.0;
        renderer.render(scene, options);
    }
    EXPECT_EQ(renderer.read_regions_computed(), 1u) << "the clock alone recomputed the region";
    scene.water->waves.components[0].amplitude *= 1.5;
    renderer.render(scene, options);
    EXPECT_EQ(renderer.read_regions_computed(), 2u) << "a new amplitude bound must recompute it";
    scene.camera.position.x += 0.1;
    renderer.render(scene, options);
    EXPECT_EQ(renderer.read_regions_computed(), 3u) << "a new camera must recompute it";
}

// The receivers' meshes are uploaded once per scene; a scene loaded anew where a freed one lived
// (the same address, the same receiver count) is another scene, and gets its own.
TEST_F(RendererReuse, ASceneLoadedWhereAFreedOneLivedGetsItsOwnReceivers) {
    Renderer renderer(context());
    const RenderOptions options{33, 33, true, fg::TimingMode::None};
    std::optional<Scene> scene;  // one storage for both scenes
    const auto box = [](const char* albedo) {
        return overhead_receiver_scene(
            std::string(R"({"type": "box", "half_size": [1, 1, 1], "albedo": )") + albedo + "}", "box.json");
    };
    scene.emplace(box("[0.8, 0.1, 0.1]"));
    const float red = renderer.render(*scene, options).image.pixel(16, 16)[0];
    scene.emplace(box("[0.1, 0.1, 0.8]"));
    const float blue_scene_red = renderer.render(*scene, options).image.pixel(16, 16)[0];
    // The box top's red is proportional to its albedo's: 0.1 / 0.8 of the first scene's, within the fp32
    // shading's 1e-5 (the receiver tests'); the stale meshes would show the first scene's red again.
    EXPECT_NEAR(blue_scene_red, red / 8.0f, 1e-5f * red);
}

// Renderers given one SceneUploads (the embedding library's frames in flight) upload a scene's
// receiver meshes once between them, and each renders what a renderer of its own renders, bit
// for bit; a new scene load is uploaded once more, for all of them.
TEST_F(RendererReuse, RenderersSharingUploadsUploadTheReceiversOnce) {
    const auto uploads = std::make_shared<SceneUploads>(context());
    Renderer first(context(), nullptr, uploads), second(context(), nullptr, uploads), own(context());
    const RenderOptions options{33, 33, true, fg::TimingMode::None};
    std::optional<Scene> scene;
    // Each scene in turn, a new load each time.
    for (const char* albedo : {"[0.8, 0.1, 0.1]", "[0.1, 0.1, 0.8]"}) {
        scene.emplace(overhead_receiver_scene(
            std::string(R"({"type": "box", "half_size": [1, 1, 1], "albedo": )") + albedo + "}", "box.json"));
        const size_t uploaded = uploads->receiver_uploads();
        const ImageRGBA32F expected = own.render(*scene, options).image;
        EXPECT_EQ(first.render(*scene, options).image.rgba, expected.rgba) << albedo;
        EXPECT_EQ(second.render(*scene, options).image.rgba, expected.rgba) << albedo;
        EXPECT_EQ(uploads->receiver_uploads(), uploaded + 1) << albedo;
    }
}

// The budget draws a terrain with fewer cells by rebuilding its mesh in the same scene
// (set_terrain_detail): the renderer uploads the new mesh, whose image is the one a scene loaded at
// those cells renders, bit for bit, and back at the file's cells the first image again.
TEST_F(RendererReuse, ATerrainDrawnWithFewerCellsIsUploadedAgain) {
    const auto uploads = std::make_shared<SceneUploads>(context());
    Renderer renderer(context(), nullptr, uploads), fresh(context());
    const RenderOptions options{33, 33, true, fg::TimingMode::None};
    const auto terrain = [](int cells) {
        return overhead_receiver_scene(R"({"type": "terrain", "size": 4, "height": 0.5, "seed": 7, "resolution": )" +
                                           std::to_string(cells) + R"(, "translation": [0, 0.5, 0]})",
                                       "terrain.json");
    };
    Scene scene = terrain(64);
    const ImageRGBA32F own = renderer.render(scene, options).image;
    const size_t uploaded = uploads->receiver_uploads();
    set_terrain_detail(scene.receivers[0], 0.25);
    const ImageRGBA32F coarse = renderer.render(scene, options).image;
    EXPECT_EQ(uploads->receiver_uploads(), uploaded + 1);
    EXPECT_EQ(coarse.rgba, fresh.render(terrain(16), options).image.rgba);
    EXPECT_NE(coarse.rgba, own.rgba) << "16 cells of a terrain with 4 waves across it draw other triangles";
    set_terrain_detail(scene.receivers[0], 1.0);
    EXPECT_EQ(renderer.render(scene, options).image.rgba, own.rgba);
    EXPECT_EQ(uploads->receiver_uploads(), uploaded + 2);
}

// A caller that hands each frame to another image of the same size and format (a host's next
// target, the embedding library's) keeps the frame's device objects under dynamic rendering, where
// the executor reads imported images from the graph it runs; a VkRenderPass frame's framebuffers
// name the image's view, so there a new image is a new signature.
TEST_F(RendererReuse, AnotherImportedTargetOfTheSameKindKeepsTheObjectsUnderDynamicRendering) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json");
    const uint32_t width = 32, height = 24;
    const ImageDesc desc{width, height, VK_FORMAT_R32G32B32A32_SFLOAT,
                         VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};  // a view needs a view usage
    const Image targets[2] = {Image(context(), desc, "target a"), Image(context(), desc, "target b")};
    const auto output_into = [&](const Image& target) {
        return FrameOutput{[&target, &desc](fg::FrameGraph& graph, fg::ImageHandle hdr) {
            fg::ImportedImage imported{target.handle(), target.view(), width, height, desc.format};
            imported.final_state = fg::AccessState{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
            passes::add_whole_image_copy_pass(graph, "to the target", hdr, graph.import_image("target", imported));
        }};
    };
    for (const fg::RecordingKind recording :
         {fg::RecordingKind::DynamicRendering, fg::RecordingKind::RenderPassObject}) {
        Renderer renderer(context());
        RenderOptions options{width, height, false, fg::TimingMode::None};
        options.recording = recording;
        for (int frame = 0; frame < 4; ++frame) {
            renderer.prepare_frame(scene, options, output_into(targets[frame % 2])).execute();
        }
        const bool dynamic = recording == fg::RecordingKind::DynamicRendering;
        EXPECT_EQ(renderer.realize_count(), dynamic ? 1u : 4u) << (dynamic ? "dynamic rendering" : "render passes");
    }
}

}  // namespace
}  // namespace vkw::test
