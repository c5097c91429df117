#include "engine/image/pixel_hash.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <string_view>

namespace vkw {
namespace {

class Fnv1a64 {
public:
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            hash_ ^= bytes[i];
            hash_ *= 1099511628211ull;  // FNV-1a prime
        }
    }
    void add(uint64_t value) { add(&value, sizeof value); }
    // A float's bits, so that -0 and 0, or two NaN payloads, hash apart as they differ on disk.
    void add(const std::vector<float>& values) {
        for (float value : values) add(std::bit_cast<uint32_t>(value));
    }
    void add(uint32_t value) { add(&value, sizeof value); }
    uint64_t value() const { return hash_; }

private:
    uint64_t hash_ = 14695981039346656037ull;  // FNV-1a offset basis
};

}  // namespace

std::string pixel_hash(const ImageRGBA32F& image) {
    Fnv1a64 hash;
    hash.add(static_cast<uint64_t>(image.width));
    hash.add(static_cast<uint64_t>(image.height));
    hash.add(image.rgba);
    // read_exr returns the layers sorted by name; a render may list them in another order.
    std::vector<const ExtraLayer*> layers;
    for (const ExtraLayer& layer : image.layers) layers.push_back(&layer);
    std::sort(layers.begin(), layers.end(), [](const ExtraLayer* a, const ExtraLayer* b) { return a->name < b->name; });
    for (const ExtraLayer* layer : layers) {
        hash.add(static_cast<uint64_t>(layer->name.size()));
        hash.add(layer->name.data(), layer->name.size());
        hash.add(layer->rgb);
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash.value()));
    return text;
}

}  // namespace vkw
