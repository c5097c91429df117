// FNV-1a, 64 bits (Fowler, Noll and Vo): the fingerprint every vkwater hash of bytes uses (a scene
// file's, an image's pixels). Not cryptographic: it tells a changed input from the same one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace vkw {

class Fnv1a64 {
public:
    void add(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ ^= bytes[i];
            hash_ *= 1099511628211ull;  // the FNV prime
        }
    }
    void add_byte(unsigned char byte) { add(&byte, 1); }
    std::uint64_t value() const { return hash_; }
    // 16 hex digits, as the manifests and the EXR headers record it.
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
        return text;
    }

private:
    std::uint64_t hash_ = 14695981039346656037ull;  // the FNV offset basis
};

}  // namespace vkw
