// The library's boundary: every public call runs its body through run_guarded, which turns
// vkwater's exceptions into a Status, so nothing is thrown into the host.
#pragma once

#include <vkwater/status.hpp>

#include <functional>

namespace vkwater::detail {

Status run_guarded(const std::function<void()>& body);

}  // namespace vkwater::detail
