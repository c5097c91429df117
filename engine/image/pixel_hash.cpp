#include "engine/image/pixel_hash.hpp"

#include "engine/core/fnv1a.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace vkw {
namespace {

void add_count(Fnv1a64& hash, uint64_t count) { hash.add(&count, sizeof count); }

// Each float's bits, so that -0 and 0, or two NaN payloads, hash apart as they differ on disk.
void add_values(Fnv1a64& hash, const std::vector<float>& values) {
    for (const float value : values) {
        const uint32_t bits = std::bit_cast<uint32_t>(value);
        hash.add(&bits, sizeof bits);
    }
}

}  // namespace

std::string pixel_hash(const ImageRGBA32F& image) {
    Fnv1a64 hash;
    add_count(hash, static_cast<uint64_t>(image.width));
    add_count(hash, static_cast<uint64_t>(image.height));
    add_values(hash, image.rgba);
    // read_exr returns the layers sorted by name; a render may list them in another order.
    std::vector<const ExtraLayer*> layers;
    for (const ExtraLayer& layer : image.layers) layers.push_back(&layer);
    std::sort(layers.begin(), layers.end(), [](const ExtraLayer* a, const ExtraLayer* b) { return a->name < b->name; });
    for (const ExtraLayer* layer : layers) {
        add_count(hash, layer->name.size());
        hash.add(layer->name.data(), layer->name.size());
        add_values(hash, layer->rgb);
    }
    return hash.hex();
}

}  // namespace vkw
