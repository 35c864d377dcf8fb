#pragma once
#include "lpv/renderer/ForwardRenderer.h"
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

// A GlTest with a ForwardRenderer made for each test.
class RendererGLTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        auto r = lpv::renderer::ForwardRenderer::create();
        ASSERT_TRUE(r.has_value()) << r.error().describe();
        renderer_.emplace(std::move(*r));
    }
    std::optional<lpv::renderer::ForwardRenderer> renderer_;
};
