// run_guarded (status_from_exception.hpp).
#include "library/status_from_exception.hpp"

#include "engine/core/errors.hpp"

#include <exception>
#include <new>

namespace vkwater::detail {

Status run_guarded(const std::function<void()>& body) {
    try {
        body();
        return {};
    } catch (const vkw::UserError& error) {
        return {ErrorKind::InvalidInput, error.what()};
    } catch (const std::bad_alloc&) {
        return {ErrorKind::Internal, "out of host memory"};
    } catch (const std::exception& error) {
        // InternalError (a Vulkan call failed, the device lacks a feature) and anything unforeseen.
        return {ErrorKind::Internal, error.what()};
    } catch (...) {
        return {ErrorKind::Internal, "an unknown exception inside vkwater"};
    }
}

}  // namespace vkwater::detail
