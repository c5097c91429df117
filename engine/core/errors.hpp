// The two kinds of failure vkwater reports, and the exit code each maps to.
//
// UserError: something the user can fix (a scene file, a flag, an output path).
//   The message names the file, the field and the accepted range. Exit code 1.
// InternalError: the machine or vkwater itself failed (no Vulkan device, a Vulkan
//   call returned an error, a validation message). Exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace vkw {

class UserError : public std::runtime_error {
public:
    explicit UserError(const std::string& message) : std::runtime_error(message) {}
};

class InternalError : public std::runtime_error {
public:
    explicit InternalError(const std::string& message) : std::runtime_error(message) {}
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitUserError = 1;
inline constexpr int kExitInternalError = 2;

}  // namespace vkw
