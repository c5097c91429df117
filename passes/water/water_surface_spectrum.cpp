// h0 rounded to fp32 and written once into a host-visible buffer (water_surface_spectrum.hpp).
#include "passes/water/water_surface_spectrum.hpp"

#include "engine/core/errors.hpp"

#include <complex>
#include <utility>

namespace vkw::passes {

OceanSpectrumBuffer::OceanSpectrumBuffer(const Context& context, std::shared_ptr<const FftOceanSpectrum> spectrum)
    : spectrum_(std::move(spectrum)) {
    if (!spectrum_ || spectrum_->h0.empty() || spectrum_->h0.size() != std::size_t(spectrum_->n) * spectrum_->n) {
        throw InternalError("OceanSpectrumBuffer: the spectrum must hold n * n modes");
    }
    curvature_rms_ = spectrum_->curvature_rms();
    const VkDeviceSize bytes = spectrum_->h0.size() * 2 * sizeof(float);
    buffer_ = Buffer(context, {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, /*host_visible=*/true}, "ocean h0");
    float* out = static_cast<float*>(buffer_.mapped());
    for (const std::complex<double>& mode : spectrum_->h0) {
        *out++ = static_cast<float>(mode.real());
        *out++ = static_cast<float>(mode.imag());
    }
}

fg::BufferHandle OceanSpectrumBuffer::import_into(fg::FrameGraph& graph) const {
    fg::ImportedBuffer imported{buffer_.handle(), buffer_.size()};
    imported.initial = {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT};
    return graph.import_buffer("ocean h0", imported);
}

}  // namespace vkw::passes
