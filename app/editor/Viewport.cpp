#include "Viewport.h"

#include "OverlayLabel.h"

#include "lpv/app/ImportDefaults.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Picking.h"
#include "lpv/scene/ProjectTextures.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
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
bool texturesCached(const scene::Material& m, const std::set<std::string>& images) {
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

Viewport::Viewport(Document* document, QWidget* parent) : QWidget(parent), document_(document) {
    // The frame covers the whole widget: no background to clear first. No
    // OpenGL in the widget: the window stays a plain raster one, which costs
    // the UI thread far less than composing a GL widget (on llvmpipe above all).
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    flyTimer_.setInterval(16);
    connect(&flyTimer_, &QTimer::timeout, this, &Viewport::flyStep);
    connect(document_, &Document::changed, this, &Viewport::onDocumentChanged);
    referenceTimer_.setSingleShot(true);
    referenceTimer_.setInterval(150);
    connect(&referenceTimer_, &QTimer::timeout, this, &Viewport::restartReference);
    connect(this, &Viewport::viewCameraChanged, this, [this] { scheduleReference(false); });
    connect(&reference_, &LiveReference::passDone, this,
            [this](const QImage& image, std::shared_ptr<const LinearImage> linear, int spp, double noise,
                   double seconds) {
                referenceImage_ = image;
                referenceLinear_ = std::move(linear);
                emit referenceProgress(spp, noise, seconds);
                update();
            });
    connect(&reference_, &LiveReference::failed, this, [this](const QString& m) { emit renderFailed(m); });
    connect(document_, &Document::selectionChanged, this, [this] { update(); });
    onDocumentChanged(Change::Everything);
}

Viewport::~Viewport() {
    if (textureWorker_) {
        textureWorker_->wait(); // it writes only into its own result, but must end before the process
        delete textureWorker_;
    }
    delete worker_; // ends the render thread (its GL objects die there)
    worker_ = nullptr;
}

void Viewport::onDocumentChanged(Changes changes) {
    if (changes == Changes(Change::Everything)) {
        // A new project: start where the editor last saved it, else from its
        // first camera, else from one that frames the scene.
        const scene::Scene& s = document_->scene();
        const auto& saved = document_->project().editorView;
        controller_.setCamera(saved ? *saved : s.cameras.empty() ? scene::framingCamera(s) : s.cameras.front());
        controller_.setSceneBounds(s.worldBounds());
        emit viewCameraChanged();
    }
    pending_ |= changes;
    // An exposure or tonemapper edit shows on the last pass at once, before the restart's first.
    if ((changes & Change::Parameters) && referenceLinear_ && showsReference())
        referenceImage_ = displayReference(*referenceLinear_, referenceMapping_, document_->parameters());
    scheduleReference(changes & ~Changes(Change::Parameters | Change::Presets));
    update();
}

void Viewport::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    scheduleReference(false);
}

bool Viewport::showsReference() const { return document_->parameters().getEnum("gi.method") == "reference"; }

void Viewport::scheduleReference(bool sceneChanged) {
    referenceSceneChanged_ = referenceSceneChanged_ || sceneChanged;
    if (!showsReference()) {
        if (reference_.running() || !referenceImage_.isNull()) {
            reference_.stop();
            referenceImage_ = {};
            referenceLinear_.reset();
            referenceSceneChanged_ = true;
            emit referenceProgress(0, 0.0, 0.0);
        }
        return;
    }
    reference_.invalidate(); // what it traces now is of the old view
    referenceTimer_.start();
}

void Viewport::restartReference() {
    if (!showsReference() || paused_)
        return;
    // Half the view's size: four times the samples per second, and the noise
    // it shows is still the noise of what is traced.
    const int w = std::max(1, width() / 2), h = std::max(1, height() / 2);
    reference_.restart(document_->scene(), document_->parameters(), controller_.camera(), w, h,
                       document_->projectDir(),
                       referenceSceneChanged_);
    referenceSceneChanged_ = false;
}

void Viewport::renderAgain() {
    if (requested_)
        requested_->resend = true;
    update();
}

bool Viewport::frameUpToDate() const {
    return pending_ == Changes() && requested_ && !requested_->resend && worker_ &&
           shownSerial_ == worker_->lastSerial();
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

void Viewport::setGizmoPivot(GizmoPivot pivot) {
    gizmoPivot_ = pivot;
    update();
}

scene::Camera Viewport::homeCamera() const { return app::firstView(document_->scene()); }

void Viewport::homeView() { setViewCamera(homeCamera()); }

Viewport::Depth Viewport::depthAt(const QPoint& position) const {
    const scene::Camera& camera = controller_.camera();
    const scene::Ray ray = scene::cameraRay(camera, float(position.x()) + 0.5f, float(position.y()) + 0.5f,
                                            width(), height());
    Depth depth;
    depth.direction = ray.direction;
    if (const auto hit = scene::pickObject(document_->scene(), ray.origin, ray.direction)) {
        depth.distance = hit->distance;
        depth.hit = hit->position;
        return depth;
    }
    // Over the sky nothing says how far to go: the focus, but never more than
    // half the scene, so a far target cannot throw the eye out of it.
    depth.distance = std::min(glm::length(camera.target - camera.position), 0.5f * controller_.sceneSize());
    return depth;
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

std::optional<renderer::GlInfo> Viewport::renderGlInfo() const {
    return worker_ ? worker_->glInfo() : std::nullopt;
}

QString Viewport::glRenderer() const {
    const auto info = renderGlInfo();
    return info ? QString::fromStdString(info->renderer + " | " + info->version) : QString();
}

void Viewport::requestMissingTextures() {
    if (textureWorker_) {
        texturesRequestedAgain_ = true; // once the running job is in
        return;
    }
    auto wanted = std::make_shared<scene::Scene>();
    for (const scene::Material& m : document_->scene().materials)
        if (!texturesCached(m, texturesKnown_))
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
        for (const auto& [key, image] : decoded->images)
            texturesKnown_.insert(key);
        texturesToSend_.push_back(std::make_shared<const scene::TextureImages>(std::move(decoded->images)));
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

void Viewport::prepareSceneChanges() {
    // What changed in the document goes to the worker with the next request;
    // here only the texture cache follows (forgotten for a new project,
    // decoding started for new materials).
    if (pending_ == Changes(Change::Everything)) {
        texturesKnown_.clear(); // another project: its files may differ under the same names
        texturesToSend_.clear();
        forgetTexturesOnSend_ = true;
    }
    if (pending_ & (Change::Geometry | Change::Materials))
        requestMissingTextures();
}

void Viewport::setFramesPaused(bool paused, const QString& why) {
    if (paused_ == paused)
        return;
    paused_ = paused;
    pausedWhy_ = why;
    if (paused)
        reference_.stop();
    else
        scheduleReference(true);
    update();
}

void Viewport::requestFrameIfChanged() {
    if (paused_)
        return; // the state is compared again when the pause ends
    if (!worker_) {
        // Started with the first frame a shown view asks for: a window that
        // is never shown (a test, a screenshot of a dock) compiles no shaders.
        worker_ = new FrameWorker(this);
        connect(worker_, &FrameWorker::frameReady, this, &Viewport::onFrameReady);
    }
    const int w = renderWidth(), h = renderHeight();
    const scene::Camera& camera = controller_.camera();
    const scene::ParameterSet& params = document_->parameters();
    // Parameter and preset edits leave the scene as it is: nothing of it to send.
    const Changes sceneFlags = Change::Transforms | Change::Structure | Change::Geometry | Change::Materials |
                               Change::Lights | Change::Cameras | Change::CameraPaths | Change::Sky;
    const bool sceneChanged = (pending_ & sceneFlags) || !sceneRest_;
    const bool texturesArrived = !texturesToSend_.empty();
    if (requested_ && pending_ == Changes() && !texturesArrived && !requested_->resend &&
        requested_->camera == camera && requested_->parameters == params && requested_->split == split_ &&
        requested_->width == w && requested_->height == h && requested_->readHdr == hdrReadback_ &&
        (requested_->radiosityGeneration == radiosityGeneration_ || !showsBakedRadiosity()))
        return;
    prepareSceneChanges();
    FrameRequest request;
    const scene::Scene& s = document_->scene();
    if (sceneChanged) {
        // The meshes only when they changed: a transform drag or a material
        // edit sends the small rest of the scene.
        if (!sceneRest_ || (pending_ & Change::Geometry))
            request.meshes = std::make_shared<const std::vector<scene::Mesh>>(s.meshes);
        auto rest = std::make_shared<scene::Scene>();
        rest->materials = s.materials;
        rest->objects = s.objects;
        rest->lights = s.lights;
        rest->cameras = s.cameras;
        rest->cameraPaths = s.cameraPaths;
        rest->sky = s.sky;
        sceneRest_ = std::move(rest);
    }
    request.rest = sceneRest_;
    request.changes = pending_;
    if (texturesArrived)
        request.changes |= Change::Materials;
    request.newTextures = std::exchange(texturesToSend_, {});
    request.forgetTextures = std::exchange(forgetTexturesOnSend_, false);
    request.parameters = params;
    request.split = split_;
    request.camera = camera;
    request.width = w;
    request.height = h;
    request.visualizers = vizRequest_;
    request.readHdr = hdrReadback_;
    request.projectFile = document_->path().toStdString();
    request.radiosityGeneration = radiosityGeneration_;
    request.texturesPending = textureWorker_ != nullptr;
    pending_ = {};
    requested_ = Requested{camera, params, split_, w, h, hdrReadback_, radiosityGeneration_};
    worker_->submit(std::move(request));
}

void Viewport::onFrameReady(const std::shared_ptr<const FrameResult>& result) {
    shownSerial_ = result->serial;
    if (!result->error.isEmpty()) {
        lastError_ = result->error;
        emit renderFailed(lastError_);
        // Once more, in case it was passing (the view stays on the last good
        // frame meanwhile); a second failure in a row waits for a change.
        if (!std::exchange(lastFrameFailed_, true))
            renderAgain();
        update();
        return;
    }
    lastFrameFailed_ = false;
    lastError_.clear();
    gpuMemory_ = result->gpuMemory;
    if (!result->image.isNull())
        shownImage_ = result->image;
    if (result->visualizers && vizRequest_.active()) {
        vizFrame_ = result->visualizers;
        emit visualizerFrame(vizFrame_);
    }
    emit frameRendered(result->timings);
    if (result->hdr && hdrReadback_)
        emit hdrFrameRendered(result->hdr);
    if (result->lpvNote != lastNote_) {
        lastNote_ = result->lpvNote;
        emit lpvNoteChanged(lastNote_);
    }
    if (result->radiosityNote != lastRadiosityNote_) {
        lastRadiosityNote_ = result->radiosityNote;
        if (!lastRadiosityNote_.isEmpty())
            emit radiosityNoteChanged(lastRadiosityNote_, result->radiosityFailed);
    }
    update();
}

void Viewport::paintEvent(QPaintEvent*) {
    // Never renders here: asks the worker for a frame when the state changed,
    // and shows the last finished one at once.
    requestFrameIfChanged();
    QPainter painter(this);
    if (shownImage_.isNull()) {
        painter.fillRect(rect(), QColor(31, 31, 33));
    } else {
        painter.setRenderHint(QPainter::SmoothPixmapTransform, shownImage_.size() != size());
        painter.drawImage(QRectF(0, 0, width(), height()), shownImage_);
    }
    // gi.method = reference: the path tracer's image over the (direct-only) frame once it has one.
    if (showsReference() && !referenceImage_.isNull()) {
        painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
        painter.drawImage(QRectF(0, 0, width(), height()), referenceImage_);
    }
    if (comparisonSplitShown())
        drawComparisonSplit(painter);
    if (!errorOverlay_.isNull()) {
        // Mostly opaque: the magma scale reads true, and the scene's edges
        // still show through enough to tell where the error is.
        painter.setOpacity(0.85);
        painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
        painter.drawImage(QRectF(0, 0, width(), height()), errorOverlay_);
        painter.setOpacity(1.0);
    }
    drawOverlay(painter);
}

std::optional<glm::vec3> Viewport::gizmoPivot() const {
    const Selection& sel = document_->selection();
    if (!sel.isObject())
        return std::nullopt;
    if (gizmoPivot_ == GizmoPivot::BoundsCentre) {
        // An object without a mesh (an empty parent) has no bounds: its origin then.
        const scene::Bounds b = scene::objectWorldBounds(document_->scene(), sel.index);
        if (!b.empty())
            return b.center();
    }
    const glm::mat4 world = document_->scene().worldMatrix(sel.index);
    return glm::vec3(world[3]);
}

std::function<std::optional<QPointF>(const glm::vec3&)> Viewport::screenProjection(const scene::Camera& camera) const {
    const glm::mat4 viewProj = camera.projection(float(width()) / float(std::max(height(), 1))) * camera.view();
    return [viewProj, w = double(width()), h = double(height())](const glm::vec3& p) -> std::optional<QPointF> {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        if (c.w <= 1e-4f)
            return std::nullopt;
        return QPointF((c.x / c.w * 0.5 + 0.5) * w, (0.5 - c.y / c.w * 0.5) * h);
    };
}

void Viewport::drawOverlay(QPainter& painter) {
    if (paused_) {
        const QString text = tr("Paused: %1").arg(pausedWhy_);
        const QRectF box(8, height() - 32, painter.fontMetrics().horizontalAdvance(text) + 16, 24);
        painter.fillRect(box, QColor(0, 0, 0, 160));
        painter.setPen(Qt::white);
        painter.drawText(box, Qt::AlignCenter, text);
    }
    painter.setRenderHint(QPainter::Antialiasing);
    const scene::Scene& s = document_->scene();
    const Selection& sel = document_->selection();
    const scene::Camera& camera = controller_.camera();
    const auto project = screenProjection(camera);
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
        if (const auto pivot = gizmoPivot()) {
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
    if (comparisonSplitShown()) {
        painter.setPen(QPen(Qt::white, 2));
        painter.drawLine(QPointF(width() / 2.0, 0), QPointF(width() / 2.0, height()));
        // On a box: white text alone could not be read on a bright sky (issue #46).
        const std::string method = document_->parameters().getEnum("gi.method");
        drawOverlayLabel(painter, QPointF(8, 8), method == "lpv" ? tr("LPV") : QString::fromStdString(method),
                         width() / 2.0 - 16);
        drawOverlayLabel(painter, QPointF(width() / 2.0 + 8, 8), tr("Reference"), width() / 2.0 - 16);
    } else if (split_) {
        painter.setPen(QPen(Qt::white, 2));
        painter.drawLine(QPointF(width() / 2.0, 0), QPointF(width() / 2.0, height()));
        drawOverlayLabel(painter, QPointF(8, 8), "A: " + splitLabels_[0], width() / 2.0 - 16);
        drawOverlayLabel(painter, QPointF(width() / 2.0 + 8, 8), "B: " + splitLabels_[1], width() / 2.0 - 16);
    }
}

void Viewport::reloadBakedRadiosity() {
    ++radiosityGeneration_;
    update(); // a frame that shows the solution is asked for again
}

bool Viewport::showsBakedRadiosity() const {
    return renderer::showsBakedRadiosity(document_->parameters()) ||
           (split_ && (renderer::showsBakedRadiosity(split_->first) || renderer::showsBakedRadiosity(split_->second)));
}

void Viewport::setVisualizerRequest(const VisualizerRequest& request) {
    vizRequest_ = request;
    if (!request.active())
        vizFrame_.reset(); // nothing shown: nothing kept
    if (requested_)
        requested_->resend = true; // the next frame reads back what is asked now
    update();
}

void Viewport::setHdrReadback(bool on) {
    if (hdrReadback_ == on)
        return;
    hdrReadback_ = on;
    update(); // the next request asks for it (or stops asking)
}

void Viewport::setErrorOverlay(const QImage& heatMap) {
    errorOverlay_ = heatMap;
    update();
}

void Viewport::setReferenceMapping(ReferenceMapping mapping) {
    referenceMapping_ = mapping;
    reference_.setMapping(mapping);
    if (referenceLinear_)
        referenceImage_ = displayReference(*referenceLinear_, mapping, document_->parameters());
    update();
}

void Viewport::setComparisonSplit(const QImage& left, const QImage& right) {
    comparisonLeft_ = left;
    comparisonRight_ = right;
    update();
}

void Viewport::drawComparisonSplit(QPainter& painter) {
    // Each half from its own image, the same pixels of the view: the left
    // half of the LPV frame, the right half of the reference.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    const double half = width() / 2.0;
    const QRectF leftSource(0, 0, comparisonLeft_.width() / 2.0, comparisonLeft_.height());
    const QRectF rightSource(comparisonRight_.width() / 2.0, 0, comparisonRight_.width() / 2.0,
                             comparisonRight_.height());
    painter.drawImage(QRectF(0, 0, half, height()), comparisonLeft_, leftSource);
    painter.drawImage(QRectF(half, 0, width() - half, height()), comparisonRight_, rightSource);
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
    const auto project = screenProjection(camera);
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
        // Placed now, not only when painted: a press right after the
        // selection or the pivot changed would grab the handles of before.
        if (const auto pivot = gizmoPivot())
            gizmo_.place(*pivot, controller_.camera(), width(), height());
        const auto axis = document_->selection().isObject() ? gizmo_.hitTest(mouse) : std::nullopt;
        if (axis) {
            drag_ = Drag::Gizmo;
            gizmoAxis_ = *axis;
            const scene::Scene& s = document_->scene();
            const int index = document_->selection().index;
            gizmoStart_ = s.objects[std::size_t(index)].transform;
            // Rotate and scale turn about the gizmo's pivot, given in the space the transform lives in.
            gizmoDragPivot_.reset();
            if (const auto pivot = gizmoPivot()) {
                const int parent = s.objects[std::size_t(index)].parent;
                const glm::mat4 parentWorld = parent >= 0 ? s.worldMatrix(parent) : glm::mat4(1.0f);
                gizmoDragPivot_ = glm::vec3(glm::inverse(parentWorld) * glm::vec4(*pivot, 1.0f));
            }
        } else {
            drag_ = heldKeys_.contains(Qt::Key_L) ? Drag::Sun : Drag::Orbit;
            // About what the user grabbed: orbiting a far target from inside
            // a building swung the eye through its walls.
            if (drag_ == Drag::Orbit) {
                const Depth depth = depthAt(pressPosition_);
                orbitPivot_ = depth.hit ? *depth.hit : controller_.camera().target;
            }
        }
    } else if (event->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
        // The grabbed surface follows the mouse, near or far.
        const Depth depth = depthAt(pressPosition_);
        const scene::Camera& camera = controller_.camera();
        panDepth_ = depth.hit ? depth.distance *
                                    glm::dot(depth.direction, glm::normalize(camera.target - camera.position))
                              : 0.0f;
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
    case Drag::Orbit:
        orbitStep(delta);
        break;
    case Drag::Pan:
        controller_.pan(float(delta.x()), float(delta.y()), height(), panDepth_);
        break;
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
                                       glm::vec2(float(p.x()), float(p.y())), snap, gizmoDragPivot_);
        static const char* names[] = {"Move object", "Rotate object", "Scale object"};
        document_->setObject(index, object, tr(names[int(gizmoMode_)]));
        return;
    }
    case Drag::None: return;
    }
    emit viewCameraChanged();
    update();
}

void Viewport::orbitStep(const QPoint& delta) {
    const scene::Camera before = controller_.camera();
    controller_.orbitAround(orbitPivot_, float(delta.x()), float(delta.y()));
    const glm::vec3 move = controller_.camera().position - before.position;
    const float length = glm::length(move);
    if (!(length > 0.0f))
        return;
    // Never through a wall: orbiting about the far end of Sponza's atrium
    // swings the eye metres sideways. Where it would pass a surface (with a
    // margin of 1% of the scene) the view turns in place instead, the same turn.
    const auto hit = scene::pickObject(document_->scene(), before.position, move / length);
    if (hit && hit->distance < length + 0.01f * controller_.sceneSize()) {
        controller_.setCamera(before);
        controller_.look(float(delta.x()), float(delta.y()));
    }
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
    // A fraction of the way to what is under the cursor: a wheel step in
    // Sponza's atrium moves metres, in the Cornell box centimetres.
    const Depth depth = depthAt(event->position().toPoint());
    controller_.dollyAlong(float(event->angleDelta().y()) / 120.0f, depth.direction, depth.distance);
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
    case Qt::Key_Home:
        homeView();
        return;
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
            QWidget::keyPressEvent(event);
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
    QWidget::focusOutEvent(event);
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
    // What lies straight ahead sets the pace (a pick: milliseconds on Sponza).
    const Depth ahead = depthAt(QPoint(width() / 2, height() / 2));
    controller_.fly(axes, std::min(seconds, 0.1f), heldKeys_.contains(Qt::Key_Shift),
                    ahead.hit ? ahead.distance : 0.0f);
    emit viewCameraChanged();
    update();
}

} // namespace lpv::editor
