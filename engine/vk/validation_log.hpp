// Collects the messages of the Khronos validation layer. In vkwater every error or
// warning is a failure (tests assert an empty log; the CLI exits 2), except
// performance warnings listed in kAcceptedPerformanceWarnings with their reason.
#pragma once

#include <array>
#include <mutex>
#include <string>
#include <vector>

namespace vkw {

struct AcceptedWarning {
    const char* message_id;  // the layer's VUID / message id name
    const char* reason;      // why it is harmless for vkwater (also listed in docs/testing.md)
};

// Empty today: no performance warning is accepted. Add one only with its reason,
// and list it in docs/testing.md, "Validation", too.
inline constexpr std::array<AcceptedWarning, 0> kAcceptedPerformanceWarnings{};

class ValidationLog {
public:
    // echo: print each failure to stderr as it happens (the CLI wants that; some tests do not).
    explicit ValidationLog(bool echo = true) : echo_(echo) {}

    void record_failure(std::string message);
    void record_accepted(std::string message);

    size_t failure_count() const;
    std::vector<std::string> failures() const;
    size_t accepted_count() const;
    void clear();

private:
    mutable std::mutex mutex_;
    std::vector<std::string> failures_;
    size_t accepted_ = 0;
    bool echo_ = true;
};

}  // namespace vkw
