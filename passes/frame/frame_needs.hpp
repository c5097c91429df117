// The one function that decides, from the scene and its camera, which effects a
// frame needs, each with a human-readable reason, from conservative bounds: the
// water's box (its extent, and the mean level +- the surface's maximum amplitude),
// the camera's frustum and near-plane rectangle. effects.<name>.mode = on | off
// overrides a rule and is marked forced. Effects whose passes do not exist yet get no
// decision. `vkwater passes` prints the decisions.
#pragma once

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene.hpp"

#include <glm/glm.hpp>

#include <array>

namespace vkw {

fg::FrameNeeds decide_frame_needs(const Scene& scene, double aspect);

// The bounds the rules use, exposed for tests.
struct WaterBounds {
    glm::dvec3 lo, hi;  // axis-aligned box that holds the water body and every wave
};
WaterBounds water_bounds(const Scene& scene);
// World-space corners of the camera's near-plane rectangle.
std::array<glm::dvec3, 4> near_plane_corners(const Camera& camera, double aspect);

}  // namespace vkw
