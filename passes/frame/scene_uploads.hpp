// The scene's static data on the device, made once and shared by every renderer on the device
// that is given the same SceneUploads: the embedding library's frames in flight, one renderer
// each, would otherwise each upload their own copy of the receiver meshes (a glTF model's
// vertices, indices and textures) and of the FFT ocean's spectrum.
//
// Each getter returns the data for the scene it is given, made again only when the scene's
// receivers or spectrum changed. A renderer keeps the shared_ptr it was given for as long as its
// compiled frames import the data, so a frame still in flight keeps the old meshes alive when
// another renderer has moved on to a new scene.
#pragma once

#include "engine/scene/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace vkw {
class Context;
struct FftOceanSpectrum;
}  // namespace vkw

namespace vkw::passes {
class ReceiverMeshes;
class OceanSpectrumBuffer;
}  // namespace vkw::passes

namespace vkw {

class SceneUploads {
public:
    explicit SceneUploads(Context& context);
    ~SceneUploads();

    // The scene's receiver meshes; null when it has none. Receivers are static: they are uploaded
    // once per scene object, load and mesh sizes (the budget draws a terrain with fewer cells,
    // set_terrain_detail, which changes its mesh's size).
    std::shared_ptr<const passes::ReceiverMeshes> receiver_meshes(const Scene& scene);
    // The FFT ocean's spectrum h0; null unless the water is the FFT ocean. Made again for a new
    // spectrum (new settings or seed).
    std::shared_ptr<const passes::OceanSpectrumBuffer> ocean_spectrum(const Scene& scene);

    // How many times receiver meshes were uploaded.
    size_t receiver_uploads() const { return receiver_uploads_; }

private:
    Context& context_;
    std::shared_ptr<const passes::ReceiverMeshes> receivers_;
    const void* receivers_source_ = nullptr;  // the scene whose receivers they are
    uint64_t receivers_load_id_ = 0;          // and its Scene::load_id
    std::vector<size_t> receivers_vertices_;  // each receiver's vertex count
    size_t receiver_uploads_ = 0;
    std::shared_ptr<const passes::OceanSpectrumBuffer> ocean_;
    std::shared_ptr<const FftOceanSpectrum> ocean_source_;  // the CPU spectrum it was made from
};

}  // namespace vkw
