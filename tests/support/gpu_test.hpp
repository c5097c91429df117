// Base fixture of every GPU test: a Vulkan context on the default device (lavapipe
// on CI) with the validation layer and synchronization validation. Any validation
// error or warning fails the test in TearDown, after the context is destroyed (so
// leaks reported at vkDestroyDevice count too).
#pragma once

#include "engine/vk/context.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace vkw::test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override {
        ContextOptions options;
        options.validation = true;
        options.print_validation_messages = false;
        context_ = std::make_unique<Context>(options);
        log_ = context_->shared_validation_log();
    }

    void TearDown() override {
        context_.reset();
        if (!expect_validation_messages_) {
            for (const std::string& message : log_->failures()) ADD_FAILURE() << message;
        }
    }

    // Destroys the context now and returns what validation reported.
    std::vector<std::string> finish_and_collect_validation() {
        context_.reset();
        expect_validation_messages_ = true;
        return log_->failures();
    }

    Context& context() { return *context_; }

private:
    std::unique_ptr<Context> context_;
    std::shared_ptr<ValidationLog> log_;
    bool expect_validation_messages_ = false;
};

}  // namespace vkw::test
