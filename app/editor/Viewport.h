#pragma once
// The central 3D view: a QOpenGLWidget that drives the same renderer library
// as the CLI. It redraws only when something changed (Qt calls paintGL on
// update()), never in a busy loop.
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/Project.h"

#include <QOpenGLWidget>

#include <optional>

namespace lpv::editor {

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // The viewport shows `project` until the next call; it must outlive the
    // viewport's use of it. Its texture paths are relative to `projectDir`.
    void setProject(const scene::Project* project, const QString& projectDir = {});
    // Errors from GL set-up or rendering, empty if none.
    const QString& lastError() const { return lastError_; }

signals:
    // GPU time of the last frame in milliseconds (sum of pass medians).
    void frameTimed(double gpuMs, const QString& glRenderer);
    void renderFailed(const QString& message);

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    const scene::Project* project_ = nullptr;
    QString projectDir_;
    std::optional<renderer::ForwardRenderer> renderer_;
    scene::Camera framingCamera_; // used while the project has no camera
    bool sceneDirty_ = true;
    QString lastError_;
    QString glRenderer_;
};

} // namespace lpv::editor
