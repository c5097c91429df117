// vkwater as a host engine meets it: installed into a fresh prefix, found by a separate project
// (examples/embed_host) with find_package(vkwater), its offscreen sample run on lavapipe under
// validation with no path into this build tree. Its picture must equal the installed CLI's render
// of the same scene wherever the host's own box is not. The sample's window host then runs too.
#include "engine/image/exr_io.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 160, kHeight = 120;

// A PFM file ("PF", RGB, little-endian, rows bottom to top) as rows top to bottom.
std::vector<float> read_pfm(const fs::path& path, int& width, int& height) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    double scale = 0.0;
    in >> magic >> width >> height >> scale;
    in.get();  // the single whitespace before the data
    if (!in || magic != "PF" || scale >= 0.0) return {};
    std::vector<float> bottom_up(size_t(width) * height * 3);
    in.read(reinterpret_cast<char*>(bottom_up.data()), std::streamsize(bottom_up.size() * sizeof(float)));
    if (!in) return {};
    std::vector<float> rows(bottom_up.size());
    for (int y = 0; y < height; ++y) {
        std::copy_n(bottom_up.begin() + std::ptrdiff_t(size_t(height - 1 - y) * width * 3), width * 3,
                    rows.begin() + std::ptrdiff_t(size_t(y) * width * 3));
    }
    return rows;
}

int run(const std::string& command, const fs::path& log) {
    const std::string line = command + " > '" + log.string() + "' 2>&1";
    const int status = std::system(line.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string tail(const fs::path& log) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string all = text.str();
    return all.size() > 3000 ? all.substr(all.size() - 3000) : all;
}

TEST(EmbedInstall, SampleHostBuiltAgainstAnInstallMatchesTheInstalledCli) {
    const fs::path work = fs::path(VKWATER_BINARY_DIR) / "tests/embed/install_test";
    fs::remove_all(work);
    fs::create_directories(work);
    const fs::path prefix = work / "prefix", host = work / "host", log = work / "step.log";
    const std::string cmake = VKWATER_CMAKE_COMMAND;
    // No step may find this build tree's shaders through the environment the test runs in.
    const std::string clean_env = "env -u VKWATER_SHADER_DIR ";

    ASSERT_EQ(run("'" + cmake + "' --install '" + VKWATER_BINARY_DIR + "' --prefix '" + prefix.string() + "'", log), 0)
        << tail(log);
    ASSERT_TRUE(fs::exists(prefix / "lib/cmake/vkwater/vkwaterConfig.cmake"));
    ASSERT_EQ(run("'" + cmake + "' -S '" + VKWATER_SOURCE_DIR + "/examples/embed_host' -B '" + host.string() +
                      "' -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH='" + prefix.string() + "'",
                  log),
              0)
        << tail(log);
    ASSERT_EQ(run("'" + cmake + "' --build '" + host.string() + "'", log), 0) << tail(log);

    const fs::path scene = prefix / "share/vkwater/scenes/pool.json";
    const std::string size = " --width " + std::to_string(kWidth) + " --height " + std::to_string(kHeight);
    ASSERT_EQ(run(clean_env + "'" + (host / "embed_host_offscreen").string() + "' '" + scene.string() + "' '" +
                      (work / "host").string() + "'" + size + " --validation",
                  log),
              0)
        << tail(log);
    ASSERT_EQ(run(clean_env + "'" + (prefix / "bin/vkwater").string() + "' render '" + scene.string() + "'" + size +
                      " --out '" + (work / "cli.exr").string() + "'",
                  log),
              0)
        << tail(log);

    int w = 0, h = 0, mw = 0, mh = 0;
    const std::vector<float> color = read_pfm(work / "host.color.pfm", w, h);
    const std::vector<float> mask = read_pfm(work / "host.box_mask.pfm", mw, mh);
    ASSERT_EQ(w, kWidth);
    ASSERT_EQ(h, kHeight);
    ASSERT_EQ(mw, kWidth);
    ASSERT_EQ(mh, kHeight);
    const vkw::ImageRGBA32F cli = vkw::read_exr(work / "cli.exr");
    ASSERT_EQ(cli.width, kWidth);

    // Outside the box: the same scene, passes, SPIR-V and device: equal bit for bit (tolerance 0).
    // Inside it: a pixel differs where the box is nearer than the water and equals where it is not.
    size_t outside = 0, box = 0, box_shown = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            const float* want = cli.pixel(x, y);
            const float* got = &color[3 * i];
            if (mask[3 * i] > 0.0f) {
                ++box;
                if (got[0] != want[0] || got[1] != want[1] || got[2] != want[2]) ++box_shown;
                continue;
            }
            ++outside;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(got[c], want[c]) << x << "," << y << " channel " << c;
        }
    }
    // The sample's box stands in the pool: above the water it is nearer and shows; its submerged
    // part is behind the surface, where the water (which cannot see the box) is nearer and wins.
    EXPECT_GT(box, 100u);  // the box covers a visible part of the 160x120 frame
    EXPECT_GT(box_shown, box / 2) << "the box is nearer than the water over most of it";
    EXPECT_LT(box_shown, box) << "the water hides the box's submerged part";
    EXPECT_GT(outside, size_t(kWidth) * kHeight / 2);

    // A scene built in code against the installed headers (examples/embed_host/scene_in_code_main.cpp:
    // pool in structs), written as a file and rendered by the installed CLI: pool.json's image bit
    // for bit, so the structs, scene_json and its export all reached the install.
    const fs::path in_code = work / "pool_in_code.json";
    ASSERT_EQ(run("'" + (host / "embed_host_scene_in_code").string() + "' '" + in_code.string() + "'", log), 0)
        << tail(log);
    ASSERT_EQ(run(clean_env + "'" + (prefix / "bin/vkwater").string() + "' render '" + in_code.string() + "'" + size +
                      " --out '" + (work / "in_code.exr").string() + "'",
                  log),
              0)
        << tail(log);
    const vkw::ImageRGBA32F from_structs = vkw::read_exr(work / "in_code.exr");
    ASSERT_EQ(from_structs.width, kWidth);
    ASSERT_EQ(from_structs.height, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            for (int c = 0; c < 4; ++c) ASSERT_EQ(from_structs.pixel(x, y)[c], cli.pixel(x, y)[c]) << x << "," << y;
        }
    }

    // The window host, built by the same project (GLFW is a dependency of vkwater's own viewer, so it
    // is there): two frames into its swapchain under a virtual X server, validation clean.
    ASSERT_TRUE(fs::exists(host / "embed_host_window")) << "the sample's GLFW host was not built";
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null 2>&1"), 0)
        << "xvfb-run is missing (Debian: xvfb xauth; tools/install-deps.sh installs them)";
    ASSERT_EQ(run(clean_env + "xvfb-run -a '" + (host / "embed_host_window").string() + "' '" + scene.string() +
                      "' --frames 2 --validation",
                  log),
              0)
        << tail(log);
}

}  // namespace
