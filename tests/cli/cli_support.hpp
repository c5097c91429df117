// What the tests of the vkwater command line share: running it as a user does (its exit code and
// its stdout and stderr together), a scratch folder, and the check of a clean failure.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace vkw::cli_test {

namespace fs = std::filesystem;

struct CommandRun {
    int exit_code;
    std::string output;  // stdout and stderr together
};

inline CommandRun run_vkwater(const std::string& arguments, const std::string& environment = "") {
    const std::string command = environment + " '" VKWATER_CLI "' " + arguments + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    CommandRun run{-1, ""};
    if (!pipe) return run;
    std::array<char, 4096> buffer;
    while (size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) run.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return run;
}

inline fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / "vkwater_cli_test";
    fs::create_directories(dir);
    return dir / name;
}

inline const std::string kPool = std::string(VKWATER_SOURCE_DIR) + "/scenes/pool.json";

// One failure, cleanly: the exit code, the line naming what was wrong, no validation message.
inline void expect_clean_failure(const CommandRun& run, int exit_code, const std::string& needle) {
    EXPECT_EQ(run.exit_code, exit_code) << run.output;
    EXPECT_NE(run.output.find(needle), std::string::npos) << "expected '" << needle << "' in:\n" << run.output;
    EXPECT_EQ(run.output.find("validation error"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("validation warning"), std::string::npos) << run.output;
}

}  // namespace vkw::cli_test
