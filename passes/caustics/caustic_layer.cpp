#include "passes/caustics/caustic_layer.hpp"

namespace vkw::passes {

void CausticLayerTarget::create(fg::PassBuilder& builder, const std::string& name, const fg::ImageInfo& info) {
    image = builder.color_attachment(builder.create_image(name, info), fg::LoadOp::Clear);
}

void CausticLayerTarget::load(fg::PassBuilder& builder, const fg::Blackboard& blackboard) {
    if (blackboard.has(keys::kCausticLayer)) {
        image = builder.color_attachment(blackboard.get(keys::kCausticLayer), fg::LoadOp::Load);
    }
}

void CausticLayerTarget::create_or_load(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool wanted) {
    if (blackboard.has(keys::kCausticLayer)) {
        load(builder, blackboard);
    } else if (wanted) {
        create(builder, "caustic layer", {VK_FORMAT_R32G32B32A32_SFLOAT});
    }
}

void CausticLayerTarget::publish(fg::Blackboard& blackboard) const {
    if (image) blackboard.put(keys::kCausticLayer, *image);
}

}  // namespace vkw::passes
