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
// The same into `needs`, cleared first: decisions made again in the same order write their reasons
// into the strings the last ones left (fg::FrameNeeds::clear), which is how the renderer decides
// every frame's needs without allocating for them.
void decide_frame_needs(const Scene& scene, double aspect, fg::FrameNeeds& needs);

// The bounds the rules use, exposed for tests.
struct WaterBounds {
    glm::dvec3 lo, hi;  // axis-aligned box that holds the water body and every wave
};
WaterBounds water_bounds(const Scene& scene);
// The godrays' rule leaves them out where, at most, they would change a pixel's radiance by this
// fraction: no channel of the PNG preview (engine/image/tone_curve.hpp, at any exposure) moves by
// half a step. The curve's steepest point, 72.9 steps per unit of log radiance at 0.169 exposed,
// gives 0.5 / 72.9 = 0.00686; this is 0.5 / 73 (tests/godrays/godrays_needs_test.cpp checks it).
inline constexpr double kGodraysInvisibleChange = 0.5 / 73.0;
// World-space corners of the camera's near-plane rectangle.
std::array<glm::dvec3, 4> near_plane_corners(const Camera& camera, double aspect);

}  // namespace vkw
