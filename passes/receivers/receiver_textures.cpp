#include "passes/receivers/receiver_textures.hpp"

#include "engine/vk/context.hpp"
#include "passes/receivers/texture_mips.hpp"

#include <cstring>

namespace vkw::passes {
namespace {

VkSamplerAddressMode address_mode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkSamplerCreateInfo sampler_info(const MeshTexture& texture) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = texture.magnify_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    info.minFilter = texture.minify_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    info.mipmapMode = texture.mipmap_linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = address_mode(texture.wrap_u);
    info.addressModeV = address_mode(texture.wrap_v);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    // glTF's NEAREST and LINEAR minification read the base level alone.
    info.maxLod = texture.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
    return info;
}

}  // namespace

ReceiverTextures::ReceiverTextures(Context& context, const std::vector<const MeshTexture*>& textures) {
    static const TextureImage kWhite{1, 1, {255, 255, 255, 255}};
    std::vector<const TextureImage*> images{&kWhite};
    textures_.push_back({Image(), Sampler(context, sampler_info(MeshTexture{}), "white receiver texture")});
    for (std::size_t i = 0; i < textures.size(); ++i) {
        images.push_back(textures[i]->image.get());
        textures_.push_back(
            {Image(), Sampler(context, sampler_info(*textures[i]), "receiver texture " + std::to_string(i))});
    }
    upload(context, images);
}

void ReceiverTextures::upload(Context& context, const std::vector<const TextureImage*>& images) {
    // Every level of every image in one staging buffer, copied in one submission.
    struct Copy {
        std::size_t texture;
        VkBufferImageCopy region;
    };
    std::vector<Copy> copies;
    std::vector<uint8_t> staged;
    for (std::size_t i = 0; i < images.size(); ++i) {
        const TextureImage& image = *images[i];
        const std::vector<MipLevel> levels = linear_mip_chain(image);
        const std::string name = i == 0 ? "white receiver texture" : "receiver texture " + std::to_string(i - 1);
        textures_[i].image =
            Image(context,
                  {image.width, image.height, VK_FORMAT_R16G16B16A16_SFLOAT,
                   VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, uint32_t(levels.size())},
                  name);
        for (uint32_t level = 0; level < levels.size(); ++level) {
            VkBufferImageCopy region{};
            region.bufferOffset = staged.size();
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
            region.imageExtent = {levels[level].width, levels[level].height, 1};
            copies.push_back({i, region});
            const auto* bytes = reinterpret_cast<const uint8_t*>(levels[level].rgba.data());
            staged.insert(staged.end(), bytes, bytes + levels[level].rgba.size() * sizeof(uint16_t));
        }
    }
    Buffer staging(context, {staged.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true}, "receiver texture staging");
    std::memcpy(staging.mapped(), staged.data(), staged.size());
    const auto barrier = [&](VkCommandBuffer cmd, const DeviceTexture& texture, bool before_copy) {
        VkImageMemoryBarrier2 image_barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        image_barrier.srcStageMask = before_copy ? VK_PIPELINE_STAGE_2_NONE : VK_PIPELINE_STAGE_2_COPY_BIT;
        image_barrier.srcAccessMask = before_copy ? VK_ACCESS_2_NONE : VK_ACCESS_2_TRANSFER_WRITE_BIT;
        image_barrier.dstStageMask =
            before_copy ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        image_barrier.dstAccessMask =
            before_copy ? VK_ACCESS_2_TRANSFER_WRITE_BIT : VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
        image_barrier.oldLayout = before_copy ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        image_barrier.newLayout =
            before_copy ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        image_barrier.srcQueueFamilyIndex = image_barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        image_barrier.image = texture.image.handle();
        image_barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, texture.image.desc().mip_levels, 0, 1};
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.imageMemoryBarrierCount = 1;
        dependency.pImageMemoryBarriers = &image_barrier;
        vkCmdPipelineBarrier2(cmd, &dependency);
    };
    context.submit_and_wait(
        [&](VkCommandBuffer cmd) {
            for (const DeviceTexture& texture : textures_) barrier(cmd, texture, true);
            for (const Copy& copy : copies) {
                vkCmdCopyBufferToImage(cmd, staging.handle(), textures_[copy.texture].image.handle(),
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy.region);
            }
            for (const DeviceTexture& texture : textures_) barrier(cmd, texture, false);
        },
        "receiver texture upload");
}

fg::DescriptorBinding ReceiverTextures::binding(int32_t index) const {
    const DeviceTexture& texture = textures_[std::size_t(index + 1)];
    fg::DescriptorBinding result;
    result.name = "base_color_texture";
    result.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    result.image = {texture.sampler.handle(), texture.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    return result;
}

}  // namespace vkw::passes
