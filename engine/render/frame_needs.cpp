#include "engine/render/frame_needs.hpp"

namespace vkw {

fg::FrameNeeds decide_frame_needs(const Scene&) { return {}; }

}  // namespace vkw
