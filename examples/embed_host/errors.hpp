// How the sample fails: a failed Vulkan call of its own or a vkwater Status that is not ok becomes a
// HostError, which main() catches, prints and returns as the exit code. Nothing aborts, as vkwater
// itself never does (vkwater/status.hpp).
#pragma once

#include <vkwater/status.hpp>

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace embed_host {

// Exit codes: 1 for what the user can fix (a bad argument, vkwater's InvalidInput: a scene file, a
// field), 2 for the device or the program (a Vulkan call that failed, vkwater's Internal).
inline constexpr int kExitInvalidInput = 1;
inline constexpr int kExitInternal = 2;

class HostError : public std::runtime_error {
public:
    HostError(const std::string& message, int exit_code) : std::runtime_error(message), exit_code_(exit_code) {}
    int exit_code() const { return exit_code_; }

private:
    int exit_code_;
};

inline void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) {
        throw HostError(std::string(what) + " failed (VkResult " + std::to_string(result) + ")", kExitInternal);
    }
}

// vkwater's message is one line that already names the file, field or target at fault.
inline void check(const vkwater::Status& status) {
    if (status.ok()) return;
    throw HostError("vkwater: " + status.message,
                    status.kind == vkwater::ErrorKind::InvalidInput ? kExitInvalidInput : kExitInternal);
}

}  // namespace embed_host
