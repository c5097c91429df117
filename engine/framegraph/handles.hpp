// Typed, versioned resource handles. A write returns a new version; the old handle
// becomes stale, and using it is an error naming the pass and the resource. Images
// and buffers have distinct handle types, so one cannot be passed for the other.
#pragma once

#include <cstdint>
#include <limits>

namespace vkw::fg {

template <class Tag>
struct Handle {
    static constexpr uint32_t kInvalid = std::numeric_limits<uint32_t>::max();
    uint32_t index = kInvalid;  // which resource
    uint32_t version = 0;       // how many writes it had seen when this handle was made

    bool valid() const { return index != kInvalid; }
    bool operator==(const Handle&) const = default;
};

struct ImageTag {};
struct BufferTag {};
using ImageHandle = Handle<ImageTag>;
using BufferHandle = Handle<BufferTag>;

}  // namespace vkw::fg
