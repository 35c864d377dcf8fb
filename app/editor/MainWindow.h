#pragma once
#include "lpv/scene/Project.h"

#include <QMainWindow>

class QLabel;

namespace lpv::editor {

class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // Loads a project; on failure shows the loader's error and keeps the current one.
    bool openProject(const QString& path, bool interactive = true);
    // Shows a project that is not on disk (the built-in Cornell box when its file is missing).
    void showProject(scene::Project project, const QString& path);
    Viewport* viewport() const { return viewport_; }
    const scene::Project& project() const { return project_; }

private:
    void createMenus();
    void openDialog();

    scene::Project project_;
    QString projectPath_;
    Viewport* viewport_ = nullptr;
    QLabel* frameLabel_ = nullptr;
};

} // namespace lpv::editor
