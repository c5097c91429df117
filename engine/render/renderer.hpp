// Renders a scene offscreen: decides the frame's needs, builds and compiles the frame
// graph, runs it on the device and reads the HDR image back. The compiled graph and
// its resources are kept and reused while the configuration (output size, needs,
// recording kind, check and timing modes) stays the same; only the frame constants
// change between such frames.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/image/image.hpp"
#include "engine/render/frame_constants.hpp"
#include "engine/scene/scene.hpp"
#include "engine/vk/resources.hpp"

#include <cstdint>
#include <memory>
#include <string>

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

namespace passes {
class OceanSpectrumBuffer;
class ReceiverMeshes;
}

// Declares every pass of a frame into `graph`. `constants` is read at record time.
// The readback target is `readback` (VK_NULL_HANDLE when the graph is only printed);
// `ocean` is the device copy of an FFT ocean's spectrum (nullptr for other waves);
// `receivers` the scene's receiver meshes on the device (nullptr when it has none).
void build_frame_graph(fg::FrameGraph& graph, const Scene& scene, const FrameConstants* constants, uint32_t width,
                       uint32_t height, VkBuffer readback, const passes::OceanSpectrumBuffer* ocean,
                       const passes::ReceiverMeshes* receivers);

class Renderer {
public:
    explicit Renderer(Context& context);
    ~Renderer();
    RenderResult render(const Scene& scene, const RenderOptions& options);

    // Pipelines created so far; culled passes never add one.
    const fg::PipelineStore& pipelines() const { return pipelines_; }
    // How many times a frame graph was compiled (once per configuration).
    size_t compile_count() const { return compile_count_; }

private:
    struct CompiledFrame;
    static std::string water_configuration(const Scene& scene);
    static std::string sun_shadow_configuration(const Scene& scene);
    const passes::OceanSpectrumBuffer* ocean_spectrum(const Scene& scene);
    const passes::ReceiverMeshes* receiver_meshes(const Scene& scene);
    Context& context_;
    fg::PipelineStore pipelines_;
    std::unique_ptr<FrameConstants> constants_;  // stable address, read when the frame records
    std::unique_ptr<CompiledFrame> frame_;
    std::unique_ptr<passes::OceanSpectrumBuffer> ocean_;  // the FFT ocean's h0 on the device
    std::string ocean_key_;                               // the settings it was made for
    std::unique_ptr<passes::ReceiverMeshes> receivers_;   // the scene's receiver meshes on the device
    const void* receivers_source_ = nullptr;              // the scene whose receivers they are
    size_t receivers_count_ = 0;
    size_t compile_count_ = 0;
};

}  // namespace vkw
