// vkwater render --budget-ms: it prints the settings it chose, records them in the EXR, and the same
// settings given explicitly give the same image bit for bit. Which settings a budget gets depends
// on the machine's speed; what is asserted holds for any choice. Misuse is one clear line.
#include "engine/image/exr_io.hpp"
#include "tests/cli/cli_support.hpp"

#include <regex>

namespace vkw::cli_test {
namespace {

std::string attribute(const ImageRGBA32F& image, const std::string& name) {
    for (const ImageAttribute& a : image.attributes) {
        if (a.name == name) return a.value;
    }
    return "";
}

// Runs `render SCENE <options> --budget-ms B`, then the settings it printed given explicitly, and
// expects the same image bit for bit; returns the settings.
std::string budgeted_settings_reproduce(const std::string& options, const std::string& budget_ms,
                                        const std::string& scene = kPool) {
    const fs::path budgeted = scratch("budget.exr"), explicit_out = scratch("budget-explicit.exr");
    const CommandRun run = run_vkwater("render " + scene + " --width 160 --height 120 " + options + " --budget-ms " +
                                       budget_ms + " --validation --out " + budgeted.string());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    // The on/off knobs are measured on the scene before the choice (tools/vkwater/budget_previews.hpp):
    // pool's caustics, lake's caustics, scene lookups and second layer.
    EXPECT_NE(run.output.find("budget: turned off in 160x120 previews"), std::string::npos) << run.output;
    std::smatch match;
    if (!std::regex_search(run.output, match, std::regex("budget " + budget_ms + R"( ms: chose (.*) \(measured)"))) {
        ADD_FAILURE() << run.output;
        return "";
    }
    const std::string chosen = match[1].str();
    const ImageRGBA32F image = read_exr(budgeted);
    EXPECT_NE(attribute(image, "vkwater/budget").find(chosen), std::string::npos) << attribute(image, "vkwater/budget");
    const std::string arguments = chosen == "the scene's own settings" ? "" : chosen;
    const CommandRun again = run_vkwater("render " + scene + " --width 160 --height 120 " + arguments +
                                         " --validation --out " + explicit_out.string());
    EXPECT_EQ(again.exit_code, 0) << again.output;
    if (again.exit_code != 0) return chosen;
    const ImageRGBA32F repeated = read_exr(explicit_out);
    EXPECT_EQ(repeated.width, image.width);
    EXPECT_TRUE(repeated.rgba == image.rgba) << "the settings '" << chosen << "' gave another image";
    EXPECT_EQ(repeated.layers.size(), image.layers.size());
    for (size_t i = 0; i < std::min(image.layers.size(), repeated.layers.size()); ++i) {
        EXPECT_TRUE(repeated.layers[i].rgb == image.layers[i].rgb);
    }
    return chosen;
}

TEST(cli, RenderBudgetPrintsItsSettingsAndTheyGiveTheSameImage) {
    // pool at its own settings takes about 0.3 s a frame here on lavapipe (0.1 ms on a GPU): 20 ms
    // makes the budget turn settings down on a CPU device.
    budgeted_settings_reproduce("", "20");
}

// Lake has every knob, the scene lookups and the terrain's cells among them (a --set with brackets,
// quoted for the shell): a budget of 10 microseconds, which no device meets (a frame is about 25
// passes), takes the cheapest candidate, both lookups off.
TEST(cli, RenderBudgetOnLakeGivesSettingsThatReproduceIt) {
    const std::string chosen =
        budgeted_settings_reproduce("", "0.01", std::string(VKWATER_SOURCE_DIR) + "/scenes/lake.json");
    EXPECT_NE(chosen.find("effects.refraction.mode=off"), std::string::npos) << chosen;
    EXPECT_NE(chosen.find("'receivers[0].resolution=32'"), std::string::npos) << chosen;
}

// With --spp N the budget may take up to N samples: a budget no device misses keeps all of them
// (and says so, since --spp is not the command's default), a tight one gives settings that
// reproduce the image too, samples included.
TEST(cli, RenderBudgetTakesAtMostTheSamplesAsked) {
    EXPECT_EQ(budgeted_settings_reproduce("--spp 4", "9999"), "--spp 4");
    budgeted_settings_reproduce("--spp 4", "20");
}

TEST(cli, RenderBudgetRefusesWhatItChoosesItself) {
    const fs::path out = scratch("budget-refused.exr");
    fs::remove(out);  // a run of an older build may have left one
    expect_clean_failure(run_vkwater("render " + kPool + " --budget-ms 50 --render-scale 0.5 --out " + out.string()), 1,
                         "--budget-ms chooses the resolution scale itself");
    expect_clean_failure(
        run_vkwater("render " + kPool + " --budget-ms 50 --frames 0:1 --out " + scratch("budget_%04d.exr").string()), 1,
        "a sequence renders every frame at the same settings");
    expect_clean_failure(run_vkwater("render " + kPool + " --budget-ms 0 --out " + out.string()), 1, "--budget-ms");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vkw::cli_test
