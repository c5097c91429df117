// vkwater render --frames: a sequence's frames, the same bit for bit however the range is split
// (one process, shards, a frame alone), each at its water time, the folder's manifest, re-runs
// that keep what is done, and the refusals of what a sequence cannot be.
#include "engine/image/exr_io.hpp"
#include "tests/cli/cli_support.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace vkw::cli_test {
namespace {

// pool with a coarse photon grid: waves that move, caustics, godrays, at a few hundred ms a frame.
std::string pool_sequence(const std::string& range, const fs::path& folder, const std::string& more = "") {
    return "render " + kPool + " --set water.grid_resolution=64 --width 32 --height 24 --validation --frames " + range +
           " --out " + (folder / "f_%04d.exr").string() + (more.empty() ? "" : " " + more);
}

fs::path fresh_folder(const std::string& name) {
    const fs::path folder = scratch(name);
    fs::remove_all(folder);
    return folder;
}

nlohmann::json read_manifest(const fs::path& folder) {
    std::ifstream in(folder / "manifest.json");
    return nlohmann::json::parse(in);
}

// Pixel data compared value by value, independently of the manifest's hash.
void expect_same_pixels(const fs::path& a, const fs::path& b) {
    const ImageRGBA32F first = read_exr(a);
    const ImageRGBA32F second = read_exr(b);
    ASSERT_EQ(first.width, second.width);
    ASSERT_EQ(first.height, second.height);
    EXPECT_TRUE(first.rgba == second.rgba) << a << " and " << b << " differ";
    ASSERT_EQ(first.layers.size(), second.layers.size());
    for (size_t i = 0; i < first.layers.size(); ++i) {
        EXPECT_EQ(first.layers[i].name, second.layers[i].name);
        EXPECT_TRUE(first.layers[i].rgb == second.layers[i].rgb) << a << " layer " << first.layers[i].name;
    }
}

std::string attribute(const ImageRGBA32F& image, const std::string& name) {
    for (const ImageAttribute& a : image.attributes) {
        if (a.name == name) return a.value;
    }
    return {};
}

TEST(cli, SequenceFramesAreTheSameHoweverTheRangeIsSplit) {
    const fs::path whole = fresh_folder("sequence-whole");
    const fs::path shards = fresh_folder("sequence-shards");
    const fs::path alone = fresh_folder("sequence-alone");
    const CommandRun run = run_vkwater(pool_sequence("0:3", whole));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    // One renderer for the whole sequence: the frame's device objects are made once, not per frame.
    EXPECT_NE(run.output.find("the frame's device objects made 1 time(s)"), std::string::npos) << run.output;
    // Two tasks of an array into one folder, the second first: they share the manifest.
    ASSERT_EQ(run_vkwater(pool_sequence("0:3", shards, "--shard 1/2")).exit_code, 0);
    ASSERT_EQ(run_vkwater(pool_sequence("0:3", shards, "--shard 0/2")).exit_code, 0);
    ASSERT_EQ(run_vkwater(pool_sequence("2:2", alone)).exit_code, 0);

    for (int frame = 0; frame < 4; ++frame) {
        const std::string name = "f_000" + std::to_string(frame) + ".exr";
        expect_same_pixels(whole / name, shards / name);
    }
    expect_same_pixels(whole / "f_0002.exr", alone / "f_0002.exr");

    // The manifests agree frame by frame, and list every frame once, in order.
    const nlohmann::json a = read_manifest(whole);
    const nlohmann::json b = read_manifest(shards);
    ASSERT_EQ(a["frames"].size(), 4u);
    ASSERT_EQ(b["frames"].size(), 4u);
    for (int frame = 0; frame < 4; ++frame) {
        EXPECT_EQ(a["frames"][frame]["frame"], frame);
        EXPECT_EQ(a["frames"][frame]["file"], "f_000" + std::to_string(frame) + ".exr");
        EXPECT_EQ(a["frames"][frame]["pixelHash"], b["frames"][frame]["pixelHash"]);
        EXPECT_EQ(a["frames"][frame]["waterTime"].get<double>(), frame / 24.0);  // water.time is 0 in pool
    }
    EXPECT_EQ(a["sceneHash"], b["sceneHash"]);
    EXPECT_EQ(a["settings"]["width"], 32);
    // The water moves: a sequence of one picture repeated would pass everything above.
    EXPECT_NE(a["frames"][0]["pixelHash"], a["frames"][1]["pixelHash"]);
    EXPECT_FALSE(read_exr(whole / "f_0000.exr").rgba == read_exr(whole / "f_0001.exr").rgba);
}

// Frame f is the scene at water.time + f / fps: frame 3 at 12 fps is a one-frame render at 0.25 s
// (exact in binary, so both paths hand the renderer the same double).
TEST(cli, ASequenceFrameIsTheOneFrameRenderAtItsWaterTime) {
    const fs::path folder = fresh_folder("sequence-time");
    const CommandRun run = run_vkwater(pool_sequence("3:3", folder, "--fps 12"));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const fs::path single = scratch("sequence-time-single.exr");
    const CommandRun one = run_vkwater("render " + kPool +
                                       " --set water.grid_resolution=64 --set water.time=0.25 --width 32 --height 24 "
                                       "--validation --out " +
                                       single.string());
    ASSERT_EQ(one.exit_code, 0) << one.output;
    expect_same_pixels(folder / "f_0003.exr", single);
    const std::string frame = attribute(read_exr(folder / "f_0003.exr"), "vkwater/frame");
    EXPECT_EQ(frame, "3 of 3:3:1 at 12 fps, water.time 0.25 s");
}

// A re-run keeps the frames whose files hold what the manifest records, renders the others (a
// truncated file, a missing one), and leaves the kept files as they were.
TEST(cli, ARerunRendersOnlyTheFramesNotDone) {
    const fs::path folder = fresh_folder("sequence-resume");
    ASSERT_EQ(run_vkwater(pool_sequence("0:3", folder)).exit_code, 0);
    const std::string kept_hash = read_manifest(folder)["frames"][0]["pixelHash"];
    const auto kept_time = fs::last_write_time(folder / "f_0000.exr");
    const nlohmann::json before = read_manifest(folder);
    fs::remove(folder / "f_0001.exr");
    fs::resize_file(folder / "f_0002.exr", 100);
    const CommandRun rerun = run_vkwater(pool_sequence("0:3", folder));
    ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
    EXPECT_NE(rerun.output.find("2 kept (their files match"), std::string::npos) << rerun.output;
    EXPECT_NE(rerun.output.find("2 to render"), std::string::npos) << rerun.output;
    EXPECT_EQ(fs::last_write_time(folder / "f_0000.exr"), kept_time);
    const nlohmann::json after = read_manifest(folder);
    ASSERT_EQ(after["frames"].size(), 4u);
    for (int frame = 0; frame < 4; ++frame) {
        EXPECT_EQ(after["frames"][frame]["pixelHash"], before["frames"][frame]["pixelHash"]) << frame;
    }
    EXPECT_EQ(after["frames"][0]["pixelHash"], kept_hash);
    // Nothing left to do: no device is even made.
    const CommandRun again = run_vkwater(pool_sequence("0:3", folder));
    EXPECT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("4 kept"), std::string::npos) << again.output;
    EXPECT_EQ(again.output.find("device:"), std::string::npos) << again.output;
}

// A folder holds one sequence: other settings are refused before anything is rendered.
TEST(cli, AFolderOfAnotherSequenceIsRefused) {
    const fs::path folder = fresh_folder("sequence-other");
    const std::string calm = std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json";
    const std::string out = (folder / "c_%03d.exr").string();
    ASSERT_EQ(run_vkwater("render " + calm + " --width 16 --height 12 --frames 0:1 --out " + out).exit_code, 0);
    expect_clean_failure(run_vkwater("render " + calm + " --width 20 --height 12 --frames 0:1 --out " + out), 1,
                         "manifest.json': records another sequence: settings.width is 16 (this run: 20)");
    expect_clean_failure(run_vkwater("render " + kPool + " --width 16 --height 12 --frames 0:1 --out " + out), 1,
                         "records another sequence: sceneHash is");
    std::ofstream(folder / "manifest.json") << "{\"frames\": []}";
    expect_clean_failure(run_vkwater("render " + calm + " --width 16 --height 12 --frames 0:1 --out " + out), 1,
                         "not a vkwater sequence manifest");
}

TEST(cli, SequenceOptionsAreCheckedBeforeRendering) {
    const std::string calm = std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json --width 16 --height 12 ";
    const std::string out = " --out " + (scratch("sequence-bad") / "f_%04d.exr").string();
    expect_clean_failure(run_vkwater("render " + calm + "--frames 5:2" + out), 1,
                         "--frames '5:2': the last frame 2 is before the first 5 (accepted: A:B or A:B:STEP");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 1-4" + out), 1, "--frames '1-4': not a frame range");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:4:0" + out), 1, "--frames '0:4:0': a step of 0");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:99999999" + out), 1, "<= 10000000");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --shard 2/2" + out), 1,
                         "--shard '2/2': not a task of an array (accepted: I/N, task I of N, 0 <= I < N");
    expect_clean_failure(run_vkwater("render " + calm + "--shard 0/2" + out), 1, "give --frames too");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --fps 0" + out), 1, "--fps");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --repeat 2" + out), 1, "--repeat");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3"), 1, "give --out with the frame number");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --out x.exr"), 1,
                         "--out 'x.exr': no frame number in the file name");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --out x_%d_%d.exr"), 1, "more than one frame");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --out x_%04d.png"), 1,
                         "a sequence's frames are .exr files");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --out d%d/x_%d.exr"), 1, "in the folder");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --out x_%s.exr"), 1,
                         "a '%' that is neither %d, %0Nd nor %%");
    // Temporal accumulation: a sequence's frames in order, in one process, each at one sample.
    expect_clean_failure(run_vkwater("render " + calm + "--temporal" + out), 1,
                         "--temporal: accumulates over a sequence's frames (accepted: with --frames A:B)");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --temporal --shard 0/2" + out), 1,
                         "--shard '0/2': a temporal sequence's frames depend on the ones before");
    expect_clean_failure(run_vkwater("render " + calm + "--frames 0:3 --temporal --spp 4" + out), 1,
                         "--spp 4: --temporal jitters its frames within the pixel itself (accepted: --spp 1 with it)");
}

// A temporal sequence renders every frame again, in order: a kept frame would not hold the
// history the next one needs.
TEST(cli, ATemporalSequenceRendersEveryFrameAgain) {
    const fs::path folder = fresh_folder("sequence-temporal");
    const std::string calm = std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json --width 16 --height 12 --temporal";
    const std::string out = " --frames 0:2 --out " + (folder / "t_%04d.exr").string();
    ASSERT_EQ(run_vkwater("render " + calm + out).exit_code, 0);
    const CommandRun rerun = run_vkwater("render " + calm + out);
    ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
    EXPECT_NE(rerun.output.find("0 kept"), std::string::npos) << rerun.output;
    EXPECT_NE(rerun.output.find("3 to render"), std::string::npos) << rerun.output;
}

}  // namespace
}  // namespace vkw::cli_test
