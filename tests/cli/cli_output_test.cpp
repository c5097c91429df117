// What the commands say besides their results: -q and -v, progress reports, warnings about what a
// scene's files ask for that is left out, and the preview's exposure.
#include "tests/cli/cli_support.hpp"
#include "tests/scene/gltf_test_files.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>

namespace vkw::cli_test {
namespace {

// Off a terminal the reference reports its progress a line per tenth instead of a bar (it used to
// print nothing until it finished).
TEST(cli, TheReferenceReportsProgressOffATerminal) {
    const CommandRun run =
        run_vkwater("reference " + std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json --width 16 --height 12 --out " +
                    scratch("progress.exr").string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("reference: 10%\n"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("reference: 100%\n"), std::string::npos) << run.output;
}

// -q keeps the errors alone; -v adds render's decisions; they exclude each other.
TEST(cli, QuietPrintsOnlyErrors) {
    const std::string calm = std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json";
    const fs::path out = scratch("quiet.exr");
    fs::remove(out);
    const CommandRun quiet = run_vkwater("render " + calm + " --width 16 --height 12 -q --out " + out.string(),
                                         "VKWATER_PROGRESS_DELAY_S=0");
    EXPECT_EQ(quiet.exit_code, 0) << quiet.output;
    EXPECT_EQ(quiet.output, "");  // no report and no progress
    EXPECT_TRUE(fs::exists(out));
    // Before the command too, and an error still gets its one line.
    const CommandRun error = run_vkwater("-q render " + calm + " --set water.ior=0 --out " + out.string());
    EXPECT_EQ(error.exit_code, 1) << error.output;
    EXPECT_EQ(std::count(error.output.begin(), error.output.end(), '\n'), 1) << error.output;
    EXPECT_NE(error.output.find("water.ior"), std::string::npos) << error.output;
}

TEST(cli, VerboseRenderGivesEachEffectsDecision) {
    const CommandRun run =
        run_vkwater("render " + std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json --width 16 --height 12 -v --out " +
                    scratch("verbose.exr").string());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("needs:\n  water: on - "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("  caustics: off - the water is flat"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("pass times"), std::string::npos) << run.output;
    expect_clean_failure(run_vkwater("render x.json -q -v"), 1, "--quiet and --verbose: choose one");
}

// render reports its frames' progress as reference does, after its first second (the variable
// sets the delay: 0 reports at once, 1000 never within this test).
TEST(cli, RenderReportsProgressOffATerminalAfterItsDelay) {
    const std::string command = "render " + std::string(VKWATER_SOURCE_DIR) +
                                "/scenes/calm.json --width 16 --height 12 --repeat 2 --spp 4 --out " +
                                scratch("progress-render.exr").string();
    const CommandRun at_once = run_vkwater(command, "VKWATER_PROGRESS_DELAY_S=0");
    ASSERT_EQ(at_once.exit_code, 0) << at_once.output;
    // 8 sub-frames: every tenth is reached, each printed once.
    for (int tenth = 1; tenth <= 10; ++tenth) {
        const std::string line = "render: " + std::to_string(10 * tenth) + "%\n";
        EXPECT_NE(at_once.output.find(line), std::string::npos) << line << at_once.output;
        EXPECT_EQ(at_once.output.find(line), at_once.output.rfind(line)) << line << at_once.output;
    }
    const CommandRun delayed = run_vkwater(command, "VKWATER_PROGRESS_DELAY_S=1000");
    ASSERT_EQ(delayed.exit_code, 0) << delayed.output;
    EXPECT_EQ(delayed.output.find("render: "), std::string::npos) << delayed.output;
}

// What a scene's glTF asks for that is left out: a warning line on stderr naming the receiver's
// file, the command still succeeds; -q leaves it out too.
TEST(cli, AGltfMaterialLeftOutIsAWarningNamingTheReceiversFile) {
    const fs::path dir = scratch("warning-scene").parent_path() / "warning-scene";
    fs::create_directories(dir);
    test::GltfSpec spec = test::pyramid();
    spec.material = R"({ "name": "Brass", "pbrMetallicRoughness": { "metallicFactor": 1.0 } })";
    test::write_text(dir / "brass.gltf", test::gltf_text(spec));
    nlohmann::json calm = nlohmann::json::parse(std::ifstream(std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json"));
    calm["receivers"] =
        nlohmann::json::parse(R"([{ "type": "gltf", "file": "brass.gltf", "translation": [0, -0.5, 0] }])");
    const fs::path scene = test::write_text(dir / "scene.json", calm.dump());
    const CommandRun run = run_vkwater("check " + scene.string());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("vkwater: warning: receivers[0].file 'brass.gltf': materials[0] 'Brass': drawn as "
                              "Lambertian (metallicFactor 1)\n"),
              std::string::npos)
        << run.output;
    const CommandRun quiet = run_vkwater("check -q " + scene.string());
    EXPECT_EQ(quiet.exit_code, 0) << quiet.output;
    EXPECT_EQ(quiet.output, "");
}

// --exposure is the preview's: the same PNG as the override camera.exposure, another than the
// scene's own; 0, negatives and non-finite values are refused naming the option.
TEST(cli, RenderExposureSetsThePreviewsExposure) {
    const std::string calm = "render " + std::string(VKWATER_SOURCE_DIR) + "/scenes/calm.json --width 16 --height 12";
    const fs::path flag = scratch("exposure-flag.png"), set = scratch("exposure-set.png"), own = scratch("own.png");
    ASSERT_EQ(run_vkwater(calm + " --exposure 2 --out " + flag.string()).exit_code, 0);
    ASSERT_EQ(run_vkwater(calm + " --set camera.exposure=2 --out " + set.string()).exit_code, 0);
    ASSERT_EQ(run_vkwater(calm + " --out " + own.string()).exit_code, 0);
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes(flag), bytes(set));
    EXPECT_NE(bytes(flag), bytes(own));
    for (const char* bad : {"0", "-1", "inf"}) {
        const CommandRun run = run_vkwater(calm + " --exposure " + bad + " --out " + flag.string());
        EXPECT_EQ(run.exit_code, 1) << run.output;
        EXPECT_NE(run.output.find("--exposure: '" + std::string(bad) + "'"), std::string::npos) << run.output;
    }
}

}  // namespace
}  // namespace vkw::cli_test
