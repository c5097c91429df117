// A typed blackboard through which passes hand their outputs to later passes
// without knowing who calls them. Keys are objects, not strings: each key has a
// type, and looking it up with another type does not compile.
//
//   inline constexpr fg::BlackboardKey<fg::ImageHandle> kHdrColor{"hdr color"};
//   blackboard.put(kHdrColor, handle);  ...  blackboard.get(kHdrColor)
#pragma once

#include "engine/core/errors.hpp"

#include <any>
#include <string>
#include <unordered_map>

namespace vkw::fg {

template <class T>
struct BlackboardKey {
    const char* name;  // for error messages only; the key's address identifies it
};

class Blackboard {
public:
    template <class T>
    void put(const BlackboardKey<T>& key, T value) {
        entries_[&key] = std::move(value);
    }

    template <class T>
    const T& get(const BlackboardKey<T>& key) const {
        auto entry = entries_.find(&key);
        if (entry == entries_.end()) {
            throw InternalError(std::string("blackboard: no pass has published '") + key.name + "'");
        }
        return std::any_cast<const T&>(entry->second);
    }

    template <class T>
    bool has(const BlackboardKey<T>& key) const {
        return entries_.count(&key) > 0;
    }

    void clear() { entries_.clear(); }

private:
    std::unordered_map<const void*, std::any> entries_;
};

}  // namespace vkw::fg
