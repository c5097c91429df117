// The typed blackboard keys through which passes find each other's outputs.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/handles.hpp"
#include "passes/caustics_camera_splats.hpp"
#include "passes/caustics_resolve.hpp"
#include "passes/sun_shadow.hpp"

namespace vkw::keys {

inline constexpr fg::BlackboardKey<fg::BufferHandle> kFrameConstants{"frame constants"};
inline constexpr fg::BlackboardKey<fg::ImageHandle> kHdrColor{"HDR colour"};
inline constexpr fg::BlackboardKey<fg::ImageHandle> kSceneDepth{"scene depth"};
inline constexpr fg::BlackboardKey<fg::BufferHandle> kSceneOptics{"scene optics"};
// R8_UNORM, output size: 1 where the pixel's camera ray starts in the water (published only
// while the stencil split runs; passes/water_volume_stencil.hpp).
inline constexpr fg::BlackboardKey<fg::ImageHandle> kCameraMedium{"camera medium"};
inline constexpr fg::BlackboardKey<passes::CausticMap> kCausticMap{"caustic map"};
// The camera-space splats instead of the map (effects.caustics.splat = camera-space): never both.
inline constexpr fg::BlackboardKey<passes::CameraCaustics> kCameraCaustics{"camera caustics"};
// RGBA32F, output size: the caustic layer (passes/caustic_layer.hpp), only when asked for.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kCausticLayer{"caustic layer"};
// RGBA32F, the refraction scene view's size: its caustic layer, while both are drawn.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kRefractionViewCaustic{"refraction view caustic layer"};
// Published only while the scene has receiver meshes and the sun is up (passes/sun_shadow.hpp).
inline constexpr fg::BlackboardKey<passes::SunShadowMap> kSunShadow{"sun shadow map"};

}  // namespace vkw::keys
