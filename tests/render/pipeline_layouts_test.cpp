// Every pipeline of every built-in scene's frame graph gets its layout from its shaders' SPIR-V
// (engine/vk/spirv_reflection.hpp), and its pass binds descriptors of the layout's types and pushes
// exactly its constant block (engine/framegraph/pass_context.cpp): each scene renders one 64x48 frame as it is, and with every
// effect forced on (with and without the underwater view's per-pixel medium) in the variants that
// pick other shaders (camera-space splats, marched godrays), most also with the caustic layer; on
// pool also each splat kernel, procedural caustics, screen-space lookups, the other Fresnel forms
// with the depth colour, and render-pass recording. A failure here names the pass and the binding
// or the sizes that disagree. The figures of the process (pipelines checked,
// declared bindings no stage uses, stages without a push block) are printed at its end.
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/spirv_reflection.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>

namespace vkw::test {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes";

std::vector<std::string> builtin_scenes() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Every effect on; flat water's photon passes too (the flat stand-in would leave them out). The
// grids shrink: the pipelines do not depend on them, and pool's 1024^2 photons cost seconds.
std::vector<std::string> effects_on(bool underwater_view, std::vector<std::string> more = {}) {
    std::vector<std::string> overrides = {"water.grid_resolution=16", "effects.godrays.grid=8",
                                          "effects.caustics.analytic_flat=false"};
    for (const Effect effect : kAllEffects) {
        if (effect == Effect::UnderwaterView && !underwater_view) continue;  // the per-frame medium's variants
        overrides.push_back(std::string("effects.") + effect_name(effect) + ".mode=on");
    }
    overrides.insert(overrides.end(), more.begin(), more.end());
    return overrides;
}

class PipelineLayouts : public GpuTest {
protected:
    void render(const std::string& scene, const std::vector<std::string>& overrides, RenderOptions options = {}) {
        options.width = 64;
        options.height = 48;
        options.check_finite = true;
        options.timing = fg::TimingMode::None;
        std::string what = scene;
        for (const std::string& o : overrides) what += " " + o;
        if (options.caustic_layer) what += " (caustic layer)";
        if (options.recording == fg::RecordingKind::RenderPassObject) what += " (render-pass recording)";
        SCOPED_TRACE(what);
        Renderer renderer(context());
        try {
            renderer.render(load_scene(kScenes / scene, overrides), options);
        } catch (const std::exception& e) {
            ADD_FAILURE() << e.what();
        }
        EXPECT_GT(renderer.pipelines().size(), 0u);
    }
};

class BuiltinScenePipelines : public PipelineLayouts, public ::testing::WithParamInterface<std::string> {};

TEST_P(BuiltinScenePipelines, AsIsAndWithEveryEffectOn) {
    RenderOptions layer;
    layer.caustic_layer = true;
    for (const RenderOptions& options : {RenderOptions{}, layer}) {
        render(GetParam(), {}, options);
        for (const bool underwater_view : {true, false}) {
            render(GetParam(), effects_on(underwater_view), options);
            render(GetParam(), effects_on(underwater_view, {"effects.caustics.splat=camera-space"}), options);
        }
    }
    // The godray passes do not draw into the caustic layer: once is enough.
    render(GetParam(), effects_on(true, {"effects.godrays.method=marched"}));
}

INSTANTIATE_TEST_SUITE_P(Scenes, BuiltinScenePipelines, ::testing::ValuesIn(builtin_scenes()),
                         [](const auto& param_info) { return param_info.param.substr(0, param_info.param.find('.')); });

TEST_F(PipelineLayouts, PoolShaderVariants) {
    for (const char* kernel : {"bilinear", "adaptive", "footprint"}) {
        render("pool.json", effects_on(true, {std::string("effects.caustics.kernel=") + kernel}));
    }
    render("pool.json", effects_on(true, {"effects.caustics.method=procedural"}));
    render("pool.json",
           effects_on(true, {"effects.reflection.method=screen_space", "effects.refraction.method=screen_space"}));
    render("pool.json", effects_on(true, {"effects.water.fresnel=schlick", "effects.water.depth_blend={}",
                                          "effects.water.glitter=true"}));
    RenderOptions render_pass;
    render_pass.recording = fg::RecordingKind::RenderPassObject;
    render("pool.json", {}, render_pass);
    render("pool.json", effects_on(true), render_pass);
    render("pool.json", effects_on(true, {"effects.caustics.splat=camera-space", "effects.godrays.method=marched"}),
           render_pass);
}

// The figures of what this process checked, printed once at its end: how many pipelines and
// shaders, the declared bindings no stage uses, and the stages whose push-constant block is
// shorter than the layout's range (or absent); each of the last two is listed.
class Figures : public ::testing::Environment {
public:
    void TearDown() override {
        const std::vector<LayoutCheckRecord> records = layout_check_records();
        size_t unused = 0, shorter = 0, without = 0;
        std::set<std::string> shaders;
        std::string listed;
        for (const LayoutCheckRecord& r : records) {
            unused += r.unused.size();
            for (const VkDescriptorSetLayoutBinding& b : r.unused) {
                listed += "  " + r.pass + ": binding " + std::to_string(b.binding) + " (" +
                          descriptor_type_name(b.descriptorType) + ") declared, used by no stage\n";
            }
            for (size_t i = 0; i < r.shaders.size(); ++i) {
                shaders.insert(r.shaders[i]);
                if (r.shader_push_bytes[i] >= r.declared_push_bytes) continue;
                ++(r.shader_push_bytes[i] == 0 ? without : shorter);
                listed += "  " + r.pass + ": " + r.shaders[i] + " declares " + std::to_string(r.shader_push_bytes[i]) +
                          " of the " + std::to_string(r.declared_push_bytes) + " push-constant bytes\n";
            }
        }
        std::cout << "layout check: " << records.size() << " pipelines, " << shaders.size() << " shaders; " << unused
                  << " declared bindings used by no stage; " << shorter << " stages with a shorter push block, "
                  << without << " with none, in a layout with one\n"
                  << listed;
    }
};
::testing::Environment* const kFigures = ::testing::AddGlobalTestEnvironment(new Figures);

}  // namespace
}  // namespace vkw::test
