// check_host_targets (host_targets.hpp).
#include "library/host_targets.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/resources.hpp"

#include <string>

namespace vkwater::detail {
namespace {

bool is_float_color(VkFormat format) {
    return format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R32G32B32A32_SFLOAT ||
           format == VK_FORMAT_B10G11R11_UFLOAT_PACK32;
}

// vkwater's short name of a format, or its VkFormat number where it has none.
std::string describe(VkFormat format) {
    const std::string name = vkw::format_name(format);
    return name == "format?" ? "VkFormat " + std::to_string(format) : name;
}

void require(bool condition, const std::string& message) {
    if (!condition) throw vkw::UserError("vkwater::Frame: " + message);
}

vkw::fg::ImportedImage imported(const Target& target) {
    vkw::fg::ImportedImage image;
    image.image = target.image;
    image.view = target.view;
    image.width = target.width;
    image.height = target.height;
    image.format = target.format;
    image.initial = {target.before.stages, target.before.access, target.before.layout};
    image.final_state = vkw::fg::AccessState{target.after.stages, target.after.access, target.after.layout};
    return image;
}

void check_common(const Target& target, const std::string& name) {
    require(target.image != VK_NULL_HANDLE && target.view != VK_NULL_HANDLE, name + ": image and view must be given");
    require(target.width > 0 && target.height > 0, name + ": size " + std::to_string(target.width) + "x" +
                                                       std::to_string(target.height) + " (accepted: at least 1x1)");
    require(target.after.layout != VK_IMAGE_LAYOUT_UNDEFINED && target.after.layout != VK_IMAGE_LAYOUT_PREINITIALIZED,
            name + ": after.layout " + std::to_string(target.after.layout) +
                " (accepted: a layout an image can be left in, not UNDEFINED or PREINITIALIZED)");
}

void check_format_feature(const vkw::Context& context, const Target& target, const std::string& name,
                          VkFormatFeatureFlags needed, const char* what) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physical_device(), target.format, &properties);
    require(
        (properties.optimalTilingFeatures & needed) == needed,
        name + ": format " + describe(target.format) + " cannot be " + what + " on '" + context.device_name() + "'");
}

}  // namespace

HostTargets check_host_targets(const vkw::Context& context, const Frame& frame) {
    check_common(frame.color, "color");
    check_common(frame.depth, "depth");
    require(is_float_color(frame.color.format),
            "color: format " + describe(frame.color.format) +
                " (accepted: RGBA16F, RGBA32F or B10G11R11_UFLOAT_PACK32: vkwater writes HDR radiance)");
    check_format_feature(context, frame.color, "color", VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT, "a colour attachment");
    require(vkw::format_is_depth(frame.depth.format),
            "depth: format " + describe(frame.depth.format) + " (accepted: a depth format such as D32F)");
    check_format_feature(context, frame.depth, "depth", VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         "a depth attachment");
    require(frame.depth.width == frame.color.width && frame.depth.height == frame.color.height,
            "depth: size " + std::to_string(frame.depth.width) + "x" + std::to_string(frame.depth.height) +
                " (accepted: the colour target's, " + std::to_string(frame.color.width) + "x" +
                std::to_string(frame.color.height) + ")");
    HostTargets targets{imported(frame.color), imported(frame.depth), std::nullopt};
    if (frame.caustic_layer.image != VK_NULL_HANDLE) {
        check_common(frame.caustic_layer, "caustic_layer");
        require(frame.caustic_layer.format == VK_FORMAT_R32G32B32A32_SFLOAT,
                "caustic_layer: format " + describe(frame.caustic_layer.format) + " (accepted: RGBA32F)");
        require(frame.caustic_layer.width == frame.color.width && frame.caustic_layer.height == frame.color.height,
                "caustic_layer: size " + std::to_string(frame.caustic_layer.width) + "x" +
                    std::to_string(frame.caustic_layer.height) + " (accepted: the colour target's)");
        targets.caustic_layer = imported(frame.caustic_layer);
    }
    return targets;
}

}  // namespace vkwater::detail
