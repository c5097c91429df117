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

TEST(cli, RenderBudgetPrintsItsSettingsAndTheyGiveTheSameImage) {
    const fs::path budgeted = scratch("budget.exr"), explicit_out = scratch("budget-explicit.exr");
    // pool at its own settings takes about 0.3 s a frame here on lavapipe (0.1 ms on a GPU): 20 ms
    // makes the budget turn settings down on a CPU device.
    const CommandRun run = run_vkwater(
        "render " + kPool + " --width 160 --height 120 --budget-ms 20 --validation --out " + budgeted.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.output, match, std::regex(R"(budget 20 ms: chose (.*) \(measured)")))
        << run.output;
    const std::string chosen = match[1].str();
    const ImageRGBA32F image = read_exr(budgeted);
    EXPECT_NE(attribute(image, "vkwater/budget").find(chosen), std::string::npos) << attribute(image, "vkwater/budget");
    const std::string arguments = chosen == "the scene's own settings" ? "" : chosen;
    const CommandRun again = run_vkwater("render " + kPool + " --width 160 --height 120 " + arguments +
                                         " --validation --out " + explicit_out.string());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    const ImageRGBA32F repeated = read_exr(explicit_out);
    ASSERT_EQ(repeated.width, image.width);
    EXPECT_TRUE(repeated.rgba == image.rgba) << "the settings '" << chosen << "' gave another image";
    ASSERT_EQ(repeated.layers.size(), image.layers.size());
    for (size_t i = 0; i < image.layers.size(); ++i) EXPECT_TRUE(repeated.layers[i].rgb == image.layers[i].rgb);
}

TEST(cli, RenderBudgetRefusesWhatItChoosesItself) {
    const fs::path out = scratch("budget-refused.exr");
    expect_clean_failure(run_vkwater("render " + kPool + " --budget-ms 50 --render-scale 0.5 --out " + out.string()), 1,
                         "--budget-ms chooses the resolution scale itself");
    expect_clean_failure(run_vkwater("render " + kPool + " --budget-ms 50 --spp 4 --out " + out.string()), 1,
                         "--budget-ms chooses its settings at one sample per pixel");
    expect_clean_failure(
        run_vkwater("render " + kPool + " --budget-ms 50 --frames 0:1 --out " + scratch("budget_%04d.exr").string()), 1,
        "a sequence renders every frame at the same settings");
    expect_clean_failure(run_vkwater("render " + kPool + " --budget-ms 0 --out " + out.string()), 1, "--budget-ms");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vkw::cli_test
