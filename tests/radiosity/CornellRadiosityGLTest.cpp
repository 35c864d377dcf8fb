// The Cornell box solved on the GPU with coarse patches: colour bleeding,
// save, reload and resume, and the display of the solution.
#include "GlFixture.h"

#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/renderer/GpuHemicube.h"
#include "lpv/renderer/RadiosityView.h"
#include "lpv/scene/CornellBox.h"

#include "TestPaths.h"

#include <filesystem>

using namespace lpv;

namespace {

constexpr float kPatchArea = 0.5f; // coarse: a few hundred patches keep llvmpipe fast

scene::Expected<radiosity::StopReason> solveTo(radiosity::RadiositySession& session, double residual) {
    auto h = renderer::GpuHemicube::create(session.mesh(), 64, 32);
    if (!h)
        return std::unexpected(h.error());
    radiosity::SolveOptions options;
    options.residualTarget = residual;
    options.shootersPerBatch = 32;
    return radiosity::solve(session.solver(), **h, options);
}

// A fresh solve as `lpv radiosity` starts it: the area light's direct light
// is the first shot (the ceiling quad is that light's surface and emits nothing).
radiosity::RadiositySession freshSession(const scene::Scene& scene) {
    auto created = radiosity::RadiositySession::create(scene, {}, kPatchArea, 1000000);
    EXPECT_TRUE(created.has_value()) << created.error().describe();
    return std::move(*created);
}

// Mean red/green ratio of the floor patches (white material) nearer the red
// wall (x > 2.78) and nearer the green wall.
std::pair<double, double> floorRedGreenRatios(const radiosity::RadiositySession& session,
                                              const scene::Scene& scene) {
    glm::dvec3 redSide(0.0), greenSide(0.0);
    for (std::size_t i = 0; i < session.mesh().size(); ++i) {
        const auto& p = session.mesh().patches[i];
        if (p.normal.y < 0.99f || p.center.y > 0.01f ||
            scene.materials[p.material].emissive != glm::vec3(0.0f))
            continue;
        const glm::dvec3 b(session.solver().state().radiosity[i]);
        (p.center.x > 2.78f ? redSide : greenSide) += b * double(p.area);
    }
    return {redSide.x / redSide.y, greenSide.x / greenSide.y};
}

} // namespace

class CornellRadiosityGLTest : public GlTest {};

TEST_F(CornellRadiosityGLTest, RedAndGreenWallsBleedOntoTheFloor) {
    const auto project = scene::makeCornellBoxProject();
    radiosity::RadiositySession session = freshSession(project.scene);
    ASSERT_FALSE(session.resumed());
    const auto reason = solveTo(session, 0.05);
    ASSERT_TRUE(reason.has_value()) << reason.error().describe();
    EXPECT_EQ(*reason, radiosity::StopReason::Converged);
    const auto [nearRed, nearGreen] = floorRedGreenRatios(session, project.scene);
    // The published red wall is at x = 0..., the green at x = 5.5 or the other way: one side is redder.
    EXPECT_GT(std::max(nearRed, nearGreen) / std::min(nearRed, nearGreen), 1.1);
    const auto& b = session.solver().state().balance;
    EXPECT_NEAR((b.absorbed + b.escaped + session.solver().unshotPower()).y, b.emitted.y, 1e-3 * b.emitted.y);
}

TEST_F(CornellRadiosityGLTest, SolutionIsSavedReloadedAndResumes) {
    const auto project = scene::makeCornellBoxProject();
    const auto dir = std::filesystem::path(test::kBinaryDir) / "tests" / "radiosity-cornell-resume";
    std::filesystem::remove_all(dir);
    const auto file = radiosity::solutionPath(dir / "cornell.lpvproj");

    radiosity::RadiositySession first = freshSession(project.scene);
    ASSERT_TRUE(solveTo(first, 0.3).has_value());
    const auto shots = first.solver().state().shots;
    const double residual = first.solver().residual();
    ASSERT_GT(shots, 0u);
    ASSERT_TRUE(radiosity::saveSolution(first.stored(), file).has_value());

    auto loaded = radiosity::loadSolution(file, project.scene.materials.size(), project.scene.objects.size());
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    radiosity::RadiositySession resumed(project.scene, {}, kPatchArea, std::move(*loaded));
    ASSERT_TRUE(resumed.resumed()) << resumed.note();
    EXPECT_EQ(resumed.solver().state().shots, shots);
    EXPECT_NEAR(resumed.solver().residual(), residual, 1e-9);
    EXPECT_EQ(resumed.solver().state().radiosity, first.solver().state().radiosity);

    const auto reason = solveTo(resumed, 0.1);
    ASSERT_TRUE(reason.has_value());
    EXPECT_EQ(*reason, radiosity::StopReason::Converged);
    EXPECT_GT(resumed.solver().state().shots, shots);
    EXPECT_LE(resumed.solver().residual(), 0.1);

    // A different patch size is another solution: it starts over and says so.
    auto again = radiosity::loadSolution(file, project.scene.materials.size(), project.scene.objects.size());
    ASSERT_TRUE(again.has_value());
    radiosity::RadiositySession other(project.scene, {}, 1.0f, std::move(*again));
    EXPECT_FALSE(other.resumed());
    EXPECT_NE(other.note().find("starting over"), std::string::npos);
    EXPECT_EQ(other.solver().state().shots, 0u);
}

TEST_F(CornellRadiosityGLTest, ViewShowsTheSolutionSmoothAndWithWireframe) {
    const auto project = scene::makeCornellBoxProject();
    radiosity::RadiositySession session = freshSession(project.scene);
    ASSERT_TRUE(solveTo(session, 0.2).has_value());
    auto view = renderer::RadiosityView::create();
    ASSERT_TRUE(view.has_value()) << view.error().describe();
    const auto& camera = project.scene.cameras.front();
    const int w = 96, h = 72;
    auto luminance = [&](const std::vector<std::uint8_t>& px) {
        double sum = 0.0;
        for (std::size_t i = 0; i < px.size(); i += 4)
            sum += px[i] + px[i + 1] + px[i + 2];
        return sum / double(w * h);
    };
    view->setPatches(session.mesh(), session.solver().state().radiosity, true);
    view->render(camera, w, h, 0.0f, false);
    const auto smooth = view->readDisplay();
    ASSERT_EQ(smooth.size(), std::size_t(w * h * 4));
    EXPECT_GT(luminance(smooth), 20.0); // lit, not black
    view->render(camera, w, h, 0.0f, true);
    EXPECT_NE(view->readDisplay(), smooth); // the wireframe shows
    view->setPatches(session.mesh(), session.solver().state().radiosity, false);
    view->render(camera, w, h, 0.0f, false);
    EXPECT_NE(view->readDisplay(), smooth); // flat patches differ from the smoothed corners
}
