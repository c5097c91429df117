// Every `#include "..."` in engine/, passes/, tools/ and tests/ is read and held against the
// layer table (tests/source_tree/include_layers.cpp): engine/ knows no pass and no tool, passes/ knows
// no tool and only passes/frame composes the frame, the reference renderer sees only
// engine/{core,scene,water,image}. A failure names the file, its line and the edge. Quoted
// includes are root-relative, so every one must name a file from the repository root.
#include "tests/source_tree/include_layers.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace vkw::layers {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = VKWATER_SOURCE_DIR;

struct IncludeEdge {
    std::string file;  // root-relative
    int line = 0;
    std::string target;  // as written
};

bool is_source(const fs::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".cpp" || ext == ".hpp" || ext == ".h";
}

std::vector<IncludeEdge> read_edges() {
    static const std::regex include_line(R"(^\s*#\s*include\s+\"([^\"]+)\")");
    std::vector<IncludeEdge> edges;
    for (const char* top : {"engine", "passes", "library", "tools", "tests"}) {
        for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / top)) {
            if (!entry.is_regular_file() || !is_source(entry.path())) continue;
            std::ifstream in(entry.path());
            std::string text;
            int number = 0;
            while (std::getline(in, text)) {
                ++number;
                std::smatch match;
                if (std::regex_search(text, match, include_line)) {
                    edges.push_back({fs::relative(entry.path(), kRoot).generic_string(), number, match[1]});
                }
            }
        }
    }
    return edges;
}

TEST(Layers, TheTableSeesTheTree) {
    const std::vector<Layer> table = layer_table();
    EXPECT_EQ(layer_of(table, "engine/scene/scene.hpp"), "engine/scene");
    EXPECT_EQ(layer_of(table, "passes/frame/renderer.cpp"), "passes/frame");
    EXPECT_EQ(layer_of(table, "tools/vkwater/view/viewer.cpp"), "tools/vkwater");
    EXPECT_EQ(layer_of(table, "tests/render/sky_test.cpp"), "tests");
    EXPECT_EQ(layer_of(table, "passes/frame.cpp"), "");
    EXPECT_TRUE(may_include(table, "passes/frame", "passes/caustics"));
    EXPECT_FALSE(may_include(table, "passes/caustics", "passes/frame"));
    EXPECT_FALSE(may_include(table, "engine/scene", "engine/framegraph"));
    EXPECT_FALSE(may_include(table, "tools/reference", "passes/water"));
    EXPECT_FALSE(may_include(table, "engine/window", "passes/present"));
}

TEST(Layers, EveryIncludeEdgeIsAllowed) {
    const std::vector<Layer> table = layer_table();
    const std::vector<IncludeEdge> edges = read_edges();
    // Nothing read is no test: the tree has hundreds of includes.
    ASSERT_GT(edges.size(), 500u);
    size_t checked = 0;
    for (const IncludeEdge& edge : edges) {
        const std::string where = edge.file + ":" + std::to_string(edge.line) + ": #include \"" + edge.target + "\"";
        const std::string_view from = layer_of(table, edge.file);
        EXPECT_FALSE(from.empty()) << where << ": the file lies in no layer of tests/source_tree/include_layers.cpp";
        if (!fs::exists(kRoot / edge.target)) {
            ADD_FAILURE() << where << ": not a root-relative path (includes name files from the repository root)";
            continue;
        }
        const std::string_view to = layer_of(table, edge.target);
        EXPECT_FALSE(to.empty()) << where << ": the included file lies in no layer";
        if (from.empty() || to.empty()) continue;
        EXPECT_TRUE(may_include(table, from, to)) << where << ": " << from << " -> " << to
                                                  << " is not an allowed edge (tests/source_tree/include_layers.cpp)";
        ++checked;
    }
    EXPECT_EQ(checked, edges.size());
}

}  // namespace
}  // namespace vkw::layers
