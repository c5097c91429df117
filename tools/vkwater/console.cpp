// How much the vkwater commands say (console.hpp).
#include "tools/vkwater/console.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace vkw::cli {
namespace {

Verbosity current = Verbosity::Normal;

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void set_verbosity(Verbosity verbosity) {
    current = verbosity;
    if (verbosity == Verbosity::Quiet) {
        std::fflush(stdout);
        if (!std::freopen("/dev/null", "w", stdout)) std::fclose(stdout);
    }
}

Verbosity verbosity() { return current; }

void print_warnings(const std::vector<std::string>& lines) {
    if (current == Verbosity::Quiet) return;
    for (const std::string& line : lines) std::fprintf(stderr, "vkwater: warning: %s\n", line.c_str());
}

Progress::Progress(std::string label, double delay_seconds)
    : label_(std::move(label)),
      terminal_(::isatty(STDERR_FILENO) != 0),
      delay_seconds_(delay_seconds),
      start_seconds_(now_seconds()) {
    if (const char* text = std::getenv("VKWATER_PROGRESS_DELAY_S"); text && *text) {
        const double value = std::strtod(text, nullptr);
        if (std::isfinite(value) && value >= 0.0) delay_seconds_ = value;
    }
}

void Progress::report(double fraction) {
    if (current == Verbosity::Quiet) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (!started_) {
        if (now_seconds() - start_seconds_ < delay_seconds_) return;
        // Off a terminal, the first line is the tenth reached by then; the earlier ones are past.
        started_ = true;
        if (delay_seconds_ > 0.0) next_tenth_ = std::max(1, static_cast<int>(fraction * 10.0));
    }
    const int percent = static_cast<int>(fraction * 100.0);
    if (terminal_) {
        if (percent == last_percent_) return;
        last_percent_ = percent;
        const int filled = static_cast<int>(fraction * 40.0);
        std::fprintf(stderr, "\r%s [%-40.*s] %3d%%", label_.c_str(), filled, "########################################",
                     percent);
        if (fraction >= 1.0) std::fprintf(stderr, "\n");
        std::fflush(stderr);
        return;
    }
    while (next_tenth_ <= 10 && fraction >= next_tenth_ / 10.0) {
        std::fprintf(stderr, "%s: %d%%\n", label_.c_str(), next_tenth_ * 10);
        ++next_tenth_;
    }
}

}  // namespace vkw::cli
