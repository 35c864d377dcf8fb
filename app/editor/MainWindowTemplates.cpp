// Templates (the built-in Cornell box): opened as an untitled copy, so that
// a Save, a radiosity solve or a sweep never writes into the source or
// install tree the template lives in (issue #46).
#include "EventLog.h"
#include "MainWindow.h"

#include "lpv/app/BuiltInProjects.h"
#include "lpv/scene/CornellBox.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QStatusBar>

#include <filesystem>

namespace lpv::editor {

bool MainWindow::openTemplate(const QString& path, bool interactive) {
    auto loaded = scene::loadProject(path.toStdString());
    if (!loaded) {
        lastOpenError_ = QString::fromStdString(loaded.error().describe());
        statusBar()->showMessage(lastOpenError_);
        log_->add(EventLog::Severity::Error, tr("Open"), lastOpenError_);
        if (interactive)
            QMessageBox::critical(this, tr("Cannot open template"), lastOpenError_);
        return false;
    }
    // Meshes are in memory now; texture paths become absolute against the
    // template's folder, so the copy draws and saves them wherever it goes.
    document_->reset(std::move(*loaded), QString(), false, path);
    updateTitle();
    rebuildCamerasMenu();
    const QString message =
        tr("New project from the template %1: untitled until saved (Save asks where)").arg(path);
    statusBar()->showMessage(message);
    log_->add(EventLog::Severity::Info, tr("Open"), message);
    return true;
}

QString MainWindow::openBuiltInTemplate() {
    // Installed: <prefix>/share/lpvstudio/projects beside bin/; in the build folder: the source tree.
    const std::filesystem::path builtIn = app::findBuiltInProject(
        "cornell-box", std::filesystem::path(QCoreApplication::applicationDirPath().toStdU16String()));
    const QString file = QString::fromStdU16String(builtIn.u16string());
    if (!builtIn.empty() && openTemplate(file, false))
        return file;
    // No template file (or an unreadable one): the same box, made in code.
    showProject(scene::makeCornellBoxProject(), QString());
    return {};
}

} // namespace lpv::editor
