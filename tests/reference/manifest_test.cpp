// The committed references (tests/references/, point-sampled, and tests/references/box/,
// box-filtered) are data: each must have been rendered from the scene file as it is now (a
// changed scene demands a regenerated reference), have the recorded size and the caustic layer,
// and be reproduced by the reference renderer today; the box set also records its filter and
// its estimated error.
#include "engine/image/exr_io.hpp"
#include "engine/scene/pixel_filter.hpp"
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
// The box-filtered set (16 samples per pixel, caustics over each stratum's footprint), beside
// the point-sampled one.
const std::filesystem::path kBoxReferences = kReferences / "box";
// The showcase scenes' references (scenes/showcase/), point-sampled.
const std::filesystem::path kShowcaseReferences = kReferences / "showcase";
const std::filesystem::path kScenes = kReferences / "../../scenes";

nlohmann::json manifest(const std::filesystem::path& folder = kReferences) {
    std::ifstream in(folder / "manifest.json");
    return nlohmann::json::parse(in);
}

// `spp`: the samples per pixel the entry records (the showcase ocean's glitter path needs 16).
std::string regenerate_hint(const std::filesystem::path& folder, const std::string& name, int64_t spp = 1) {
    const std::string stem = std::filesystem::path(name).stem().string();
    if (folder == kBoxReferences) return "tools/reference/make_box_references.sh " + stem;
    if (folder == kShowcaseReferences) {
        return "vkwater reference scenes/showcase/" + name + " --cells-per-wavelength 64" +
               (spp > 1 ? " --spp " + std::to_string(spp) : std::string()) + " --out tests/references/showcase/" +
               stem + ".exr --manifest tests/references/showcase/manifest.json";
    }
    return "vkwater reference scenes/" + name + " --out tests/references/" + stem +
           ".exr --manifest tests/references/manifest.json";
}

void expect_entries_match_scene_files_and_images(const std::filesystem::path& folder) {
    const nlohmann::json entries = manifest(folder);
    ASSERT_FALSE(entries.empty());
    for (const auto& [name, entry] : entries.items()) {
        SCOPED_TRACE(name);
        const std::filesystem::path scene = folder / entry["scene"].get<std::string>();
        EXPECT_EQ(scene_file_hash(scene), entry["scene_hash"].get<std::string>())
            << scene << " changed since its reference was rendered; regenerate it with\n  "
            << regenerate_hint(folder, name, entry["samples_per_pixel"].get<int64_t>());
        const ImageRGBA32F image = read_exr(folder / entry["reference"].get<std::string>());
        EXPECT_EQ(image.width, entry["width"].get<int>());
        EXPECT_EQ(image.height, entry["height"].get<int>());
        ASSERT_EQ(image.layers.size(), 2u);
        EXPECT_EQ(image.layers[0].name, "caustic");
        EXPECT_EQ(image.layers[1].name, "inscatter");
    }
}

void expect_every_built_in_scene(const std::filesystem::path& folder,
                                 const std::filesystem::path& scenes_folder = kScenes) {
    // A 400x300 reference of every built-in scene (scenes/*.json, or scenes/showcase/*.json).
    const nlohmann::json entries = manifest(folder);
    int scenes = 0;
    for (const auto& file : std::filesystem::directory_iterator(scenes_folder)) {
        if (file.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = file.path().filename().string();
        EXPECT_TRUE(entries.contains(name))
            << name << " has no reference; render it with\n  " << regenerate_hint(folder, name);
    }
    EXPECT_GT(scenes, 0);
}

// References that took long (wavy water's refined caustics: tens of seconds) are checked by
// their scene hash, not re-rendered on every CI run; the others are rendered again with the
// settings their entry records.
void expect_quick_entries_reproduced(const std::filesystem::path& folder) {
    const nlohmann::json entries = manifest(folder);  // items() must not outlive the json it walks
    for (const auto& [name, entry] : entries.items()) {
        SCOPED_TRACE(name);
        if (entry["seconds"].get<double>() > 5.0) continue;
        const std::filesystem::path scene_file = folder / entry["scene"].get<std::string>();
        const Scene scene = load_scene(scene_file, entry["overrides"].get<std::vector<std::string>>());
        ReferenceOptions options;
        options.width = entry["width"];
        options.height = entry["height"];
        options.filter = pixel_filter_from_spp(entry["samples_per_pixel"].get<int64_t>());
        // As `vkwater reference` sets them (older entries lack the later fields: their defaults).
        const WaterTransport::Quality defaults;
        options.quality.caustic_in_scatter = true;
        options.quality.cells_per_wavelength = entry.value("cells_per_wavelength", defaults.cells_per_wavelength);
        options.quality.in_scatter_levels = entry.value("in_scatter_planes", defaults.in_scatter_levels);
        options.quality.in_scatter_texels = entry.value("in_scatter_texels", defaults.in_scatter_texels);
        options.quality.floor_texels = entry.value("floor_texels", defaults.floor_texels);
        options.quality.ocean_floor_texels = entry.value("floor_texels", defaults.ocean_floor_texels);
        options.quality.caustics_over_footprints = entry.value("footprint_caustics", false);
        const ImageRGBA32F committed = read_exr(folder / entry["reference"].get<std::string>());
        const ImageRGBA32F today = render_reference(scene, options);
        // Deterministic on one machine; across C libraries exp/pow may differ in the last
        // bit of a double, far below the fp32 the file stores: equal to fp32 rounding.
        const double rel_mse = metrics::rel_mse(metrics::rgb_view(today), metrics::rgb_view(committed),
                                                metrics::counted_pixels(options.width, options.height, nullptr));
        EXPECT_LT(rel_mse, 1e-12);
    }
}

TEST(reference_manifest, EveryEntryMatchesItsSceneFileAndImage) {
    expect_entries_match_scene_files_and_images(kReferences);
}

TEST(reference_manifest, EveryBuiltInSceneHasAReference) { expect_every_built_in_scene(kReferences); }

TEST(reference_manifest, TheReferenceRendererReproducesEveryCommittedImage) {
    expect_quick_entries_reproduced(kReferences);
}

TEST(showcase_reference_manifest, EveryEntryMatchesItsSceneFileAndImage) {
    expect_entries_match_scene_files_and_images(kShowcaseReferences);
}

TEST(showcase_reference_manifest, EveryShowcaseSceneHasAReference) {
    expect_every_built_in_scene(kShowcaseReferences, kScenes / "showcase");
}

TEST(box_reference_manifest, EveryEntryMatchesItsSceneFileAndImage) {
    expect_entries_match_scene_files_and_images(kBoxReferences);
}

TEST(box_reference_manifest, EveryBuiltInSceneHasAReference) { expect_every_built_in_scene(kBoxReferences); }

TEST(box_reference_manifest, TheReferenceRendererReproducesEveryQuickImage) {
    expect_quick_entries_reproduced(kBoxReferences);
}

TEST(box_reference_manifest, EveryImageIsBoxFilteredAndMeasured) {
    // 4 x 4 strata per pixel, as the header says; the caustics averaged over each stratum's own
    // footprint, or (the FFT ocean) over a map's texels; the caustics one level coarser and the
    // filter at 4 samples measured, and the estimate at least their sum.
    const nlohmann::json entries = manifest(kBoxReferences);
    for (const auto& [name, entry] : entries.items()) {
        SCOPED_TRACE(name);
        EXPECT_EQ(entry["samples_per_pixel"].get<int>(), 16);
        std::string filter = "(missing)";
        for (const ImageAttribute& a : read_exr(kBoxReferences / entry["reference"].get<std::string>()).attributes) {
            if (a.name == "vkwater/filter") filter = a.value;
        }
        EXPECT_EQ(filter, "box: 16 samples per pixel (4 x 4 strata)");
        ASSERT_TRUE(entry.contains("texels") && entry.contains("filter_change"));
        if (!entry["footprint_caustics"].get<bool>()) {
            // A texel map (the FFT ocean) cannot be a quarter of every pixel's footprint (they
            // tend to 0 where the view rays focus); what it must be is fine enough that its own
            // share of the error, the caustics' change one texel coarser, stays below the
            // filter's (the caustics' change from 4 to 16 samples per pixel).
            EXPECT_LT(entry["texels"]["caustic_coarser_change_rel_mse"].get<double>(),
                      entry["filter_change"]["caustic_rel_mse"].get<double>());
        }
        const double parts = entry["texels"]["caustic_coarser_change_rel_mse"].get<double>() +
                             entry["filter_change"]["rel_mse"].get<double>();
        EXPECT_GE(entry["estimated_rel_mse"].get<double>(), parts);
    }
}

}  // namespace
}  // namespace vkw::ref
