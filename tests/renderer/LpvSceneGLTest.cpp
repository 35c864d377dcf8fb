// The LPV through the whole renderer on the Cornell box: the ceiling opened
// and a sun shining in, so the sunlit red (or green) wall must bleed its
// colour onto the white blocks. Runs on llvmpipe.
#include "GlFixture.h"
#include "OpenCornellBox.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/LpvSnapshot.h"
#include "lpv/renderer/lpv/SceneGeometryVolume.h"
#include "lpv/scene/CornellBox.h"

#include <cmath>
#include <iostream>

using namespace lpv;

namespace {

constexpr int kWidth = 320, kHeight = 240;

// The built-in Cornell box without its ceiling (its triangles collapsed to a
// point), lit by a sun that travels toward +x (sign +1: it lights the red
// wall) or -x (sign -1: the green wall).
scene::Project openCornellBox(float sign) {
    return test::openCornellBox(glm::vec3(0.55f * sign, -1.0f, 0.25f));
}

struct Frame {
    std::vector<float> hdr, albedo, normal;
};

Frame render(renderer::ForwardRenderer& r, const scene::Project& project, float lpvIntensity) {
    scene::ParameterSet params = project.parameters;
    EXPECT_TRUE(params.set("lpv.intensity", double(lpvIntensity)).has_value());
    r.setScene(project.scene);
    // Two frames: the geometry volume also takes the previous frame's G-buffer.
    for (int i = 0; i < 2; ++i) {
        auto ok = r.render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    return {r.readHdr(), r.readGBufferAlbedo(), r.readGBufferNormal()};
}

// Summed indirect light (with LPV minus without) over the white pixels whose
// normal faces +x (side > 0) or -x (side < 0).
glm::dvec3 indirectOnWhite(const Frame& with, const Frame& without, float side, int* count) {
    glm::dvec3 sum(0.0);
    *count = 0;
    for (std::size_t i = 0; i < std::size_t(kWidth) * kHeight; ++i) {
        const glm::vec3 albedo(with.albedo[4 * i], with.albedo[4 * i + 1], with.albedo[4 * i + 2]);
        const bool white = std::abs(albedo.r - 0.725f) < 0.02f && std::abs(albedo.g - 0.71f) < 0.02f;
        if (!white || with.normal[4 * i] * side < 0.5f)
            continue;
        ++*count;
        for (int c = 0; c < 3; ++c)
            sum[c] += double(with.hdr[4 * i + std::size_t(c)]) - double(without.hdr[4 * i + std::size_t(c)]);
    }
    return sum;
}

class LpvSceneGLTest : public GlTest {};

TEST_F(LpvSceneGLTest, CornellWallsBleedTheirColourOntoTheWhiteBlocks) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    for (float sign : {1.0f, -1.0f}) {
        const scene::Project project = openCornellBox(sign);
        const Frame without = render(*r, project, 0.0f);
        EXPECT_NE(r->lpvNote().find("off"), std::string::npos) << r->lpvNote();
        const Frame with = render(*r, project, 1.0f);
        EXPECT_NE(r->lpvNote().find("computeGather"), std::string::npos) << r->lpvNote();
        for (float v : with.hdr)
            ASSERT_TRUE(std::isfinite(v));
        int towardRedCount = 0, towardGreenCount = 0;
        // The red wall is at +x (its inside faces -x): white faces turned toward it have normals along +x.
        const glm::dvec3 towardRed = indirectOnWhite(with, without, 1.0f, &towardRedCount);
        const glm::dvec3 towardGreen = indirectOnWhite(with, without, -1.0f, &towardGreenCount);
        ASSERT_GT(towardRedCount, 200);
        ASSERT_GT(towardGreenCount, 200);
        const double redFacingRatio = towardRed.r / towardRed.g;     // R/G of the light on faces toward red
        const double greenFacingRatio = towardGreen.r / towardGreen.g; // ... toward green
        std::cout << "[ figures ] sun lights the " << (sign > 0 ? "red" : "green")
                  << " wall: indirect R/G on white faces toward red " << redFacingRatio << " (" << towardRedCount
                  << " px, mean " << towardRed.g / towardRedCount << "), toward green " << greenFacingRatio << " ("
                  << towardGreenCount << " px, mean " << towardGreen.g / towardGreenCount << ")\n";
        EXPECT_GT(towardRed.g, 0.0);
        EXPECT_GT(towardGreen.g, 0.0);
        if (sign > 0) {
            // The lit red wall: the faces turned to it get red-tinted indirect light.
            EXPECT_GT(redFacingRatio, 1.2);
            EXPECT_GT(redFacingRatio, 1.2 * greenFacingRatio);
        } else {
            // The lit green wall: the faces turned to it get green-tinted indirect light.
            EXPECT_LT(greenFacingRatio, 0.9);
            EXPECT_LT(greenFacingRatio * 1.2, redFacingRatio);
        }
    }
}

// Sky light: the open box (a courtyard) calls for it and gets bluish light on
// its white floor; the closed box (a room) does not call for it, and its
// image is the same with the setting off.
Frame renderWithSky(renderer::ForwardRenderer& r, const scene::Project& project, const char* sky,
                    std::string* decision) {
    scene::ParameterSet params = project.parameters;
    EXPECT_TRUE(params.setFromText("effects.skyInjection", sky, "test").has_value());
    r.setScene(project.scene);
    for (int i = 0; i < 2; ++i) {
        auto ok = r.render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    for (const auto& e : r.frameEffects())
        if (e.parameter == "effects.skyInjection")
            *decision = std::string(e.runs() ? "run: " : "skip: ") + e.reason;
    return {r.readHdr(), r.readGBufferAlbedo(), r.readGBufferNormal()};
}

// Summed HDR over white pixels facing up (the floor and the blocks' tops).
glm::dvec3 whiteFacingUp(const Frame& f) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < std::size_t(kWidth) * kHeight; ++i) {
        const bool white = std::abs(f.albedo[4 * i] - 0.725f) < 0.02f && std::abs(f.albedo[4 * i + 1] - 0.71f) < 0.02f;
        if (white && f.normal[4 * i + 1] > 0.9f)
            sum += glm::dvec3(f.hdr[4 * i], f.hdr[4 * i + 1], f.hdr[4 * i + 2]);
    }
    return sum;
}

TEST_F(LpvSceneGLTest, OpenCourtyardReceivesSkyLightClosedRoomDoesNot) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    std::string decision;

    scene::Project open = openCornellBox(1.0f);
    open.scene.sky = {glm::vec3(0.5f, 0.7f, 1.0f), 1.0f}; // the built-in box is an interior: no sky
    const glm::dvec3 openOff = whiteFacingUp(renderWithSky(*r, open, "off", &decision));
    const glm::dvec3 openAuto = whiteFacingUp(renderWithSky(*r, open, "auto", &decision));
    std::cout << "[ figures ] open box: sky " << decision << "; white floor HDR sum off " << openOff.b << " (blue), auto "
              << openAuto.b << "; added light r/g/b " << (openAuto - openOff).r << " / " << (openAuto - openOff).g
              << " / " << (openAuto - openOff).b << "\n";
    EXPECT_EQ(decision.rfind("run", 0), 0u) << decision;
    EXPECT_NE(r->lpvNote().find("sky light injected"), std::string::npos) << r->lpvNote();
    const glm::dvec3 added = openAuto - openOff;
    EXPECT_GT(added.b, 0.05 * openOff.b) << "the sky adds at least 5% on the floor";
    EXPECT_GT(added.b, 1.5 * added.r) << "and the added light has the sky's blue tint";

    // The closed box with a sun on its roof: the LPV runs, the sky is not called for.
    scene::Project closed = scene::makeCornellBoxProject();
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 3.0f;
    closed.scene.lights.push_back(sun);
    closed.scene.sky = open.scene.sky; // a sky there is, but the room is closed
    const Frame closedOff = renderWithSky(*r, closed, "off", &decision);
    const Frame closedAuto = renderWithSky(*r, closed, "auto", &decision);
    std::cout << "[ figures ] closed box: sky " << decision << "\n";
    EXPECT_EQ(decision.rfind("skip", 0), 0u) << decision;
    EXPECT_EQ(r->lpvNote().find("sky"), std::string::npos) << r->lpvNote();
    EXPECT_EQ(closedOff.hdr, closedAuto.hdr);
}

// "LPV: reused, nothing changed since the last frame": a frame whose scene,
// lights, LPV parameters, cascades and camera are the last frame's skips
// injection and propagation (no timer for them) and draws the same image;
// a change to any of them, or lpv.reuse = false, computes it again.
struct TimedFrame {
    std::vector<float> hdr;
    std::string note;
    bool lpvTimed = false;
};

TimedFrame timedFrame(renderer::ForwardRenderer& r, const scene::Project& project, const scene::ParameterSet& params) {
    r.timer().clearHistory();
    auto ok = r.render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
    EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    r.timer().resolveAll();
    TimedFrame f{r.readHdr(), r.lpvNote(), false};
    for (const auto& row : r.timer().table())
        f.lpvTimed |= row.samples > 0 && (row.pass == "lpvInjection" || row.pass == "lpvPropagation");
    return f;
}

// With the views' geometry volume (the RSM's and the camera's surfels) the
// second frame computes again: only then does the camera's G-buffer exist.
TEST_F(LpvSceneGLTest, ViewsGeometryVolumeRecomputesOnceTheCameraGBufferExists) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    scene::Project project = openCornellBox(1.0f);
    scene::ParameterSet params = project.parameters;
    ASSERT_TRUE(params.set("lpv.geometrySource", std::string("views")).has_value());
    r->setScene(project.scene);
    const TimedFrame first = timedFrame(*r, project, params);
    const TimedFrame second = timedFrame(*r, project, params);
    const TimedFrame third = timedFrame(*r, project, params);
    EXPECT_TRUE(first.lpvTimed);
    EXPECT_TRUE(second.lpvTimed) << second.note;
    EXPECT_FALSE(third.lpvTimed) << third.note;
    EXPECT_NE(second.note.find("and the camera"), std::string::npos) << second.note;
    EXPECT_EQ(third.hdr, second.hdr);
    // A moved object: computed, then once more with the G-buffer that shows it.
    project.scene.objects.back().transform.translation.x += 0.1f;
    r->updateObjects(project.scene);
    EXPECT_TRUE(timedFrame(*r, project, params).lpvTimed);
    EXPECT_TRUE(timedFrame(*r, project, params).lpvTimed);
    EXPECT_FALSE(timedFrame(*r, project, params).lpvTimed);
}

TEST_F(LpvSceneGLTest, UnchangedFrameReusesTheLpv) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    scene::Project project = openCornellBox(1.0f);
    scene::ParameterSet params = project.parameters;
    ASSERT_EQ(params.getEnum("lpv.geometrySource"), "scene");
    r->setScene(project.scene);
    const TimedFrame first = timedFrame(*r, project, params);
    // The scene's geometry volume does not read the camera's G-buffer, so the
    // second frame has nothing new to compute from.
    const TimedFrame second = timedFrame(*r, project, params);
    EXPECT_TRUE(first.lpvTimed);
    EXPECT_FALSE(second.lpvTimed) << second.note;
    EXPECT_EQ(second.note.rfind("LPV: reused, nothing changed since the last frame", 0), 0u) << second.note;
    EXPECT_NE(second.note.find("occlusion from the scene ("), std::string::npos) << second.note;
    EXPECT_EQ(second.hdr, first.hdr);

    // Exposure does not feed the LPV: still reused.
    ASSERT_TRUE(params.set("output.exposure", 1.0).has_value());
    EXPECT_FALSE(timedFrame(*r, project, params).lpvTimed);
    // A propagation parameter does.
    ASSERT_TRUE(params.set("lpv.propagationSteps", 6).has_value());
    EXPECT_TRUE(timedFrame(*r, project, params).lpvTimed);
    EXPECT_FALSE(timedFrame(*r, project, params).lpvTimed);
    // So does a light.
    project.scene.lights[0].intensity = 2.0f;
    EXPECT_TRUE(timedFrame(*r, project, params).lpvTimed);
    // And a moved object (the scene's geometry volume is sampled again).
    project.scene.objects.back().transform.translation.x += 0.1f;
    r->updateObjects(project.scene);
    EXPECT_TRUE(timedFrame(*r, project, params).lpvTimed);
    EXPECT_FALSE(timedFrame(*r, project, params).lpvTimed);
    // Turned off, every frame computes, and gets what the reused frame showed.
    const TimedFrame settled = timedFrame(*r, project, params);
    ASSERT_TRUE(params.set("lpv.reuse", false).has_value());
    const TimedFrame recomputed = timedFrame(*r, project, params);
    EXPECT_FALSE(settled.lpvTimed);
    EXPECT_TRUE(recomputed.lpvTimed);
    double maxDiff = 0.0;
    for (std::size_t i = 0; i < settled.hdr.size(); ++i)
        maxDiff = std::max(maxDiff, double(std::abs(settled.hdr[i] - recomputed.hdr[i])));
    std::cout << "[ figures ] reused against recomputed frame: max HDR difference " << maxDiff << "\n";
    EXPECT_LT(maxDiff, 1e-5);
}

} // namespace

// lpv.geometrySource = scene through the renderer: each cascade's geometry
// volume on the GPU is the CPU twin's window of the scene's world GV
// (lpvref::buildSceneGv, windowOf) under that cascade, float for float; the
// views' GV of the same frame differs (it lacks what the sun and the camera
// do not see: the blocks' hidden faces, the walls' backs).
TEST_F(LpvSceneGLTest, SceneGeometryVolumeIsTheCpuTwinsWindowOfEachCascade) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const scene::Project project = openCornellBox(1.0f);
    scene::ParameterSet params = project.parameters;
    // A cell size of its own (the fitted one follows the view): the twin
    // below needs the cascades' cells. The box's bounds start at the world
    // origin, so render space (RenderSpace.h) is world space here.
    ASSERT_TRUE(params.set("lpv.cellSize", 0.2).has_value());
    r->setScene(project.scene);
    const int cascades = params.getInt("lpv.cascades");
    std::vector<float> cellSizes;
    for (int k = 0; k < cascades; ++k)
        cellSizes.push_back(float(params.getFloat("lpv.cellSize")) * float(1 << k));
    const renderer::lpvref::SceneGv twin = renderer::lpvref::buildSceneGv(project.scene, cellSizes, std::size_t(1) << 24);
    double viewsDifference = 0.0;
    int holding = 0; // cascades that reach the box (the camera stands 8 m in front of it)
    for (int k = 0; k < cascades; ++k) {
        r->setLpvCapture(renderer::LpvCaptureRequest{k, 0});
        for (const char* source : {"views", "scene"}) {
            ASSERT_TRUE(params.set("lpv.geometrySource", std::string(source)).has_value());
            auto ok = r->render(project.scene, params, project.scene.cameras.front(), 96, 72);
            ASSERT_TRUE(ok.has_value()) << ok.error().describe();
            const renderer::LpvSnapshot* snapshot = r->lpvSnapshot();
            ASSERT_NE(snapshot, nullptr);
            const renderer::LpvGridFrame frame = r->lpvCascadeFrames().at(std::size_t(k));
            const renderer::lpvref::GvGrid expected = renderer::lpvref::windowOf(
                twin.levels[std::size_t(k)], {frame.origin, frame.cellSize, frame.gridSize});
            ASSERT_EQ(snapshot->geometry.size(), expected.potential.size());
            double difference = 0.0, total = 0.0;
            for (std::size_t i = 0; i < expected.potential.size(); ++i)
                for (int j = 0; j < 4; ++j) {
                    difference += std::abs(double(snapshot->geometry[i][j]) - double(expected.potential[i][j]));
                    total += std::abs(double(expected.potential[i][j]));
                }
            if (std::string(source) == "scene") {
                EXPECT_EQ(difference, 0.0) << "cascade " << k;
                holding += total > 1.0 ? 1 : 0;
            } else if (total > 0.0) {
                viewsDifference += difference / total;
            }
        }
    }
    std::cout << "[ figures ] views' GV against the scene's, summed relative difference over " << cascades
              << " cascades: " << viewsDifference << "\n";
    EXPECT_GE(holding, 2) << "the box must lie in some cascades, or this compares empty volumes";
    EXPECT_GT(viewsDifference, 0.1) << "the views see less of the box than the scene holds";
}
