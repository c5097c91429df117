// The FFT ocean's initial spectrum h0 on the device. h0 is computed once per (ocean settings,
// seed) on the CPU in double precision (engine/water/fft_ocean.hpp make_ocean_spectrum);
// this rounds it once to fp32 (re, im) pairs, in the CPU's layout, and writes it through a
// persistently mapped host-visible, host-coherent buffer when the object is made. Each
// frame's graph then imports the buffer: the GPU ocean evolves the very h0 that the CPU
// ocean evolves, so both are the same surface.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/fft_ocean.hpp"

#include <memory>

namespace vkw {
class Context;
}

namespace vkw::passes {

class OceanSpectrumBuffer {
public:
    OceanSpectrumBuffer(const Context& context, std::shared_ptr<const FftOceanSpectrum> spectrum);

    const FftOceanSpectrum& spectrum() const { return *spectrum_; }
    VkBuffer buffer() const { return buffer_.handle(); }
    double curvature_rms() const { return curvature_rms_; }  // the spectrum's, computed once

    // Imports the buffer into `graph` for reading by the ocean's spectrum kernel. Its initial
    // state is a host write (the constructor's memcpy): the graph derives the host-to-compute
    // barrier that makes the write visible. Later frames repeat that barrier although nothing
    // writes any more; it is cheap, and keeps one import valid for the first frame and all
    // others. No final state: the buffer is only read, and it stays as it is between frames.
    // The object must outlive the execution of every frame that imported it.
    fg::BufferHandle import_into(fg::FrameGraph& graph) const;

private:
    std::shared_ptr<const FftOceanSpectrum> spectrum_;
    Buffer buffer_;
    double curvature_rms_ = 0.0;
};

}  // namespace vkw::passes
