// bench::runFlicker called in process: a camera that does not move gives no
// flicker, one that moves gives some, and a sun turn needs a sun.
#include "lpv/bench/FlickerSweep.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv;

namespace {

bench::FlickerSpec cornellAlong(glm::vec3 move) {
    bench::FlickerSpec spec;
    spec.project = scene::makeCornellBoxProject();
    spec.camera = spec.project.scene.cameras.front();
    spec.width = 64;
    spec.height = 48;
    spec.frames = 3;
    scene::CameraPath path;
    path.name = "test";
    for (int k = 0; k < 2; ++k) {
        scene::Camera at = spec.camera;
        at.position += float(k) * move;
        at.target += float(k) * move;
        path.keyframes.push_back(scene::keyframeFromCamera(at, float(k)));
    }
    spec.path = path;
    spec.fps = 4; // frames 0.25 s apart
    return spec;
}

} // namespace

TEST(FlickerSweepGL, AStillCameraHasNoFlickerAndAMovingOneHasSome) {
    auto still = bench::runFlicker(cornellAlong(glm::vec3(0.0f)), nullptr);
    ASSERT_TRUE(still.has_value()) << still.error().describe();
    ASSERT_EQ(still->runs.size(), 1u);
    EXPECT_LT(still->runs[0].meanFlicker, 1e-4) << "the same frame rendered again";
    EXPECT_GT(still->runs[0].keptFraction, 0.9);
    EXPECT_GT(still->runs[0].totalMs, 0.0);

    bench::FlickerSpec moving = cornellAlong(glm::vec3(0.8f, 0.0f, 0.0f));
    moving.combinations = {{{"lpv.cellSnapping", "true"}}, {{"lpv.cellSnapping", "false"}}};
    std::vector<std::string> labels;
    bench::FlickerCallbacks callbacks;
    callbacks.progress = [&](int, int, const std::string& label) {
        labels.push_back(label);
        return true;
    };
    auto moved = bench::runFlicker(moving, nullptr, callbacks);
    ASSERT_TRUE(moved.has_value()) << moved.error().describe();
    ASSERT_EQ(moved->runs.size(), 2u);
    EXPECT_EQ(labels, (std::vector<std::string>{"lpv.cellSnapping=true", "lpv.cellSnapping=false"}));
    for (const auto& run : moved->runs) {
        EXPECT_TRUE(std::isfinite(run.meanFlicker));
        EXPECT_GT(run.meanFlicker, still->runs[0].meanFlicker);
        EXPECT_GE(run.worstFlicker, run.meanFlicker);
    }
    const std::string md = bench::flickerMarkdown(moved->runs, "cmd", "machine", bench::describeMotion(moving));
    EXPECT_NE(md.find("camera path 'test', 3 frames at 4 fps"), std::string::npos) << md;
    EXPECT_NE(md.find("lpv.cellSnapping=false"), std::string::npos);
}

TEST(FlickerSweepGL, TurningTheSunNeedsASunAndTwoFrames) {
    bench::FlickerSpec spec = cornellAlong(glm::vec3(0.0f));
    spec.path.reset(); // the Cornell box is lit by an area light: nothing to turn
    auto result = bench::runFlicker(spec, nullptr);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("directional light"), std::string::npos);
    spec = cornellAlong(glm::vec3(0.0f));
    spec.frames = 1;
    EXPECT_FALSE(bench::runFlicker(spec, nullptr).has_value());
}
