// The device memory one rendered frame uses, for `vkwater bench`'s memory column: the frame
// graph's transient heap (the images and buffers the graph creates, with aliasing, at the
// sizes the device asked for) plus every imported buffer and image the frame reads or writes
// (the readback, the receiver meshes, an FFT ocean's spectrum). Pipelines, descriptor pools
// and the driver's own allocations are not counted.
#pragma once

#include <cstdint>

#include "passes/frame/renderer.hpp"

namespace vkw::bench {

struct FrameMemory {
    uint64_t transient_bytes = 0;  // the graph's transient heap, after aliasing
    uint64_t imported_bytes = 0;   // each imported buffer or image once, however many passes import it
    uint64_t total() const { return transient_bytes + imported_bytes; }
};

// Compiles the frame render(scene, options) runs (without running it) and measures it. The
// renderer's next render() compiles its own frame again.
FrameMemory measure_frame_memory(Renderer& renderer, const Scene& scene, const RenderOptions& options);

}  // namespace vkw::bench
