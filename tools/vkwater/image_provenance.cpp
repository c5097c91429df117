// The EXR attributes of a command's image (image_provenance.hpp).
#include "tools/vkwater/image_provenance.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/file_paths.hpp"
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
    if (!provenance.frame.empty()) attributes.push_back({"vkwater/frame", provenance.frame});
    if (!provenance.render_scale.empty()) attributes.push_back({"vkwater/renderScale", provenance.render_scale});
    if (!provenance.budget.empty()) attributes.push_back({"vkwater/budget", provenance.budget});
    return attributes;
}

void require_comparable_filters(const PixelFilter& filter, const ImageRGBA32F& reference,
                                const std::string& reference_path) {
    std::string text = PixelFilter{}.describe();  // references older than the attribute were point-sampled
    for (const ImageAttribute& attribute : reference.attributes) {
        if (attribute.name == "vkwater/filter") text = attribute.value;
    }
    if (filter.is_box() && pixel_filter_kind(text) != "box") {
        throw UserError("--reference " + quoted_path(reference_path) + ": its pixels are '" + text +
                        "', this render's are '" + filter.describe() +
                        "' (compare a box-filtered render with a box-filtered reference: vkwater reference --spp N)");
    }
}

}  // namespace vkw::cli
