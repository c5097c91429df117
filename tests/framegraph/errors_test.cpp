// Graph-building mistakes the frame graph refuses with a short, precise InternalError:
// reading what nobody wrote, stale handles, duplicate pass names, two layouts in one pass.
#include "tests/framegraph/framegraph_test_support.hpp"

namespace vkw::fg::test {
namespace {

TEST(framegraph_errors, ReadingUnwrittenResource) {
    FrameGraph graph;
    add_pass(graph, "shade", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.side_effect();
        builder.sample(builder.create_image("hdr", small_image()));
    });
    const std::string message = internal_error_of([&] { graph.compile(64, 64); });
    expect_contains(message, {"'shade'", "'hdr'", "no pass writes before it"});
}

TEST(framegraph_errors, ReadModifyWriteOfUnwrittenBuffer) {
    FrameGraph graph;
    add_pass(graph, "accumulate", PassKind::Compute, [&](PassBuilder& builder) {
        graph.request_output(builder.read_write_storage(builder.create_buffer("photons", {4096})));
    });
    const std::string message = internal_error_of([&] { graph.compile(64, 64); });
    expect_contains(message, {"'accumulate'", "'photons'", "no pass writes before it"});
}

TEST(framegraph_errors, StaleHandleAfterWrite) {
    FrameGraph graph;
    ImageHandle first, second;
    add_pass(graph, "clear", PassKind::Graphics, [&](PassBuilder& builder) {
        first = builder.color_attachment(builder.create_image("caustics", small_image()));
    });
    add_pass(graph, "splat", PassKind::Graphics,
             [&](PassBuilder& builder) { second = builder.color_attachment(first, LoadOp::Load); });
    const std::string message = internal_error_of(
        [&] { add_pass(graph, "blur", PassKind::Compute, [&](PassBuilder& builder) { builder.sample(first); }); });
    expect_contains(message, {"'blur'", "stale handle", "'caustics'", "'splat'"});
    EXPECT_NE(second, first);
}

TEST(framegraph_errors, DuplicatePassName) {
    FrameGraph graph;
    add_pass(graph, "water", PassKind::Graphics, [](PassBuilder& builder) { builder.side_effect(); });
    const std::string message = internal_error_of(
        [&] { add_pass(graph, "water", PassKind::Graphics, [](PassBuilder& builder) { builder.side_effect(); }); });
    expect_contains(message, {"two passes", "'water'"});
}

TEST(framegraph_errors, OneImageInTwoLayoutsInOnePass) {
    FrameGraph graph;
    ImageHandle target;
    add_pass(graph, "clear", PassKind::Graphics, [&](PassBuilder& builder) {
        target = builder.color_attachment(builder.create_image("target", small_image()));
    });
    add_pass(graph, "feedback", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.sample(target);
        graph.request_output(builder.color_attachment(target, LoadOp::Load));
    });
    const std::string message = internal_error_of([&] { graph.compile(64, 64); });
    expect_contains(message,
                    {"'feedback'", "'target'", "two layouts", "SHADER_READ_ONLY_OPTIMAL", "COLOR_ATTACHMENT_OPTIMAL"});
}

TEST(framegraph_errors, CompiledBeforeCompileIsAnError) {
    FrameGraph graph;
    const std::string message = internal_error_of([&] { graph.compiled(); });
    expect_contains(message, {"compile()"});
}

}  // namespace
}  // namespace vkw::fg::test
