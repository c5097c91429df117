// The typed blackboard: values round-trip by key, and a missing key is an error naming it.
#include "tests/framegraph/framegraph_test_support.hpp"

namespace vkw::fg::test {
namespace {

// Keys are identified by address, so they live for the whole program.
const BlackboardKey<ImageHandle> kHdr{"hdr color"};
const BlackboardKey<BufferHandle> kPhotons{"photons"};
const BlackboardKey<std::string> kNote{"note"};

TEST(framegraph_blackboard, PutGetRoundTrip) {
    Blackboard blackboard;
    blackboard.put(kHdr, ImageHandle{3, 2});
    blackboard.put(kPhotons, BufferHandle{5, 1});
    blackboard.put(kNote, std::string("caustics on"));
    EXPECT_EQ(blackboard.get(kHdr), (ImageHandle{3, 2}));
    EXPECT_EQ(blackboard.get(kPhotons), (BufferHandle{5, 1}));
    EXPECT_EQ(blackboard.get(kNote), "caustics on");
    EXPECT_TRUE(blackboard.has(kHdr));
}

TEST(framegraph_blackboard, PutReplacesValue) {
    Blackboard blackboard;
    blackboard.put(kHdr, ImageHandle{1, 0});
    blackboard.put(kHdr, ImageHandle{1, 1});
    EXPECT_EQ(blackboard.get(kHdr), (ImageHandle{1, 1}));
}

TEST(framegraph_blackboard, MissingKeyIsAnErrorNamingIt) {
    Blackboard blackboard;
    blackboard.put(kHdr, ImageHandle{0, 1});
    EXPECT_FALSE(blackboard.has(kPhotons));
    const std::string message = internal_error_of([&] { blackboard.get(kPhotons); });
    expect_contains(message, {"'photons'"});
}

TEST(framegraph_blackboard, FrameGraphOwnsOne) {
    FrameGraph graph;
    graph.blackboard().put(kHdr, ImageHandle{7, 0});
    EXPECT_EQ(graph.blackboard().get(kHdr), (ImageHandle{7, 0}));
}

}  // namespace
}  // namespace vkw::fg::test
