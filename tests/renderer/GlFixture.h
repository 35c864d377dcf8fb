#pragma once
#include "lpv/renderer/GlContext.h"

#include <gtest/gtest.h>

#include <optional>

// One headless context per test suite; a machine without any EGL/GL driver fails
// loudly (CI has Mesa llvmpipe, so every GL path must run there).
class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto ctx = lpv::renderer::HeadlessContext::create();
        ASSERT_TRUE(ctx.has_value()) << ctx.error().describe();
        context_.emplace(std::move(*ctx));
    }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override { ASSERT_TRUE(context_ && context_->makeCurrent()); }

    static inline std::optional<lpv::renderer::HeadlessContext> context_;
};
