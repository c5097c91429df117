#include "passes/frame/scene_uploads.hpp"

#include "engine/water/fft_ocean.hpp"
#include "passes/receivers/receiver_meshes.hpp"
#include "passes/water/water_surface_spectrum.hpp"

#include <algorithm>

namespace vkw {

SceneUploads::SceneUploads(Context& context) : context_(context) {}

SceneUploads::~SceneUploads() = default;

std::shared_ptr<const passes::ReceiverMeshes> SceneUploads::receiver_meshes(const Scene& scene) {
    if (scene.receivers.empty()) return nullptr;
    const bool same_sizes = std::equal(
        receivers_vertices_.begin(), receivers_vertices_.end(), scene.receivers.begin(), scene.receivers.end(),
        [](size_t vertices, const Receiver& receiver) { return vertices == receiver.mesh.positions.size(); });
    if (!receivers_ || receivers_source_ != &scene || receivers_load_id_ != scene.load_id || !same_sizes) {
        receivers_ = std::make_shared<const passes::ReceiverMeshes>(context_, scene.receivers);
        receivers_source_ = &scene;
        receivers_load_id_ = scene.load_id;
        receivers_vertices_.clear();
        for (const Receiver& receiver : scene.receivers) receivers_vertices_.push_back(receiver.mesh.positions.size());
        ++receiver_uploads_;
    }
    return receivers_;
}

std::shared_ptr<const passes::OceanSpectrumBuffer> SceneUploads::ocean_spectrum(const Scene& scene) {
    if (!scene.water || scene.water->waves.model != WaveModel::FftOcean) return nullptr;
    // The spectrum the CPU bounds use too: a new one (new settings or seed) is a new pointer.
    std::shared_ptr<const FftOceanSpectrum> spectrum =
        shared_ocean_spectrum(scene.water->waves.ocean, scene.water->waves.seed);
    if (!ocean_ || spectrum != ocean_source_) {
        ocean_ = std::make_shared<const passes::OceanSpectrumBuffer>(context_, spectrum);
        ocean_source_ = std::move(spectrum);
    }
    return ocean_;
}

}  // namespace vkw
