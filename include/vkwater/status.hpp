// How vkwater's public API reports failure: every call returns a Status (or a Result holding one),
// never throws into the host and never aborts it.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace vkwater {

enum class ErrorKind {
    None,
    // Something the host or its user can fix: a scene file, a field, a target of the wrong
    // format or size. The message names the file or argument, the value and the accepted range.
    InvalidInput,
    // The device or vkwater failed (a Vulkan call returned an error, a feature is missing).
    Internal,
};

struct Status {
    ErrorKind kind = ErrorKind::None;
    std::string message;  // one line; empty when ok

    bool ok() const { return kind == ErrorKind::None; }
    explicit operator bool() const { return ok(); }
};

// A value or the Status that says why there is none.
template <class T>
class Result {
public:
    Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit, as std::optional's
    Result(Status status) : status_(std::move(status)) {}

    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }
    const Status& status() const { return status_; }
    T& value() { return *value_; }
    const T& value() const { return *value_; }
    T* operator->() { return &*value_; }
    const T* operator->() const { return &*value_; }

private:
    std::optional<T> value_;
    Status status_;
};

}  // namespace vkwater
