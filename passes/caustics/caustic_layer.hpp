// The caustic layer (EXR channels caustic.R/G/B): per pixel,
// the sun's irradiance (W m^-2) on the receiver the pixel sees under the water (through the
// surface for a camera above it), 0 elsewhere: what `vkwater reference` writes beside its image,
// so that the caustics can be compared alone. Only when asked for (RenderOptions::caustic_layer).
// The passes that draw a pixel's receiver then write it as a second colour attachment, after
// their HDR colour, with their shaders' variants that define VKWATER_CAUSTIC_LAYER:
// - the first of the water and the floor creates it, cleared to 0 (the sky, receivers in the air
//   and the surface seen from below keep 0, as in the reference);
// - the other, and the receiver meshes, write their pixels over it;
// - the refraction scene view keeps a layer of its own (keys::kRefractionViewCaustic), which the
//   water reads at the texel where a refracted ray meets a mesh.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"

#include <optional>
#include <string>

namespace vkw::passes {

struct CausticLayerTarget {
    std::optional<fg::ImageHandle> image;

    // Creates the layer (RGBA32F, cleared to 0) as this pass's next colour attachment.
    void create(fg::PassBuilder& builder, const std::string& name, const fg::ImageInfo& info);
    // Declares the frame's layer (keys::kCausticLayer), if it has one, as this pass's next
    // colour attachment, loading what the passes before wrote.
    void load(fg::PassBuilder& builder, const fg::Blackboard& blackboard);
    // Loads the frame's layer if a pass before created it, else creates it when `wanted`.
    void create_or_load(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool wanted);
    // Publishes the written version under keys::kCausticLayer.
    void publish(fg::Blackboard& blackboard) const;
    // Whether the layer is written: then the pass's shaders define VKWATER_CAUSTIC_LAYER.
    bool written() const { return image.has_value(); }
};

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

// RGBA32F, output size: the caustic layer (passes/caustics/caustic_layer.hpp), only when asked for.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kCausticLayer{"caustic layer"};

}  // namespace vkw::keys
