// The scene analysis' decision for glossy LPV reflections: the threshold,
// the auto/on/off setting, and that without an LPV there is nothing to march.
#include "lpv/renderer/SceneAnalysis.h"

#include <gtest/gtest.h>

using namespace lpv;

TEST(GlossyDecision, AutoRunsAboveTheThresholdOnly) {
    renderer::SceneTraits traits;
    scene::ParameterSet params;
    ASSERT_TRUE(params.set("effects.glossyThreshold", 0.5).has_value());
    traits.maxGlossiness = 0.5f;
    auto d = renderer::decideGlossyReflections(traits, params, true, "");
    EXPECT_FALSE(d.runs());
    EXPECT_NE(d.reason.find("no visible material is glossy enough (glossiness up to 0.50, threshold 0.50)"),
              std::string::npos)
        << d.reason;
    traits.maxGlossiness = 0.6f;
    d = renderer::decideGlossyReflections(traits, params, true, "");
    EXPECT_TRUE(d.runs());
    EXPECT_TRUE(d.implemented);
    EXPECT_EQ(d.reason.rfind("a visible material is glossy (glossiness up to 0.60", 0), 0u) << d.reason;
}

TEST(GlossyDecision, NoLpvNothingToMarchEvenWhenForced) {
    renderer::SceneTraits traits;
    traits.maxGlossiness = 0.9f;
    scene::ParameterSet params;
    auto d = renderer::decideGlossyReflections(traits, params, false, "LPV: off (lpv.intensity is 0)");
    EXPECT_FALSE(d.runs());
    EXPECT_NE(d.reason.find("lpv.intensity is 0"), std::string::npos) << d.reason;
    ASSERT_TRUE(params.setFromText("effects.glossyReflections", "on", "test").has_value());
    d = renderer::decideGlossyReflections(traits, params, false, "LPV: off (lpv.intensity is 0)");
    EXPECT_FALSE(d.runs());
    EXPECT_EQ(d.reason.rfind("forced on by effects.glossyReflections, but the LPV does not run", 0), 0u)
        << d.reason;
    // Forced on with an LPV, it runs even for a scene below the threshold (the shader still skips such
    // materials).
    traits.maxGlossiness = 0.0f;
    EXPECT_TRUE(renderer::decideGlossyReflections(traits, params, true, "").runs());
    ASSERT_TRUE(params.setFromText("effects.glossyReflections", "off", "test").has_value());
    traits.maxGlossiness = 1.0f;
    EXPECT_FALSE(renderer::decideGlossyReflections(traits, params, true, "").runs());
}
