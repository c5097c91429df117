// The two sample programs' one shared piece of command-line parsing: a bounded count.
#pragma once

#include "errors.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace embed_host {

// `text` as an integer in [1, max], or a HostError naming `option`, the value and the range.
inline uint32_t parse_count(const std::string& option, const std::string& text, uint32_t max,
                            const std::string& usage) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0' || value < 1 || value > max) {
        throw HostError(option + " " + text + " (accepted: an integer in [1, " + std::to_string(max) + "])\n" + usage,
                        kExitInvalidInput);
    }
    return static_cast<uint32_t>(value);
}

}  // namespace embed_host
