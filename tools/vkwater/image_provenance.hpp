// What an image a command writes says about how it was made: the EXR header's string attributes
// (README "What an EXR file records"). The pixels never depend on them; bit-identity and
// every hash in the project are over pixel data.
#pragma once

#include "engine/image/image.hpp"
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
};

// software, vkwater/scene, vkwater/sceneHash (FNV-1a of the file's bytes), vkwater/camera,
// vkwater/overrides (only when there are any), vkwater/renderer, vkwater/filter, vkwater/device,
// vkwater/time.
std::vector<ImageAttribute> image_attributes(const ImageProvenance& provenance, const Camera& camera);

}  // namespace vkw::cli
