// How much the vkwater commands say, and their progress reports.
//
// The commands write their reports (the device, the pass times, the files written) to stdout and
// their errors to stderr, prefixed "vkwater: ". -q/--quiet keeps the errors alone; -v/--verbose
// adds the details a command has (render: each effect's decision and its reason).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkw::cli {

enum class Verbosity : uint8_t { Quiet, Normal, Verbose };

// Set once, after the command line is parsed. Quiet closes stdout (every report goes there), so a
// command need not test it line by line.
void set_verbosity(Verbosity verbosity);
Verbosity verbosity();
inline bool verbose() { return verbosity() == Verbosity::Verbose; }

// Each line on stderr as "vkwater: warning: LINE" (what a scene asks for that is left out, say);
// nothing when quiet.
void print_warnings(const std::vector<std::string>& lines);

// A long command's progress on stderr: a bar redrawn in place on a terminal; elsewhere (logs, CI)
// one line per tenth ("reference: 30%"), so that a long run is never silent; nothing when quiet.
// With a delay, nothing until the command has run that long (a quick render stays quiet); the
// environment variable VKWATER_PROGRESS_DELAY_S replaces every delay (the tests set 0).
class Progress {
public:
    explicit Progress(std::string label, double delay_seconds = 0.0);
    // fraction in [0, 1]; reports each step once, and ends the bar's line at 1.
    void report(double fraction);

private:
    std::string label_;
    bool terminal_;
    double delay_seconds_;
    double start_seconds_;
    bool started_ = false;
    int next_tenth_ = 1;
    int last_percent_ = -1;
};

}  // namespace vkw::cli
