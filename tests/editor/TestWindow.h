#pragma once
// What the editor's GUI tests share: the main window as every test drives it,
// the built-in Cornell template, and a scene imported as `lpv import` makes it.
#include "Autosave.h"
#include "MainWindow.h"

#include <QSize>
#include <QString>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace lpv::editor::test {

// The built-in Cornell box template in the source tree.
QString cornellTemplate();

// Imports `sceneUnderShared` (a path below ../shared/scenes, e.g.
// "sponza/sponza.obj") into `projectFile` with the real `lpv import`, as a
// user makes a project of their own scene.
::testing::AssertionResult importWithCli(const QString& sceneUnderShared, const QString& projectFile);

// Autosaves go to a folder of the test's own, never the user's; set before
// the window exists, so nothing it starts can write elsewhere.
struct TemporaryAutosaveRoot {
    QTemporaryDir dir;
    TemporaryAutosaveRoot() { Autosave::setRootForTests(dir.path()); }
};

// The main window as a test drives it: its own autosave folder, and an
// unsaved-changes prompt answered "discard" so that no modal box waits for a
// click nobody makes.
struct TestWindow : TemporaryAutosaveRoot {
    MainWindow window;
    TestWindow();
    // Opens `project`, sizes the window and shows it; fails where the open
    // fails or the window never appears.
    ::testing::AssertionResult openAndShow(const QString& project, QSize size);
    ::testing::AssertionResult show(QSize size);
};

} // namespace lpv::editor::test
