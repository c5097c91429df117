// What an image a command writes says about how it was made: the EXR header's string attributes
// (docs/cli.md, "What an EXR file records"). The pixels never depend on them; bit-identity and
// every hash in the project are over pixel data.
#pragma once

#include "engine/image/image.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/scene/scene.hpp"

#include <string>
#include <vector>

namespace vkw::cli {

struct ImageProvenance {
    std::string scene_file;              // as the user named it
    std::vector<std::string> overrides;  // the --set values, in order
    std::string renderer;                // "real-time" or "reference"
    std::string filter;                  // e.g. "point: one sample at each pixel centre"
    std::string device;                  // the Vulkan device, or the reference's threads
    std::string time;                    // the frame's (or the whole reference's) time, with how it was measured
    std::string frame;                   // a sequence's frame: its number, range and water time; empty otherwise
    std::string render_scale;            // "0.5: rendered at 400x300, stretched bilinearly"; empty at 1
    std::string budget;                  // what --budget-ms chose, as the options that repeat it; empty without
};

// software, vkwater/scene, vkwater/sceneHash (FNV-1a of the file's bytes), vkwater/camera,
// vkwater/overrides (only when there are any), vkwater/renderer, vkwater/filter, vkwater/device,
// vkwater/time, vkwater/frame (only in a sequence), vkwater/renderScale (only below 1),
// vkwater/budget (only under --budget-ms).
std::vector<ImageAttribute> image_attributes(const ImageProvenance& provenance, const Camera& camera);

// Refuses (vkw::UserError naming both filters and the file) to compare a box-filtered image with a
// point-sampled reference: the two differ by the filter alone wherever the image has detail. A
// reference without vkwater/filter was point-sampled (it predates the attribute). A point image
// against a box reference is what the error tables measure, and allowed.
void require_comparable_filters(const PixelFilter& filter, const ImageRGBA32F& reference,
                                const std::string& reference_path);

}  // namespace vkw::cli
