// The EXR attributes of a command's image (image_provenance.hpp).
#include "tools/vkwater/image_provenance.hpp"

#include "engine/scene/range.hpp"
#include "tools/reference/scene_hash.hpp"

#include <glm/glm.hpp>

namespace vkw::cli {

std::vector<ImageAttribute> image_attributes(const ImageProvenance& provenance, const Camera& camera) {
    std::vector<ImageAttribute> attributes = {
        {"software", "vkwater " VKWATER_VERSION},
        {"vkwater/scene", provenance.scene_file},
        {"vkwater/sceneHash", ref::scene_file_hash(provenance.scene_file)},
        {"vkwater/camera", "position " + format_vec3(camera.position) + " m, direction " +
                               format_vec3(glm::normalize(camera.target - camera.position)) + ", fov_y " +
                               format_number(camera.fov_y_deg) + " degrees"},
        {"vkwater/renderer", provenance.renderer},
        {"vkwater/filter", provenance.filter},
        {"vkwater/device", provenance.device},
        {"vkwater/time", provenance.time},
    };
    if (!provenance.overrides.empty()) {
        std::string joined;
        for (const std::string& text : provenance.overrides) joined += (joined.empty() ? "" : "; ") + text;
        attributes.push_back({"vkwater/overrides", joined});
    }
    return attributes;
}

}  // namespace vkw::cli
