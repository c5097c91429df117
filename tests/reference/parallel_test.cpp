// engine/core/parallel.hpp: every index runs exactly once, and an exception thrown on a worker
// thread reaches the caller with its type (a UserError stays exit 1), where a plain std::thread
// would have called std::terminate (the reference's map builders refuse from worker threads).
#include "engine/core/parallel.hpp"
#include "engine/core/errors.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace vkw {
namespace {

TEST(parallel, EveryIndexRunsOnce) {
    for (unsigned threads : {1u, 2u, 7u}) {
        std::vector<std::atomic<int>> runs(threads);
        run_on_threads(threads, [&](unsigned index) { ++runs[index]; });
        for (unsigned index = 0; index < threads; ++index) EXPECT_EQ(runs[index].load(), 1) << index;
    }
}

TEST(parallel, AWorkersExceptionReachesTheCallerWithItsType) {
    std::atomic<int> finished{0};
    EXPECT_THROW(run_on_threads(4,
                                [&](unsigned index) {
                                    if (index == 3) throw UserError("refused on a worker");
                                    ++finished;
                                }),
                 UserError);
    EXPECT_EQ(finished.load(), 3);  // the others ran to their end before the rethrow
}

}  // namespace
}  // namespace vkw
