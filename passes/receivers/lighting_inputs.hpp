// What every pass that lights receivers reads besides the frame constants and the
// scene optics: the camera-medium split's per-pixel camera medium, the caustic map and the sun
// shadow map, each only while its passes run. One place declares them, names the shader
// variant that matches (shaders/CMakeLists.txt) and binds them (bindings 3 to 7).
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/receivers/sun_shadow.hpp"

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {

struct LightingInputs {
    fg::BufferHandle constants;                     // binding 0: the frame constants (vertex and fragment)
    fg::BufferHandle optics;                        // binding 1: the scene optics
    std::optional<fg::ImageHandle> camera_medium;   // binding 3: the camera-medium split's mask
    std::optional<fg::BufferHandle> caustic_frame;  // binding 4: the caustic map's light space
    std::optional<fg::ImageHandle> caustic_map;     // binding 5: the caustic irradiance map
    // Or the camera-space splats: binding 4 their receivers' view, binding 5 their irradiance.
    std::optional<fg::ImageHandle> camera_caustic_receivers;
    std::optional<fg::ImageHandle> camera_caustics;
    SunShadowReads sun_shadow;  // bindings 6 and 7: the sun's depth of the objects and its light space

    // Declares, as sampled/uniform reads of this pass, whichever the blackboard holds (the
    // caustic map or the camera-space splats light every receiver under the water, the floor and
    // the meshes alike).
    // Passes that do not draw the camera's pixels (the scene views) pass with_camera_medium = false.
    void declare(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool with_camera_medium = true);
    // "<shader>.<variant>" for a shader compiled with the lighting variants.
    std::string shader(const std::string& base) const;
    void add_bindings(const fg::PassContext& context, std::vector<fg::DescriptorBinding>& bindings) const;
};

}  // namespace vkw::passes
