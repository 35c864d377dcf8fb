#include "MainWindow.h"

#include "AboutDialog.h"
#include "Viewport.h"

#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

namespace lpv::editor {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    viewport_ = new Viewport(this);
    setCentralWidget(viewport_);
    frameLabel_ = new QLabel(this);
    statusBar()->addPermanentWidget(frameLabel_);
    connect(viewport_, &Viewport::frameTimed, this, [this](double ms, const QString& gl) {
        frameLabel_->setText(QString("GPU %1 ms  |  %2").arg(ms, 0, 'f', 2).arg(gl));
    });
    connect(viewport_, &Viewport::renderFailed, this,
            [this](const QString& message) { statusBar()->showMessage("Render error: " + message); });
    createMenus();
    resize(1280, 800);
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openDialog);
    open->setShortcut(QKeySequence::Open);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), qApp, &QApplication::quit);
    quit->setShortcut(QKeySequence::Quit);
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About LPV Studio"), this, [this] { AboutDialog(viewport_, this).exec(); });
}

void MainWindow::openDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), QFileInfo(projectPath_).path(),
                                                      tr("LPV Studio projects (*.lpvproj)"));
    if (!path.isEmpty())
        openProject(path);
}

bool MainWindow::openProject(const QString& path, bool interactive) {
    auto loaded = scene::loadProject(path.toStdString());
    if (!loaded) {
        const QString message = QString::fromStdString(loaded.error().describe());
        statusBar()->showMessage(message);
        if (interactive)
            QMessageBox::critical(this, tr("Cannot open project"), message);
        return false;
    }
    showProject(std::move(*loaded), path);
    return true;
}

void MainWindow::showProject(scene::Project project, const QString& path) {
    project_ = std::move(project);
    projectPath_ = path;
    setWindowTitle(QString("%1 - LPV Studio").arg(QString::fromStdString(project_.name)));
    statusBar()->showMessage(QString("%1: %2 triangles, %3 lights")
                                 .arg(path)
                                 .arg(project_.scene.triangleCount())
                                 .arg(project_.scene.lights.size()));
    viewport_->setProject(&project_, QFileInfo(path).absolutePath());
}

} // namespace lpv::editor
