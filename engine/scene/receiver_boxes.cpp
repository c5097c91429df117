#include "engine/scene/receiver_boxes.hpp"

#include <algorithm>
#include <cmath>

namespace vkw {

ReceiverBoxes receiver_boxes(const Scene& scene) {
    ReceiverBoxes boxes;
    for (const Receiver& receiver : scene.receivers) {
        if (receiver.mesh.positions.empty()) continue;  // nothing to meet
        const std::size_t slot = std::min(boxes.count, kReceiverBoxes - 1);
        if (slot == boxes.count) {
            boxes.lo[slot] = receiver.mesh.bounds_min;
            boxes.hi[slot] = receiver.mesh.bounds_max;
            ++boxes.count;
        } else {
            boxes.lo[slot] = glm::min(boxes.lo[slot], receiver.mesh.bounds_min);
            boxes.hi[slot] = glm::max(boxes.hi[slot], receiver.mesh.bounds_max);
        }
    }
    for (std::size_t i = 0; i < boxes.count; ++i) {
        // fp32 carries about 7 digits: 1e-5 of the largest coordinate is two orders above its
        // rounding, and the ray's origin and the slab's divisions round at that scale too.
        const glm::dvec3 largest = glm::max(glm::abs(boxes.lo[i]), glm::abs(boxes.hi[i]));
        const double margin = std::max(1e-4, 1e-5 * std::max({largest.x, largest.y, largest.z}));
        boxes.lo[i] -= margin;
        boxes.hi[i] += margin;
    }
    return boxes;
}

}  // namespace vkw
