// Helpers shared by the image tests: a scratch directory, a test image, file bytes and a
// check that a call throws a one-line UserError naming a path.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "engine/core/errors.hpp"
#include "engine/image/image.hpp"

namespace vkw::test {

// A fresh directory per test, removed afterwards; named after the test so leftovers from a
// crashed run are easy to attribute.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() / ("vkwater_" + std::string(info->test_suite_name()) + "_" +
                                                          info->name() + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// Every value distinct, of both signs, mostly not representable as half, so that a channel
// mix-up, a row flip or a lossy conversion shows.
inline ImageRGBA32F make_test_image(int width, int height, const std::vector<std::string>& layer_names = {}) {
    ImageRGBA32F image;
    image.width = width;
    image.height = height;
    image.rgba.resize(image.pixel_count() * 4);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        const float magnitude = 0.1f + 0.37f * static_cast<float>(i);
        image.rgba[i] = i % 5 == 3 ? -magnitude : magnitude;
    }
    for (std::size_t l = 0; l < layer_names.size(); ++l) {
        ExtraLayer layer{layer_names[l], std::vector<float>(image.pixel_count() * 3)};
        for (std::size_t i = 0; i < layer.rgb.size(); ++i) {
            layer.rgb[i] = 1000.0f * static_cast<float>(l + 1) + 0.013f * static_cast<float>(i);
        }
        image.layers.push_back(std::move(layer));
    }
    return image;
}

inline std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Runs `call`, expects a UserError whose message is one line, names `path` in quotes and
// contains `reason`.
inline void expect_user_error(const std::function<void()>& call, const std::filesystem::path& path,
                              const std::string& reason) {
    try {
        call();
        ADD_FAILURE() << "expected vkw::UserError naming '" << path.string() << "'";
    } catch (const UserError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'" + path.string() + "'"), std::string::npos) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

}  // namespace vkw::test
