// The Radiosity dock on the Cornell box with coarse patches: run to the
// target, the progress bar, chart and preview fill, the solution is saved
// into the project's assets, and a second run resumes it. The solve uses its
// own EGL context, so Qt's offscreen platform is enough.
#include "RadiosityPanel.h"
#include "Document.h"

#include "lpv/radiosity/SolutionFile.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"

#include "TestPaths.h"

#include <QApplication>
#include <QLabel>
#include <QLineSeries>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv;

namespace {

QString runToStop(editor::RadiosityPanel& panel) {
    QSignalSpy spy(&panel, &editor::RadiosityPanel::stopped);
    panel.runButton()->click();
    EXPECT_TRUE(panel.running());
    EXPECT_EQ(panel.runButton()->text(), "Pause");
    EXPECT_TRUE(spy.wait(60000));
    return spy.isEmpty() ? QString() : spy.first().first().toString();
}

} // namespace

TEST(RadiosityPanel, RunsSavesAndResumes) {
    const auto dir = std::filesystem::path(test::kBinaryDir) / "tests" / "editor-radiosity";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto file = dir / "cornell.lpvproj";
    scene::Project project = scene::makeCornellBoxProject();
    ASSERT_TRUE(project.parameters.setFromText("radiosity.maxPatchArea", "0.5", "test").has_value());
    ASSERT_TRUE(project.parameters.setFromText("radiosity.hemicubeResolution", "32", "test").has_value());
    ASSERT_TRUE(project.parameters.setFromText("radiosity.convergenceThreshold", "0.2", "test").has_value());
    ASSERT_TRUE(scene::saveProject(project, file).has_value());

    editor::Document document;
    document.reset(project, QString::fromStdString(file.string()));
    editor::RadiosityPanel panel(&document);
    panel.show();

    const QString first = runToStop(panel);
    EXPECT_TRUE(first.startsWith("converged")) << first.toStdString();
    EXPECT_FALSE(panel.running());
    EXPECT_EQ(panel.runButton()->text(), "Run");
    EXPECT_EQ(panel.progressBar()->value(), panel.progressBar()->maximum());
    EXPECT_GT(panel.residualSeries()->count(), 0);
    EXPECT_FALSE(panel.previewImage().isNull());
    EXPECT_TRUE(std::filesystem::exists(radiosity::solutionPath(file)));
    const auto saved = radiosity::loadSolution(radiosity::solutionPath(file), project.scene.materials.size(),
                                               project.scene.objects.size());
    ASSERT_TRUE(saved.has_value());
    const auto shots = saved->state.shots;
    EXPECT_GT(shots, 0u);

    // Converged: a second run resumes the saved solution and stops at once.
    const QString second = runToStop(panel);
    EXPECT_TRUE(second.startsWith("converged")) << second.toStdString();
    const auto again = radiosity::loadSolution(radiosity::solutionPath(file), project.scene.materials.size(),
                                               project.scene.objects.size());
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(again->state.shots, shots);
}
