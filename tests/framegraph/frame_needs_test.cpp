// fg::FrameNeeds on its own and in the graph: a decision made again replaces the earlier one, a
// cleared FrameNeeds writes its next decisions' reasons into the strings the last ones left (the
// renderer decides every frame's needs that way, without allocating for them), and a graph takes
// its needs to decide only before its declaration's first pass or resource.
#include "tests/framegraph/framegraph_test_support.hpp"

namespace vkw::fg::test {
namespace {

// Longer than any short-string buffer, so that the reason lives on the heap.
const std::string kLongReason(200, 'r');

TEST(framegraph_needs, ADecisionMadeAgainReplacesTheEarlierOne) {
    FrameNeeds needs;
    needs.decide(Effect::SurfaceCaustics, true, "the sun is up");
    needs.decide(Effect::VolumeCaustics, false, "the medium does not scatter");
    needs.decide_in_place(Effect::SurfaceCaustics, false, /*forced=*/true) += "effects.caustics.mode = off";
    ASSERT_EQ(needs.decisions.size(), 2u);
    const EffectDecision* caustics = needs.find(Effect::SurfaceCaustics);
    ASSERT_NE(caustics, nullptr);
    EXPECT_FALSE(caustics->needed);
    EXPECT_TRUE(caustics->forced);
    EXPECT_EQ(caustics->reason, "effects.caustics.mode = off") << "the earlier reason was kept";
    EXPECT_FALSE(needs.needs(Effect::SurfaceCaustics));
    EXPECT_TRUE(needs.needs(Effect::Reflection)) << "an effect with no decision is needed";
}

TEST(framegraph_needs, AClearedNeedsWritesItsNextReasonsInTheLastOnesStrings) {
    FrameNeeds needs;
    needs.decide(Effect::SurfaceCaustics, true, kLongReason);
    needs.decide(Effect::VolumeCaustics, false, kLongReason);
    const char* first = needs.decisions[0].reason.data();
    const char* second = needs.decisions[1].reason.data();
    needs.clear();
    EXPECT_TRUE(needs.decisions.empty());
    EXPECT_EQ(needs.find(Effect::SurfaceCaustics), nullptr) << "clear() kept a decision";
    // The same decisions in the same order: each in the string its place had, with the new text.
    needs.decide(Effect::SurfaceCaustics, false, std::string(150, 'a'));
    std::string& written = needs.decide_in_place(Effect::VolumeCaustics, true);
    EXPECT_TRUE(written.empty()) << "the last reason's text was left in the string";
    written += "b";
    ASSERT_EQ(needs.decisions.size(), 2u);
    EXPECT_EQ(needs.decisions[0].reason.data(), first);
    EXPECT_EQ(needs.decisions[1].reason.data(), second);
    EXPECT_EQ(needs.decisions[0].reason, std::string(150, 'a'));
    EXPECT_EQ(needs.decisions[1].reason, "b");
    EXPECT_FALSE(needs.decisions[0].needed);
    EXPECT_TRUE(needs.decisions[1].needed);
    // A third decision finds no string left: it gets its own.
    needs.decide(Effect::Reflection, true, kLongReason);
    EXPECT_EQ(needs.decisions[2].reason, kLongReason);
}

TEST(framegraph_needs, AGraphTakesItsNeedsToDecideOnlyBeforeItsFirstPass) {
    FrameNeeds off;
    off.decide(Effect::SurfaceCaustics, false, kLongReason);
    FrameGraph graph(std::move(off));
    add_pass(graph, "splat", PassKind::Compute, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.side_effect();
        (void)builder.write_storage(builder.create_image("caustics", small_image()));
    });
    expect_contains(internal_error_of([&] { (void)graph.needs_to_decide(); }), {"before the declaration's first pass"});
    // clear() keeps the needs and their strings for the next declaration to decide again.
    const char* reason = graph.needs().decisions.at(0).reason.data();
    graph.clear();
    FrameNeeds& next = graph.needs_to_decide();
    EXPECT_EQ(&next, &graph.needs());
    next.clear();
    next.decide(Effect::SurfaceCaustics, true, kLongReason);
    EXPECT_EQ(graph.needs().decisions.at(0).reason.data(), reason);
    // clear(FrameNeeds) replaces them.
    graph.clear(FrameNeeds{});
    EXPECT_TRUE(graph.needs().decisions.empty());
}

}  // namespace
}  // namespace vkw::fg::test
