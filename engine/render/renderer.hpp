// Renders a scene offscreen: builds the frame graph from the scene's needs, compiles
// it, runs it on the device and reads the HDR image back.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/image/image.hpp"
#include "engine/scene/scene.hpp"

#include <cstdint>

namespace vkw {

class Context;

struct RenderOptions {
    uint32_t width = 800;
    uint32_t height = 600;
    bool check_finite = false;
    // Tests use None: one submission, which synchronization validation can check whole.
    fg::TimingMode timing = fg::TimingMode::Auto;
    fg::RecordingKind recording = fg::RecordingKind::DynamicRendering;
};

struct RenderResult {
    ImageRGBA32F image;
    fg::FrameReport timing;
};

// Declares every pass of a frame into `graph`; the readback target is `readback`
// (VK_NULL_HANDLE is fine when the graph is only compiled and printed).
void build_frame_graph(fg::FrameGraph& graph, const Scene& scene, uint32_t width, uint32_t height,
                       VkBuffer readback);

class Renderer {
public:
    explicit Renderer(Context& context) : context_(context) {}
    RenderResult render(const Scene& scene, const RenderOptions& options);
    // Pipelines created so far; culled passes never add one.
    const fg::PipelineStore& pipelines() const { return pipelines_; }

private:
    Context& context_;
    fg::PipelineStore pipelines_;
};

}  // namespace vkw
