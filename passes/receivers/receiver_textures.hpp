// The receivers' base colour textures on the device: each MeshTexture as a linear half-float image
// with its whole mip chain (texture_mips.hpp) and a sampler of its glTF wrap and filter modes, uploaded once
// and left in SHADER_READ_ONLY_OPTIMAL, outside the frame graph (nothing writes them again). A 1 x 1
// white texture stands in for untextured parts, so that every mesh draw samples one.
#pragma once

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/mesh.hpp"
#include "engine/vk/resources.hpp"

#include <vector>

namespace vkw {
class Context;
}

namespace vkw::passes {

class ReceiverTextures {
public:
    ReceiverTextures(Context& context, const std::vector<const MeshTexture*>& textures);

    // textures[index], or the white texel for -1, for the mesh shaders' `base_color_texture`.
    fg::DescriptorBinding binding(int32_t index) const;

private:
    struct DeviceTexture {
        Image image;
        Sampler sampler;
    };
    void upload(Context& context, const std::vector<const TextureImage*>& images);
    std::vector<DeviceTexture> textures_;  // textures_[0] the white texel, then the meshes' in order
};

}  // namespace vkw::passes
