// Renders a scene offscreen: decides the frame's needs, declares and compiles the frame
// graph, runs it on the device and reads the HDR image back. The graph is declared anew
// every frame (a few hundred microseconds of CPU); its device objects (transient images and
// buffers, their memory, render passes, pipelines) are kept and reused while the compiled
// graph's physical signature stays the same, as in Filament's frame graph.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/image/image.hpp"
#include "engine/scene/scene.hpp"
#include "engine/vk/resources.hpp"
#include "passes/caustics/caustic_map_carry.hpp"
#include "passes/caustics/caustics_read_region.hpp"
#include "passes/common/frame_constants.hpp"
#include "passes/frame/scene_uploads.hpp"
#include "passes/frame/temporal_accumulation.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vkw {

class Context;
struct FftOceanSpectrum;

enum class CausticMapCarry : uint8_t { None, Keep, Reuse };

// Temporal accumulation over the frames a renderer renders with it on, in order
// (passes/frame/temporal_accumulation.hpp).
struct TemporalOptions {
    bool enabled = false;
    // The least weight a frame gets: the first frames are a running mean (1 / n), later ones an
    // exponential one of about 1 / blend_floor frames, so that the picture follows the scene.
    double blend_floor = 0.1;
    bool clamp_history = true;  // off only in tests: the plain running mean
};

struct RenderOptions {
    uint32_t width = 800;
    uint32_t height = 600;
    bool check_finite = false;
    // Tests use None: one submission, which synchronization validation can check whole.
    fg::TimingMode timing = fg::TimingMode::Auto;
    fg::RecordingKind recording = fg::RecordingKind::DynamicRendering;
    // Also render the caustic layer (passes/caustics/caustic_layer.hpp) into the image's layer "caustic".
    bool caustic_layer = false;
    // Also render the in-scatter layer (keys::kInScatterLayer, passes/godrays/godrays_composite.hpp)
    // into the image's layer "inscatter" when the godrays run; a frame without them has no such layer.
    bool inscatter_layer = false;
    // The scene's passes render at this fraction of width x height per side, in (0, 1], and the
    // frame is stretched to width x height at its end (passes/frame/upscale.hpp), layers included.
    double render_scale = 1.0;
    // The sub-frames of a supersampled frame (passes/frame/supersampled_frame.hpp) share one
    // light-space caustic map (passes/caustics/caustic_map_carry.hpp): Keep makes it for the
    // cameras of every sub-frame (`sub_frame_shifts`, each a Camera::image_shift_ndc) and keeps it;
    // Reuse reads the kept one instead of tracing the photons again.
    CausticMapCarry caustic_map_carry = CausticMapCarry::None;
    std::vector<glm::dvec2> sub_frame_shifts;
    // On: this frame, whose camera the caller has shifted by Renderer::next_temporal_shift (as a
    // box filter's sub-frames are shifted), is blended into the colour the renderer accumulated over
    // the frames before it, reprojected to this camera; off: the frame as it is, and the accumulated
    // colour is forgotten.
    TemporalOptions temporal;
};

struct RenderResult {
    ImageRGBA32F image;
    fg::FrameReport timing;
};

namespace passes {
class OceanSpectrumBuffer;
class ReceiverMeshes;
}  // namespace passes

// The last passes of a frame in place of the readback, for a caller that keeps or shows the
// image itself (the window hands the HDR colour on to its present graph).
struct FrameOutput {
    std::function<void(fg::FrameGraph& graph, fg::ImageHandle hdr)> add_passes;
    // The frame also renders the caustic layer (keys::kCausticLayer on the graph's blackboard) for
    // `add_passes` to hand on (the embedding library's optional output).
    bool caustic_layer = false;
};

// Declares every pass of a frame into `graph`. `constants` is read at record time.
// The readback target is `readback` (VK_NULL_HANDLE when the graph is only printed);
// `ocean` is the device copy of an FFT ocean's spectrum (nullptr for other waves);
// `receivers` the scene's receiver meshes on the device (nullptr when it has none);
// `output`, when given, ends the frame instead of the readback (which is then unused);
// `layers`' buffers, when given (and no `output`), receive the caustic layer
// (passes/caustics/caustic_layer.hpp) and the in-scatter layer (passes/godrays/godrays_composite.hpp),
// which the frame then renders (the in-scatter layer only where the godrays run).
// `width` x `height` is the size the scene's passes render at; `output`, when larger, the size the
// frame's image and layers are stretched to before the readback or `output`'s passes.
// What the photon pass's culling needs to know of the frame (passes/caustics/caustics_read_region.hpp):
// the camera at `aspect`, the waves' bounds (`amplitude`, the slope from the wave model), the
// lowest receiver, and from `needs` whether a ray can start in the water and whether the blur runs.
passes::CausticReadInputs caustic_read_inputs(const Scene& scene, double aspect, const fg::FrameNeeds& needs,
                                              double amplitude, double lowest_receiver);

struct LayerReadbacks {
    VkBuffer caustic = VK_NULL_HANDLE;
    VkBuffer inscatter = VK_NULL_HANDLE;
};

// The caustic map carried between the sub-frames of a supersampled frame (RenderOptions::caustic_map_carry).
struct CausticMapCarrying {
    CausticMapCarry mode = CausticMapCarry::None;
    // The kept image for a map of this size, made if need be (Keep); the kept one, or a null image
    // when none of that size is kept (Reuse: the map is then made as without carrying).
    std::function<fg::ImportedImage(const fg::ImageInfo&)> kept;
    std::vector<glm::dmat4> more_views;  // Keep: the other sub-frames' cameras, for the photon culling
};

void build_frame_graph(fg::FrameGraph& graph, const Scene& scene, const FrameConstants* constants, uint32_t width,
                       uint32_t height, VkBuffer readback, const passes::OceanSpectrumBuffer* ocean,
                       const passes::ReceiverMeshes* receivers, const FrameOutput* output = nullptr,
                       LayerReadbacks layers = {}, passes::CausticReadRegionCache* read_regions = nullptr,
                       VkExtent2D output_size = {0, 0}, const CausticMapCarrying* carry = nullptr,
                       const passes::TemporalInputs* temporal = nullptr);

class Renderer {
public:
    // `pipelines`: a store shared with other renderers on the same device (the embedding library's
    // frames in flight, one renderer each); pipelines never change once made, so sharing is safe.
    // `uploads`: the scene's static device data, shared the same way (scene_uploads.hpp).
    // None: the renderer's own.
    explicit Renderer(Context& context, std::shared_ptr<fg::PipelineStore> pipelines = nullptr,
                      std::shared_ptr<SceneUploads> uploads = nullptr);
    ~Renderer();
    RenderResult render(const Scene& scene, const RenderOptions& options);

    // The frame render() runs, with `output`'s passes instead of the readback, compiled (or
    // reused, as render() does) and handed to a caller that runs it alone (execute(): the
    // per-pass times) or records it into its own submission (record(cmd): the window's
    // frames, with its swapchain semaphores). Valid until the next call.
    fg::FrameExecutor& prepare_frame(const Scene& scene, const RenderOptions& options, const FrameOutput& output);
    // Waits for the device, then forgets the compiled frame and every pipeline, so that the
    // next frame re-reads the .spv files (the window's shader reload).
    void reload_shaders();

    // Pipelines created so far; culled passes never add one.
    const fg::PipelineStore& pipelines() const { return *pipelines_; }
    // How many times the frame's device objects were made: once per physical signature of the
    // compiled graph (output size, the passes that live, their resources), not per frame.
    size_t realize_count() const { return realize_count_; }
    // How many frames took the last frame's compiled graph over (fg::FrameGraph::compile): those
    // whose declaration compiled like the last one's, as with a running clock.
    size_t compilations_taken_over() const { return compilations_taken_over_; }
    // How many times the photon culling's read region was computed (it is reused while the camera stays).
    uint64_t read_regions_computed() const { return read_regions_.computed(); }
    // The CPU time of the last frame's needs decision, declaration and compilation, in milliseconds.
    double last_declare_ms() const { return last_declare_ms_; }
    // Frames accumulated so far with RenderOptions::temporal on (0 after a frame with it off).
    uint32_t temporal_frames() const { return temporal_.frames; }
    // The Camera::image_shift_ndc of the next temporal frame at width x height: its sub-pixel jitter
    // (passes/frame/temporal_accumulation.hpp). A temporal frame whose camera has another shift is
    // refused (InternalError).
    glm::dvec2 next_temporal_shift(uint32_t width, uint32_t height) const;
    // Forgets the accumulated colour: the next temporal frame starts afresh (a reloaded scene).
    void reset_temporal_history() { temporal_.frames = 0; }

private:
    struct CompiledFrame;
    struct Readback;
    CompiledFrame& prepare(const Scene& scene, const RenderOptions& options, const FrameOutput* output);
    CompiledFrame& prepare_graph(const Scene& scene, const RenderOptions& options, const FrameOutput* output,
                                 const passes::TemporalInputs* temporal);
    fg::ImportedImage temporal_history(uint32_t width, uint32_t height);
    void forget_compiled_frames();
    const Readback& readback_targets(const RenderOptions& options, bool window_output);
    const passes::OceanSpectrumBuffer* ocean_spectrum(const Scene& scene);
    const passes::ReceiverMeshes* receiver_meshes(const Scene& scene);
    fg::ImportedImage kept_caustic_map(const fg::ImageInfo& info, CausticMapCarry mode);
    Context& context_;
    std::shared_ptr<fg::PipelineStore> pipelines_;
    std::shared_ptr<SceneUploads> uploads_;
    std::unique_ptr<FrameConstants> constants_;  // stable address, read when the frame records
    std::unique_ptr<Readback> readback_;         // declared before compiled_: destroyed after them
    // Per RenderOptions::caustic_map_carry: the frame's declaration and the objects that run it.
    std::array<std::unique_ptr<CompiledFrame>, 3> compiled_;
    // The graph a compiled frame ran before its last one, emptied (FrameGraph::clear): the next
    // frame is declared into its storage, so that declaring allocates next to nothing.
    std::unique_ptr<fg::FrameGraph> spare_graph_;
    // What the compiled frames import from uploads_: held while they may run.
    std::shared_ptr<const passes::OceanSpectrumBuffer> ocean_;  // the FFT ocean's h0 on the device
    std::shared_ptr<const passes::ReceiverMeshes> receivers_;   // the scene's receiver meshes on the device
    passes::CausticReadRegionCache read_regions_;               // the photon culling's region, while the camera stays
    std::unique_ptr<Image> kept_caustic_map_;                   // RenderOptions::caustic_map_carry's map
    struct TemporalState {
        std::unique_ptr<Image> history;      // the colour accumulated so far, the output's size
        uint32_t frames = 0;                 // frames in it
        glm::dmat4 previous_view_proj{1.0};  // the last frame's camera, unjittered
    } temporal_;
    size_t realize_count_ = 0;
    size_t compilations_taken_over_ = 0;
    double last_declare_ms_ = 0.0;
};

}  // namespace vkw
