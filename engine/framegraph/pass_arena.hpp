// Storage for what a frame's passes capture: each pass's Data struct and its execute function,
// made in blocks that outlive one declaration. The renderer declares its graph every frame;
// with a heap allocation per pass for each of the two (std::make_shared, std::function), the
// declaration spent about a third of its instructions in malloc and free. A graph declared
// again into the same storage (FrameGraph::clear) finds the blocks already there.
//
// Objects are constructed in place and destroyed, newest first, by clear() or the arena's
// destructor; their addresses stay valid until then (blocks never move).
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace vkw::fg {

class PassArena {
public:
    PassArena() = default;
    PassArena(const PassArena&) = delete;
    PassArena& operator=(const PassArena&) = delete;
    PassArena(PassArena&&) = default;
    PassArena& operator=(PassArena&& other) noexcept {
        destroy_all();
        blocks_ = std::move(other.blocks_);
        destructors_ = std::move(other.destructors_);
        block_ = other.block_;
        used_ = other.used_;
        return *this;
    }
    ~PassArena() { destroy_all(); }

    template <class T, class... Args>
    T& make(Args&&... args) {
        static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "blocks are aligned for new[]");
        void* place = allocate(sizeof(T), alignof(T));
        T* object = ::new (place) T(std::forward<Args>(args)...);
        if constexpr (!std::is_trivially_destructible_v<T>) {
            destructors_.push_back({object, [](void* p) { static_cast<T*>(p)->~T(); }});
        }
        return *object;
    }

    // Destroys every object made since the last clear; the blocks stay for the next declaration.
    void clear() {
        destroy_all();
        block_ = 0;
        used_ = 0;
    }

private:
    // A frame's passes capture a few KiB (the built-in scenes: about 30 passes of 50 to 300 bytes);
    // one block holds them all, and an object larger than a block gets a block of its own size.
    static constexpr size_t kBlockBytes = 16 * 1024;

    struct Block {
        std::unique_ptr<std::byte[]> bytes;
        size_t size;
    };
    struct Destructor {
        void* object;
        void (*destroy)(void*);
    };

    void* allocate(size_t size, size_t alignment) {
        for (; block_ < blocks_.size(); ++block_, used_ = 0) {
            const size_t start = (used_ + alignment - 1) / alignment * alignment;
            if (start + size <= blocks_[block_].size) {
                used_ = start + size;
                return blocks_[block_].bytes.get() + start;
            }
        }
        const size_t bytes = std::max(kBlockBytes, size);
        blocks_.push_back({std::make_unique<std::byte[]>(bytes), bytes});
        block_ = blocks_.size() - 1;
        used_ = size;
        return blocks_.back().bytes.get();
    }

    void destroy_all() {
        for (auto it = destructors_.rbegin(); it != destructors_.rend(); ++it) it->destroy(it->object);
        destructors_.clear();
    }

    std::vector<Block> blocks_;
    std::vector<Destructor> destructors_;
    size_t block_ = 0;  // the block that allocate() tries first
    size_t used_ = 0;   // bytes used in it
};

}  // namespace vkw::fg
