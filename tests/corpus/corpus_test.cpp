// The malformed-input corpus (tests/corpus/cases.tsv, written by tests/corpus/generate.py): every
// case run through the vkwater command line as a user would run it. A refused input must exit
// with its expected code (1: the user's mistake) and print exactly one line that matches the
// case's pattern, begins "vkwater: ", and stays short once the case's own path is taken out (the
// loader quotes inputs cut to 80 characters). Never a signal, never exit 0 or 2 for bad input.
// One test per category, each row a SCOPED_TRACE, so a failure names the case.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string kCases = std::string(VKWATER_SOURCE_DIR) + "/tests/corpus/cases";

struct Case {
    std::string id, category, arguments, pattern;
    int exit_code = 0;
};

std::vector<Case> read_cases() {
    std::ifstream table(std::string(VKWATER_SOURCE_DIR) + "/tests/corpus/cases.tsv");
    std::vector<Case> cases;
    for (std::string line; std::getline(table, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> fields;
        std::stringstream columns(line);
        for (std::string field; std::getline(columns, field, '\t');) fields.push_back(field);
        if (fields.size() == 4) fields.emplace_back();  // an empty pattern
        if (fields.size() != 5) {
            ADD_FAILURE() << "malformed row in cases.tsv: " << line.substr(0, 120);
            continue;
        }
        cases.push_back({fields[0], fields[1], fields[2], fields[4], std::stoi(fields[3])});
    }
    return cases;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

std::string regex_escaped(const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
}

struct Run {
    int exit_code = -1;
    std::string output;  // stdout and stderr
};

Run run_vkwater(const std::string& arguments) {
    const std::string command = "'" VKWATER_CLI "' " + arguments + " 2>&1";
    Run run;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return run;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) run.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return run;
}

// A refusal's line with every path in the corpus replaced by one letter (the paths are the user's
// and can be of any length): about 200 characters of message and accepted range, plus at most two
// inputs quoted cut short (a key to 40 characters and an override to 80, each with its length).
constexpr std::size_t kMaxMessageChars = 260;

std::string without_corpus_paths(const std::string& line) {
    static const std::regex path(regex_escaped(kCases) + "[^ ':]*");
    return std::regex_replace(line, path, "F");
}

// Whether this build's vkwater has the case's command: the loaders-only build (the sanitizers')
// has check and compare alone.
bool command_built(const Case& c) {
#ifdef VKWATER_LOADERS_ONLY
    const std::string command = c.arguments.substr(0, c.arguments.find(' '));
    for (const char* absent : {"render", "passes", "reference", "bench", "view", "povray"}) {
        if (command == absent) return false;
    }
#else
    (void)c;
#endif
    return true;
}

void run_category(const std::string& category) {
    int count = 0;
    for (const Case& c : read_cases()) {
        if (c.category != category || !command_built(c)) continue;
        ++count;
        SCOPED_TRACE(c.id + ": vkwater " + c.arguments.substr(0, 200));
        const Run run = run_vkwater(replace_all(c.arguments, "{cases}", kCases));
        EXPECT_EQ(run.exit_code, c.exit_code) << run.output.substr(0, 2000);
        if (c.exit_code == 0) {
            EXPECT_TRUE(std::regex_search(run.output, std::regex(c.pattern))) << run.output.substr(0, 2000);
            continue;
        }
        ASSERT_FALSE(run.output.empty());
        EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << "not one line:\n" << run.output.substr(0, 2000);
        const std::string line = run.output.substr(0, run.output.find('\n'));
        EXPECT_EQ(line.rfind("vkwater: ", 0), 0u) << line;
        EXPECT_LE(without_corpus_paths(line).size(), kMaxMessageChars) << line;
        const std::regex pattern(replace_all(c.pattern, "{cases}", regex_escaped(kCases)));
        EXPECT_TRUE(std::regex_search(line, pattern)) << "pattern: " << c.pattern << "\nline: " << line;
    }
    EXPECT_GT(count, 0) << "no case of category " << category;
}

class Corpus : public ::testing::TestWithParam<std::string> {};

TEST_P(Corpus, EachCaseExitsAsExpectedWithOneMatchingLine) { run_category(GetParam()); }

const std::vector<std::string> kCategories = {"valid",    "type",    "number", "vector", "unknown", "syntax",
                                              "encoding", "nesting", "set",    "cli",    "gltf",    "exr"};

INSTANTIATE_TEST_SUITE_P(corpus, Corpus, ::testing::ValuesIn(kCategories),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

// Every row belongs to a category run above, and the corpus holds at least 300 cases.
TEST(corpus, EveryCaseIsInARunCategory) {
    const std::vector<Case> cases = read_cases();
    EXPECT_GE(cases.size(), 300u);
    std::map<std::string, int> ids;
    for (const Case& c : cases) {
        EXPECT_NE(std::find(kCategories.begin(), kCategories.end(), c.category), kCategories.end()) << c.id;
        EXPECT_EQ(++ids[c.id], 1) << "duplicate id " << c.id;
    }
}

}  // namespace
