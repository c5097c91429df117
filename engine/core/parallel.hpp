// Work split over CPU threads, with a worker's exception brought back to the caller.
//
// A refusal raised on a worker thread (a UserError from a budget check, say) must reach the
// command's handler as it would from one thread: an exception that leaves a std::thread's
// function calls std::terminate instead. run_on_threads catches on every worker and rethrows
// the first once all have ended.
#pragma once

#include <algorithm>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace vkw {

// Every hardware thread of this machine (at least 1).
inline unsigned hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Calls work(0) on the calling thread and work(1) ... work(threads - 1) on threads of their
// own, waits for all, then rethrows the first exception any call threw. Every index runs once:
// those whose thread the system cannot start run on the calling thread after work(0).
template <class Work>
void run_on_threads(unsigned threads, Work&& work) {
    std::exception_ptr first;
    std::mutex first_guard;
    auto guarded = [&](unsigned index) {
        try {
            work(index);
        } catch (...) {
            std::lock_guard lock(first_guard);
            if (!first) first = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(threads > 0 ? threads - 1 : 0);
    unsigned started = 1;
    for (; started < threads; ++started) {
        try {
            pool.emplace_back(guarded, started);
        } catch (const std::system_error&) {
            break;  // the system's thread limit
        }
    }
    guarded(0);
    for (unsigned index = started; index < threads; ++index) guarded(index);
    for (std::thread& thread : pool) thread.join();
    if (first) std::rethrow_exception(first);
}

}  // namespace vkw
