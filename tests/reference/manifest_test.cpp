// The committed references (tests/references/) are data: each must have been rendered
// from the scene file as it is now (a changed scene demands a regenerated reference),
// have the recorded size and the caustic layer, and be reproduced by the reference
// renderer today.
#include "engine/image/exr_io.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/reference_renderer.hpp"
#include "tools/reference/scene_hash.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace vkw::ref {
namespace {

const std::filesystem::path kReferences = std::filesystem::path(VKWATER_SOURCE_DIR) / "tests/references";

nlohmann::json manifest() {
    std::ifstream in(kReferences / "manifest.json");
    return nlohmann::json::parse(in);
}

TEST(reference_manifest, EveryEntryMatchesItsSceneFileAndImage) {
    const nlohmann::json entries = manifest();
    ASSERT_FALSE(entries.empty());
    for (const auto& [name, entry] : entries.items()) {
        SCOPED_TRACE(name);
        const std::filesystem::path scene = kReferences / entry["scene"].get<std::string>();
        EXPECT_EQ(scene_file_hash(scene), entry["scene_hash"].get<std::string>())
            << scene << " changed since its reference was rendered; regenerate it with\n  vkwater reference "
            << "scenes/" << name << " --out tests/references/" << entry["reference"].get<std::string>()
            << " --manifest tests/references/manifest.json";
        const ImageRGBA32F image = read_exr(kReferences / entry["reference"].get<std::string>());
        EXPECT_EQ(image.width, entry["width"].get<int>());
        EXPECT_EQ(image.height, entry["height"].get<int>());
        ASSERT_EQ(image.layers.size(), 2u);
        EXPECT_EQ(image.layers[0].name, "caustic");
        EXPECT_EQ(image.layers[1].name, "inscatter");
    }
}

TEST(reference_manifest, EveryBuiltInSceneHasAReference) {
    // A 400x300 reference of every built-in scene (scenes/*.json).
    const nlohmann::json entries = manifest();
    int scenes = 0;
    for (const auto& file : std::filesystem::directory_iterator(kReferences / "../../scenes")) {
        if (file.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = file.path().filename().string();
        EXPECT_TRUE(entries.contains(name))
            << name << " has no reference; render it with\n  vkwater reference scenes/" << name
            << " --out tests/references/" << file.path().stem().string() << ".exr --manifest "
            << "tests/references/manifest.json";
    }
    EXPECT_GT(scenes, 0);
}

TEST(reference_manifest, TheReferenceRendererReproducesEveryCommittedImage) {
    const nlohmann::json entries = manifest();  // items() must not outlive the json it walks
    for (const auto& [name, entry] : entries.items()) {
        SCOPED_TRACE(name);
        // References that took long (wavy water's refined caustics: tens of seconds) are
        // checked by their scene hash above, not re-rendered on every CI run.
        if (entry["seconds"].get<double>() > 5.0) continue;
        const std::filesystem::path scene_file = kReferences / entry["scene"].get<std::string>();
        const Scene scene = load_scene(scene_file, entry["overrides"].get<std::vector<std::string>>());
        const uint32_t width = entry["width"], height = entry["height"];
        const ImageRGBA32F committed = read_exr(kReferences / entry["reference"].get<std::string>());
        const ImageRGBA32F today = render_reference(scene, {width, height, 0, {}});
        // Deterministic on one machine; across C libraries exp/pow may differ in the last
        // bit of a double, far below the fp32 the file stores: equal to fp32 rounding.
        const double rel_mse = metrics::rel_mse(metrics::rgb_view(today), metrics::rgb_view(committed),
                                                metrics::counted_pixels(width, height, nullptr));
        EXPECT_LT(rel_mse, 1e-12);
    }
}

}  // namespace
}  // namespace vkw::ref
