// What every pass that lights receivers reads besides the frame constants and the
// scene optics: the camera-medium split's per-pixel camera medium, the caustic map and the sun
// shadow map, each only while its passes run. One place declares them (under their names in
// shaders/receivers/lighting.glsl and its includes) and names the shader variant that matches
// (shaders/CMakeLists.txt).
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/receivers/sun_shadow.hpp"

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {

// Always the frame constants (vertex and fragment stages) and the scene optics; then whichever of
// these the frame has.
struct LightingInputs {
    bool camera_medium = false;    // the camera-medium split's per-pixel mask
    bool caustic_map = false;      // the caustic map and its light space
    bool camera_caustics = false;  // or the camera-space splats: their receivers' view and irradiance
    SunShadowReads sun_shadow;     // the sun's depth of the objects and its light space

    // Declares, as sampled/uniform reads of this pass, whichever the blackboard holds (the
    // caustic map or the camera-space splats light every receiver under the water, the floor and
    // the meshes alike).
    // Passes that do not draw the camera's pixels (the scene views) pass with_camera_medium = false.
    void declare(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool with_camera_medium = true);
    // `source` (a shader compiled with the lighting variants) with the macros of these inputs.
    ShaderVariant shader(const std::string& source) const;
};

}  // namespace vkw::passes
