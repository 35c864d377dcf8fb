#include "Viewport.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/scene/FramingCamera.h"

#include "lpv/renderer/GlContext.h"

#include <QSurfaceFormat>

namespace lpv::editor {

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
    QSurfaceFormat format;
    format.setVersion(4, 5);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    setFormat(format);
    setMinimumSize(320, 240);
}

Viewport::~Viewport() {
    // GL objects must die with their context current.
    makeCurrent();
    renderer_.reset();
    doneCurrent();
}

void Viewport::setProject(const scene::Project* project, const QString& projectDir) {
    project_ = project;
    projectDir_ = projectDir;
    sceneDirty_ = true;
    update();
}

void Viewport::initializeGL() {
    renderer::installDebugOutputIfRequested();
    const renderer::GlInfo info = renderer::queryCurrentGlInfo();
    glRenderer_ = QString::fromStdString(info.renderer + " | " + info.version);
    auto created = renderer::ForwardRenderer::create();
    if (!created) {
        lastError_ = QString::fromStdString(created.error().describe());
        emit renderFailed(lastError_);
        return;
    }
    renderer_.emplace(std::move(*created));
}

void Viewport::paintGL() {
    const GLuint target = defaultFramebufferObject();
    if (!renderer_ || !project_) {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    if (sceneDirty_) {
        // Missing textures draw as a placeholder; their warnings are not shown here yet.
        const auto textures = importers::loadSceneTextures(project_->scene, projectDir_.toStdString());
        renderer_->setScene(project_->scene, textures.images);
        framingCamera_ = scene::framingCamera(project_->scene);
        sceneDirty_ = false;
    }
    const scene::Scene& s = project_->scene;
    const scene::Camera& camera = s.cameras.empty() ? framingCamera_ : s.cameras.front();
    const int w = int(width() * devicePixelRatio()), h = int(height() * devicePixelRatio());
    auto ok = renderer_->render(s, project_->parameters, camera, w, h);
    if (!ok) {
        lastError_ = QString::fromStdString(ok.error().describe());
        emit renderFailed(lastError_);
        return;
    }
    renderer_->blitTo(target, w, h);
    double total = 0.0;
    for (const renderer::PassTiming& t : renderer_->timer().table())
        total += t.lastMs;
    emit frameTimed(total, glRenderer_);
}

} // namespace lpv::editor
