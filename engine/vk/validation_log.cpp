#include "engine/vk/validation_log.hpp"

#include <cstdio>

namespace vkw {

void ValidationLog::record_failure(std::string message) {
    std::lock_guard lock(mutex_);
    if (echo_) std::fprintf(stderr, "%s\n", message.c_str());
    failures_.push_back(std::move(message));
}

void ValidationLog::record_accepted(std::string) {
    std::lock_guard lock(mutex_);
    ++accepted_;
}

size_t ValidationLog::failure_count() const {
    std::lock_guard lock(mutex_);
    return failures_.size();
}

std::vector<std::string> ValidationLog::failures() const {
    std::lock_guard lock(mutex_);
    return failures_;
}

size_t ValidationLog::accepted_count() const {
    std::lock_guard lock(mutex_);
    return accepted_;
}

void ValidationLog::clear() {
    std::lock_guard lock(mutex_);
    failures_.clear();
    accepted_ = 0;
}

}  // namespace vkw
