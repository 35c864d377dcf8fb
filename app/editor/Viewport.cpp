#include "Viewport.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Picking.h"
#include "lpv/scene/ProjectTextures.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QSurfaceFormat>
#include <QThread>
#include <QWheelEvent>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <memory>
#include <utility>

namespace lpv::editor {
namespace {

// A press that moves less than this is a click (selection), not a drag.
constexpr int kClickSlopPixels = 4;

// Whether every image `m` draws with is in `images` (under the keys the
// renderer looks up: derived images for height and colour-keyed maps).
bool texturesCached(const scene::Material& m, const scene::TextureImages& images) {
    for (const std::string* slot : scene::textureSlots(m))
        if (!slot->empty() && slot != &m.heightTexture && !images.contains(*slot))
            return false;
    if (!m.heightTexture.empty() && !images.contains(m.heightTexture + importers::kHeightNormalSuffix))
        return false;
    if (m.colorKey && !m.diffuseTexture.empty() && !images.contains(m.diffuseTexture + importers::kColorKeySuffix))
        return false;
    return true;
}

QColor axisColor(int axis, bool active) {
    static const QColor colors[3] = {QColor(230, 70, 60), QColor(90, 200, 80), QColor(70, 120, 240)};
    return active ? QColor(255, 220, 60) : colors[axis];
}

} // namespace

Viewport::Viewport(Document* document, QWidget* parent) : QOpenGLWidget(parent), document_(document) {
    QSurfaceFormat format;
    format.setVersion(4, 5);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    setFormat(format);
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    flyTimer_.setInterval(16);
    connect(&flyTimer_, &QTimer::timeout, this, &Viewport::flyStep);
    connect(document_, &Document::changed, this, &Viewport::onDocumentChanged);
    connect(document_, &Document::selectionChanged, this, [this] { update(); });
    onDocumentChanged(Change::Everything);
}

Viewport::~Viewport() {
    if (textureWorker_) {
        textureWorker_->wait(); // it writes only into its own result, but must end before the process
        delete textureWorker_;
    }
    // GL objects must die with their context current.
    makeCurrent();
    renderer_.reset();
    doneCurrent();
}

void Viewport::onDocumentChanged(Changes changes) {
    if (changes == Changes(Change::Everything)) {
        // A new project: start from its first camera, or one that frames the scene.
        const scene::Scene& s = document_->scene();
        controller_.setCamera(s.cameras.empty() ? scene::framingCamera(s) : s.cameras.front());
        controller_.setSceneBounds(s.worldBounds());
        emit viewCameraChanged();
    }
    pending_ |= changes;
    update();
}

void Viewport::setViewCamera(const scene::Camera& camera) {
    controller_.setCamera(camera);
    emit viewCameraChanged();
    update();
}

void Viewport::frameSelection() {
    const scene::Scene& s = document_->scene();
    const Selection& sel = document_->selection();
    scene::Bounds box = sel.isObject() ? scene::objectWorldBounds(s, sel.index) : s.worldBounds();
    if (sel.kind == Selection::Kind::Light && s.lights[std::size_t(sel.index)].type != scene::LightType::Directional) {
        const glm::vec3 p = s.lights[std::size_t(sel.index)].position;
        box = {};
        box.extend(p - glm::vec3(0.5f));
        box.extend(p + glm::vec3(0.5f));
    }
    controller_.frame(box);
    emit viewCameraChanged();
    update();
}

void Viewport::setGizmoMode(GizmoMode mode) {
    gizmoMode_ = mode;
    update();
}

void Viewport::setSplit(std::optional<std::pair<scene::ParameterSet, scene::ParameterSet>> presets, QString labelA,
                        QString labelB) {
    split_ = std::move(presets);
    splitLabels_[0] = std::move(labelA);
    splitLabels_[1] = std::move(labelB);
    update();
}

int Viewport::renderWidth() const { return std::max(1, int(width() * devicePixelRatio() * resolutionScale_)); }
int Viewport::renderHeight() const { return std::max(1, int(height() * devicePixelRatio() * resolutionScale_)); }

void Viewport::setResolutionScale(double scale) {
    resolutionScale_ = std::clamp(scale, 0.1, 1.0);
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
    renderer_->setLpvCapture(vizRequest_.lpv);
    renderer_->setShadowCascadeTint(vizRequest_.shadowTint);
    pending_ = Change::Everything;
}

void Viewport::requestMissingTextures() {
    if (textureWorker_) {
        texturesRequestedAgain_ = true; // once the running job is in
        return;
    }
    auto wanted = std::make_shared<scene::Scene>();
    for (const scene::Material& m : document_->scene().materials)
        if (!texturesCached(m, textures_))
            wanted->materials.push_back(m);
    if (wanted->materials.empty())
        return;
    emit texturesLoading(int(wanted->materials.size()));
    const std::string dir = document_->projectDir().toStdString();
    auto decoded = std::make_shared<importers::SceneTextures>();
    textureWorker_ = QThread::create([wanted, dir, decoded] { *decoded = importers::loadSceneTextures(*wanted, dir); });
    connect(textureWorker_, &QThread::finished, this, [this, decoded] {
        textureWorker_->deleteLater();
        textureWorker_ = nullptr;
        textures_.merge(decoded->images);
        QStringList warnings;
        for (const std::string& w : decoded->warnings)
            warnings << QString::fromStdString(w);
        emit texturesLoaded(warnings);
        pending_ |= Change::Materials;
        update();
        if (std::exchange(texturesRequestedAgain_, false))
            requestMissingTextures();
    });
    textureWorker_->start();
}

void Viewport::uploadPendingChanges() {
    const scene::Scene& s = document_->scene();
    if (pending_ == Changes(Change::Everything))
        textures_.clear(); // another project: its files may differ under the same names
    if (pending_ & (Change::Geometry | Change::Materials))
        requestMissingTextures();
    if (pending_ & Change::Geometry) {
        renderer_->setScene(s, textures_);
    } else {
        if (pending_ & Change::Materials)
            renderer_->updateMaterials(s, textures_);
        if (pending_ & (Change::Transforms | Change::Structure))
            renderer_->updateObjects(s);
    }
    pending_ = {};
}

void Viewport::paintGL() {
    const GLuint target = defaultFramebufferObject();
    if (!renderer_) {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    uploadPendingChanges();
    const scene::Scene& s = document_->scene();
    const int w = renderWidth(), h = renderHeight();
    const int fullW = std::max(1, int(width() * devicePixelRatio())), fullH = std::max(1, int(height() * devicePixelRatio()));
    // Auto exposure adapts over the real time between frames (after an idle
    // spell it is at its target at once); the split view's halves are two
    // presets through one renderer, so each is metered on its own.
    const qint64 sinceLastFrameNs = frameClock_.isValid() ? frameClock_.nsecsElapsed() : -1;
    frameClock_.start();
    renderer_->setExposureTimeStep(split_ || sinceLastFrameNs < 0 ? std::nullopt
                                                                  : std::optional<double>(double(sinceLastFrameNs) * 1e-9));
    auto renderWith = [&](const scene::ParameterSet& params) -> bool {
        auto ok = renderer_->render(s, params, controller_.camera(), w, h);
        if (!ok) {
            lastError_ = QString::fromStdString(ok.error().describe());
            emit renderFailed(lastError_);
        }
        return bool(ok);
    };
    if (split_) {
        // The same camera twice; each half of the view shows one preset.
        if (!renderWith(split_->first))
            return;
        renderer_->blitRegionTo(target, 0, 0, w / 2, h, 0, 0, fullW / 2, fullH);
        if (!renderWith(split_->second))
            return;
        renderer_->blitRegionTo(target, w / 2, 0, w, h, fullW / 2, 0, fullW, fullH);
    } else {
        if (!renderWith(document_->parameters()))
            return;
        renderer_->blitRegionTo(target, 0, 0, w, h, 0, 0, fullW, fullH);
    }
    lastError_.clear();
    emitVisualizerFrame();
    emit frameRendered(renderer_->timer().table());
    const QString note = QString::fromStdString(renderer_->lpvNote());
    if (note != lastNote_) {
        lastNote_ = note;
        emit lpvNoteChanged(note);
    }
    drawOverlay();
}

std::optional<glm::vec3> Viewport::selectionPivot() const {
    const Selection& sel = document_->selection();
    if (!sel.isObject())
        return std::nullopt;
    const glm::mat4 world = document_->scene().worldMatrix(sel.index);
    return glm::vec3(world[3]);
}

void Viewport::drawOverlay() {
    // The renderer leaves its own GL state; QPainter's GL engine expects the defaults.
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());

    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const scene::Scene& s = document_->scene();
    const Selection& sel = document_->selection();
    const scene::Camera& camera = controller_.camera();
    const glm::mat4 viewProj = camera.projection(float(width()) / float(std::max(height(), 1))) * camera.view();
    auto project = [&](const glm::vec3& p) -> std::optional<QPointF> {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        if (c.w <= 1e-4f)
            return std::nullopt;
        return QPointF((c.x / c.w * 0.5 + 0.5) * width(), (0.5 - c.y / c.w * 0.5) * height());
    };
    if (sel.isObject()) {
        // The selected object's world box.
        const scene::Bounds b = scene::objectWorldBounds(s, sel.index);
        if (!b.empty()) {
            painter.setPen(QPen(QColor(255, 200, 40), 1.5));
            auto corner = [&](int i) {
                return glm::vec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
            };
            for (int i = 0; i < 8; ++i)
                for (int bit : {1, 2, 4})
                    if (!(i & bit)) {
                        const auto a = project(corner(i)), c = project(corner(i | bit));
                        if (a && c)
                            painter.drawLine(*a, *c);
                    }
        }
        if (const auto pivot = selectionPivot()) {
            gizmo_.place(*pivot, camera, width(), height());
            if (gizmo_.visible()) {
                const glm::vec2 o = gizmo_.pivotScreen();
                for (int a = 0; a < 3; ++a) {
                    const glm::vec2 e = gizmo_.handleEnd(a);
                    painter.setPen(QPen(axisColor(a, drag_ == Drag::Gizmo && gizmoAxis_ == a), 3.0));
                    painter.drawLine(QPointF(o.x, o.y), QPointF(e.x, e.y));
                    painter.setBrush(axisColor(a, false));
                    if (gizmoMode_ == GizmoMode::Scale)
                        painter.drawRect(QRectF(e.x - 5, e.y - 5, 10, 10));
                    else if (gizmoMode_ == GizmoMode::Rotate)
                        painter.drawEllipse(QPointF(e.x, e.y), 6, 6);
                    else
                        painter.drawEllipse(QPointF(e.x, e.y), 3, 3);
                }
            }
        }
    }
    drawPath(painter);
    drawVisualizerOverlay(painter, vizRequest_, vizFrame_.get(), camera, QSizeF(width(), height()));
    if (split_) {
        painter.setPen(QPen(Qt::white, 2));
        painter.drawLine(QPointF(width() / 2.0, 0), QPointF(width() / 2.0, height()));
        painter.setPen(Qt::white);
        painter.drawText(QRectF(8, 8, width() / 2.0 - 16, 24), Qt::AlignLeft, "A: " + splitLabels_[0]);
        painter.drawText(QRectF(width() / 2.0 + 8, 8, width() / 2.0 - 16, 24), Qt::AlignLeft, "B: " + splitLabels_[1]);
    }
}

void Viewport::setVisualizerRequest(const VisualizerRequest& request) {
    vizRequest_ = request;
    if (!request.active())
        vizFrame_.reset(); // nothing shown: nothing kept
    if (renderer_) {
        makeCurrent();
        renderer_->setLpvCapture(request.lpv);
        renderer_->setShadowCascadeTint(request.shadowTint);
        doneCurrent();
    }
    update();
}

void Viewport::emitVisualizerFrame() {
    if (!vizRequest_.active())
        return;
    auto frame = std::make_shared<VisualizerFrame>();
    frame->cascades = renderer_->lpvCascadeFrames();
    frame->lpvNote = renderer_->lpvNote();
    if (const renderer::LpvSnapshot* snapshot = renderer_->lpvSnapshot())
        frame->lpv = *snapshot;
    if (vizRequest_.rsm)
        frame->rsm = renderer_->debugImages("rsm");
    if (vizRequest_.shadow)
        frame->shadow = renderer_->debugImages("shadowMaps");
    vizFrame_ = frame;
    emit visualizerFrame(frame);
}

void Viewport::setShownPath(int index) {
    shownPath_ = index;
    update();
}

std::optional<QPointF> Viewport::keyScreenPosition(int key) const {
    const auto& paths = document_->scene().cameraPaths;
    if (shownPath_ < 0 || std::size_t(shownPath_) >= paths.size())
        return std::nullopt;
    const auto& keys = paths[std::size_t(shownPath_)].keyframes;
    if (key < 0 || std::size_t(key) >= keys.size())
        return std::nullopt;
    const scene::Camera& camera = controller_.camera();
    const glm::mat4 viewProj = camera.projection(float(width()) / float(std::max(height(), 1))) * camera.view();
    const glm::vec4 c = viewProj * glm::vec4(keys[std::size_t(key)].position, 1.0f);
    if (c.w <= 1e-4f)
        return std::nullopt;
    return QPointF((c.x / c.w * 0.5 + 0.5) * width(), (0.5 - c.y / c.w * 0.5) * height());
}

void Viewport::drawPath(QPainter& painter) {
    const auto& paths = document_->scene().cameraPaths;
    if (shownPath_ < 0 || std::size_t(shownPath_) >= paths.size())
        return;
    const scene::CameraPath& path = paths[std::size_t(shownPath_)];
    if (path.keyframes.empty())
        return;
    const scene::Camera& camera = controller_.camera();
    const glm::mat4 viewProj = camera.projection(float(width()) / float(std::max(height(), 1))) * camera.view();
    auto project = [&](const glm::vec3& p) -> std::optional<QPointF> {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        if (c.w <= 1e-4f)
            return std::nullopt;
        return QPointF((c.x / c.w * 0.5 + 0.5) * width(), (0.5 - c.y / c.w * 0.5) * height());
    };
    // The curve, sampled finely enough to look smooth at any zoom that matters.
    const scene::CameraSpline spline(path);
    const int samples = 40 * int(path.keyframes.size());
    painter.setPen(QPen(QColor(80, 200, 255), 2.0));
    std::optional<QPointF> previous;
    for (int i = 0; i <= samples; ++i) {
        const auto p = project(spline.sample(spline.duration() * float(i) / float(samples)).position);
        if (p && previous)
            painter.drawLine(*previous, *p);
        previous = p;
    }
    for (std::size_t k = 0; k < path.keyframes.size(); ++k) {
        const auto p = project(path.keyframes[k].position);
        if (!p)
            continue;
        const bool active = drag_ == Drag::PathKey && draggedKey_ == int(k);
        painter.setPen(QPen(Qt::black, 1.0));
        painter.setBrush(active ? QColor(255, 220, 60) : QColor(80, 200, 255));
        painter.drawRect(QRectF(p->x() - 5, p->y() - 5, 10, 10));
        // Which way the key looks: a short line along its forward axis.
        const glm::vec3 forward = path.keyframes[k].orientation * glm::vec3(0.0f, 0.0f, -1.0f);
        const float length = 0.05f * glm::length(path.keyframes[k].position - camera.position);
        if (const auto tip = project(path.keyframes[k].position + forward * length))
            painter.drawLine(*p, *tip);
    }
}

void Viewport::dragPathKey(const QPoint& position) {
    scene::CameraPath path = document_->scene().cameraPaths.at(std::size_t(shownPath_));
    scene::CameraKeyframe& key = path.keyframes.at(std::size_t(draggedKey_));
    // Along the plane through the key that faces the camera: the key stays at its depth.
    const scene::Camera& camera = controller_.camera();
    const glm::vec3 normal = glm::normalize(camera.target - camera.position);
    const scene::Ray ray = scene::cameraRay(camera, float(position.x()) + 0.5f, float(position.y()) + 0.5f, width(),
                                            height());
    const float denominator = glm::dot(ray.direction, normal);
    if (std::abs(denominator) < 1e-6f)
        return;
    const float t = glm::dot(key.position - ray.origin, normal) / denominator;
    if (t <= 0.0f)
        return;
    key.position = ray.origin + t * ray.direction;
    document_->setCameraPath(shownPath_, path, tr("Move camera key"));
}

void Viewport::selectAt(const QPoint& position) {
    const scene::Ray ray = scene::cameraRay(controller_.camera(), float(position.x()) + 0.5f,
                                            float(position.y()) + 0.5f, width(), height());
    const auto hit = scene::pickObject(document_->scene(), ray.origin, ray.direction);
    document_->select(hit ? Selection{Selection::Kind::Object, hit->object} : Selection{});
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    pressPosition_ = lastPosition_ = event->position().toPoint();
    movedSincePress_ = false;
    const glm::vec2 mouse(float(pressPosition_.x()), float(pressPosition_.y()));
    if (event->button() == Qt::LeftButton) {
        // Camera path keys first: they are small and drawn on top.
        const auto& paths = document_->scene().cameraPaths;
        if (shownPath_ >= 0 && std::size_t(shownPath_) < paths.size())
            for (int k = 0; k < int(paths[std::size_t(shownPath_)].keyframes.size()); ++k)
                if (const auto p = keyScreenPosition(k);
                    p && (QPointF(pressPosition_) - *p).manhattanLength() <= TransformGizmo::kGrabPixels * 1.5) {
                    drag_ = Drag::PathKey;
                    draggedKey_ = k;
                    return;
                }
        const auto axis = document_->selection().isObject() ? gizmo_.hitTest(mouse) : std::nullopt;
        if (axis) {
            drag_ = Drag::Gizmo;
            gizmoAxis_ = *axis;
            gizmoStart_ = document_->scene().objects[std::size_t(document_->selection().index)].transform;
        } else {
            drag_ = heldKeys_.contains(Qt::Key_L) ? Drag::Sun : Drag::Orbit;
        }
    } else if (event->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    } else if (event->button() == Qt::RightButton) {
        drag_ = Drag::Look;
        flyClock_.start();
    }
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPoint p = event->position().toPoint();
    const QPoint delta = p - lastPosition_;
    lastPosition_ = p;
    if ((p - pressPosition_).manhattanLength() > kClickSlopPixels)
        movedSincePress_ = true;
    if (!movedSincePress_)
        return;
    switch (drag_) {
    case Drag::Orbit: controller_.orbit(float(delta.x()), float(delta.y())); break;
    case Drag::Pan: controller_.pan(float(delta.x()), float(delta.y()), height()); break;
    case Drag::Look: controller_.look(float(delta.x()), float(delta.y())); break;
    case Drag::Sun: dragSun(delta); return;
    case Drag::PathKey: dragPathKey(p); return;
    case Drag::Gizmo: {
        const int index = document_->selection().index;
        scene::Object object = document_->scene().objects[std::size_t(index)];
        const bool snapping = snap_.enabled != bool(event->modifiers() & Qt::ControlModifier);
        GizmoSnap snap = snap_;
        snap.enabled = snapping;
        object.transform = gizmo_.drag(gizmoMode_, gizmoAxis_, gizmoStart_,
                                       glm::vec2(float(pressPosition_.x()), float(pressPosition_.y())),
                                       glm::vec2(float(p.x()), float(p.y())), snap);
        static const char* names[] = {"Move object", "Rotate object", "Scale object"};
        document_->setObject(index, object, tr(names[int(gizmoMode_)]));
        return;
    }
    case Drag::None: return;
    }
    emit viewCameraChanged();
    update();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && !movedSincePress_ && drag_ != Drag::Gizmo && drag_ != Drag::PathKey)
        selectAt(event->position().toPoint());
    drag_ = Drag::None;
    gizmoAxis_ = -1;
    draggedKey_ = -1;
    flyTimer_.stop();
    update();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    controller_.dolly(float(event->angleDelta().y()) / 120.0f);
    emit viewCameraChanged();
    update();
}

void Viewport::dragSun(const QPoint& delta) {
    // The selected light if it is directional, else the first directional light.
    const scene::Scene& s = document_->scene();
    int index = -1;
    const Selection& sel = document_->selection();
    if (sel.kind == Selection::Kind::Light && s.lights[std::size_t(sel.index)].type == scene::LightType::Directional)
        index = sel.index;
    for (std::size_t i = 0; index < 0 && i < s.lights.size(); ++i)
        if (s.lights[i].type == scene::LightType::Directional)
            index = int(i);
    if (index < 0)
        return;
    scene::Light sun = s.lights[std::size_t(index)];
    // Azimuth follows horizontal mouse travel, elevation vertical; the sun stays above the horizon.
    const glm::vec3 toSun = -glm::normalize(sun.direction);
    float azimuth = std::atan2(toSun.x, toSun.z) + glm::radians(0.4f * float(delta.x()));
    float elevation = std::asin(std::clamp(toSun.y, -1.0f, 1.0f)) - glm::radians(0.4f * float(delta.y()));
    elevation = std::clamp(elevation, glm::radians(1.0f), glm::radians(89.0f));
    const glm::vec3 dir{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                        std::cos(elevation) * std::cos(azimuth)};
    sun.direction = -dir;
    document_->setLight(index, sun, tr("Turn sun"));
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->isAutoRepeat())
        return;
    heldKeys_.insert(event->key());
    const bool flying = drag_ == Drag::Look;
    switch (event->key()) {
    case Qt::Key_F: frameSelection(); return;
    case Qt::Key_W:
    case Qt::Key_A:
    case Qt::Key_S:
    case Qt::Key_D:
    case Qt::Key_Q:
    case Qt::Key_E:
        if (flying) {
            if (!flyTimer_.isActive()) {
                flyClock_.restart();
                flyTimer_.start();
            }
            return;
        }
        break;
    default: break;
    }
    if (!flying) {
        if (event->key() == Qt::Key_W)
            setGizmoMode(GizmoMode::Move);
        else if (event->key() == Qt::Key_E)
            setGizmoMode(GizmoMode::Rotate);
        else if (event->key() == Qt::Key_R)
            setGizmoMode(GizmoMode::Scale);
        else
            QOpenGLWidget::keyPressEvent(event);
    }
}

void Viewport::keyReleaseEvent(QKeyEvent* event) {
    if (event->isAutoRepeat())
        return;
    heldKeys_.remove(event->key());
}

void Viewport::focusOutEvent(QFocusEvent* event) {
    heldKeys_.clear();
    flyTimer_.stop();
    QOpenGLWidget::focusOutEvent(event);
}

void Viewport::flyStep() {
    glm::vec3 axes(0.0f);
    if (heldKeys_.contains(Qt::Key_W)) axes.z += 1.0f;
    if (heldKeys_.contains(Qt::Key_S)) axes.z -= 1.0f;
    if (heldKeys_.contains(Qt::Key_D)) axes.x += 1.0f;
    if (heldKeys_.contains(Qt::Key_A)) axes.x -= 1.0f;
    if (heldKeys_.contains(Qt::Key_E)) axes.y += 1.0f;
    if (heldKeys_.contains(Qt::Key_Q)) axes.y -= 1.0f;
    const float seconds = float(flyClock_.restart()) / 1000.0f;
    if (axes == glm::vec3(0.0f) || drag_ != Drag::Look) {
        flyTimer_.stop(); // nothing held: no more redraws
        return;
    }
    controller_.fly(axes, std::min(seconds, 0.1f), heldKeys_.contains(Qt::Key_Shift));
    emit viewCameraChanged();
    update();
}

} // namespace lpv::editor
