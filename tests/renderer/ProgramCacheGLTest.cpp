// ProgramCache (issue #23): variants built on first use and kept, uniform
// locations looked up once, compile errors as values; the LPV builds only
// the kernels its settings select.
#include "GlFixture.h"

#include "passes/lpv/LpvPass.h"
#include "gl/ProgramCache.h"

#include <gtest/gtest.h>

using namespace lpv;
using renderer::ProgramCache;

namespace {

class ProgramCacheGLTest : public GlTest {};

TEST_F(ProgramCacheGLTest, AVariantIsBuiltOnceAndItsUniformsLookedUpOnce) {
    ProgramCache cache;
    EXPECT_EQ(cache.size(), 0u);
    auto tonemap = cache.get({{"fullscreen.vert", "tonemap.frag"}, {}});
    ASSERT_TRUE(tonemap.has_value()) << tonemap.error().describe();
    auto again = cache.get({{"fullscreen.vert", "tonemap.frag"}, {}});
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(*tonemap, *again) << "the same variant is the same program";
    EXPECT_EQ(cache.size(), 1u);
    const GLint location = (*tonemap)->uniform("uExposure");
    EXPECT_GE(location, 0);
    EXPECT_EQ(location, glGetUniformLocation((*tonemap)->id(), "uExposure"));
    EXPECT_EQ((*tonemap)->uniform("uNoSuchUniform"), -1);
    // Another set of defines is another variant.
    auto gather = cache.get({{"lpv_gather.comp"}, {}});
    auto first = cache.get({{"lpv_gather.comp"}, {"LPV_FIRST_STEP 1"}});
    ASSERT_TRUE(gather.has_value() && first.has_value());
    EXPECT_NE(*gather, *first);
    EXPECT_EQ(cache.size(), 3u);
}

TEST_F(ProgramCacheGLTest, AVariantThatDoesNotBuildIsAnErrorAndNotCached) {
    ProgramCache cache;
    auto missing = cache.get({{"no_such_shader.comp"}, {}});
    ASSERT_FALSE(missing.has_value());
    EXPECT_NE(missing.error().describe().find("no_such_shader.comp"), std::string::npos) << missing.error().describe();
    EXPECT_EQ(cache.size(), 0u);
}

TEST_F(ProgramCacheGLTest, TheLpvBuildsOnlyTheKernelsItsSettingsSelect) {
    auto lpv = renderer::LpvPass::create();
    ASSERT_TRUE(lpv.has_value()) << lpv.error().describe();
    EXPECT_EQ(lpv->builtKernels(), 0u) << "creating the pass compiles nothing";
    renderer::LpvSettings settings; // compute gather, occlusion, one bounce, undirected
    settings.gridSize = 8;
    const std::vector<renderer::LpvCascade> cascades = {{glm::vec3(0.0f), 1.0f, 8}};
    ASSERT_TRUE(lpv->prepare(settings, cascades).has_value());
    const std::size_t gather = lpv->builtKernels();
    // flux max, inject, resolve; GV from the RSM and the camera, merge, face blocking; gather (2) and deinterleave.
    EXPECT_EQ(gather, 10u);
    ASSERT_TRUE(lpv->prepare(settings, cascades).has_value());
    EXPECT_EQ(lpv->builtKernels(), gather) << "a second frame builds nothing";
    settings.variant = renderer::LpvVariant::RasterScatter;
    ASSERT_TRUE(lpv->prepare(settings, cascades).has_value());
    EXPECT_EQ(lpv->builtKernels(), gather + 1) << "switching the variant builds that variant only";
}

} // namespace
