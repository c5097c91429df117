// Helpers shared by the scene tests: a minimal valid scene and error-message capture.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/errors.hpp"

namespace vkw::test {

inline const std::filesystem::path kSourceDir = VKWATER_SOURCE_DIR;

// Only the required fields: everything else takes its default.
inline constexpr const char* kMinimalScene = R"({
  "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
  "sun": { "elevation_deg": 45 },
  "sky": { "radiance": [0.3, 0.4, 0.5] }
})";

// Runs `action`, which must throw vkw::UserError, and returns the message ("" and a test
// failure otherwise). Any other exception fails the test too.
inline std::string user_error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const UserError& error) {
        return error.what();
    } catch (const std::exception& error) {
        ADD_FAILURE() << "expected vkw::UserError, got another exception: " << error.what();
        return {};
    }
    ADD_FAILURE() << "expected vkw::UserError, nothing was thrown";
    return {};
}

}  // namespace vkw::test
