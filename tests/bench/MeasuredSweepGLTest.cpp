// bench::measureSweep: the references a sweep needs are traced first, one per
// like-for-like group, and every run lands in its combination's place.
#include "lpv/bench/MeasuredSweep.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv;

namespace {

bench::MeasuredSweepSpec cornell() {
    bench::MeasuredSweepSpec spec;
    spec.project = scene::makeCornellBoxProject();
    spec.camera = spec.project.scene.cameras.front();
    spec.width = 48;
    spec.height = 32;
    spec.frames = 1;
    spec.warmup = 1;
    spec.referenceSpp = 8;
    return spec;
}

} // namespace

// A radiosity solution holds every bounce: it gets a reference of its own
// (8 bounces, no sky), whatever lpv.bounces says.
TEST(MeasuredSweepGL, RadiosityGetsAManyBounceReferenceOfItsOwn) {
    bench::MeasuredSweepSpec spec = cornell();
    spec.combinations = {{}, {{"gi.method", "radiosity"}}, {{"gi.method", "radiosity"}, {"lpv.bounces", "2"}}};
    const auto groups = bench::groupByReference(spec);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (std::vector<int>{0}));
    EXPECT_EQ(groups[1], (std::vector<int>{1, 2}));
}

TEST(MeasuredSweepGL, EachBounceCountGetsItsOwnReferenceAndRunsKeepTheirOrder) {
    bench::MeasuredSweepSpec spec = cornell();
    spec.combinations = {{}, {{"lpv.bounces", "2"}}, {{"lpv.propagationSteps", "2"}}};
    const auto groups = bench::groupByReference(spec);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (std::vector<int>{0, 2}));
    EXPECT_EQ(groups[1], (std::vector<int>{1}));
    std::vector<int> done;
    std::vector<std::string> texts;
    bench::MeasuredSweepCallbacks callbacks;
    callbacks.runDone = [&](int index, const bench::SweepRun&, const std::vector<glm::vec3>& layer,
                            const std::vector<float>& coverage) {
        done.push_back(index);
        EXPECT_EQ(layer.size(), coverage.size());
    };
    double last = -1.0;
    callbacks.progress = [&](double f, const std::string& text) {
        EXPECT_GE(f, last) << "progress never goes back";
        last = f;
        texts.push_back(text);
        return true;
    };
    auto result = bench::measureSweep(spec, callbacks);
    ASSERT_TRUE(result.has_value()) << result.error().describe();
    EXPECT_EQ(result->references, 2);
    EXPECT_EQ(done, (std::vector<int>{0, 2, 1})) << "the first reference's group, then the second's";
    ASSERT_EQ(result->runs.size(), 3u);
    EXPECT_EQ(result->runs[1].bounces, 2);
    EXPECT_EQ(result->runs[2].settings, spec.combinations[2]);
    for (const auto& run : result->runs)
        EXPECT_TRUE(std::isfinite(run.indirect.mare));
    EXPECT_DOUBLE_EQ(last, 1.0);
    EXPECT_TRUE(std::ranges::any_of(texts, [](const std::string& t) { return t.find("Reference 2 of 2") == 0; }));
    EXPECT_TRUE(std::ranges::any_of(texts, [](const std::string& t) { return t.find("left)") != std::string::npos; }));
    EXPECT_EQ(result->reference.width, 48);
}

TEST(MeasuredSweepGL, StoppingWhileTheReferenceTracesRendersNothing) {
    bench::MeasuredSweepSpec spec = cornell();
    spec.referenceSpp = 1000;
    spec.combinations = {{}};
    int runs = 0;
    bench::MeasuredSweepCallbacks callbacks;
    callbacks.progress = [](double, const std::string& text) { return text.find("Reference") != 0; };
    callbacks.runDone = [&](int, const bench::SweepRun&, const auto&, const auto&) { ++runs; };
    auto result = bench::measureSweep(spec, callbacks);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, scene::ErrorCode::Cancelled);
    EXPECT_EQ(runs, 0);
}
