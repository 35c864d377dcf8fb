#include "RadiosityPanel.h"

#include "Document.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/FormFactorSources.h"
#include "lpv/renderer/RadiosityView.h"
#include "lpv/scene/FramingCamera.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace lpv::editor {
namespace {

constexpr int kPreviewWidth = 320;
constexpr int kPreviewHeight = 240;

} // namespace

RadiosityPanel::RadiosityPanel(Document* document, QWidget* parent)
    : QWidget(parent), document_(document),
      memory_(std::make_shared<std::optional<radiosity::StoredSolution>>()) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout();
    run_ = new QPushButton(tr("Run"), this);
    run_->setObjectName("radiosityRun");
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setFormat(tr("residual"));
    row->addWidget(run_);
    row->addWidget(progress_, 1);
    layout->addLayout(row);
    status_ =
        new QLabel(tr("Every light shoots: the lights' direct light first, then emissive surfaces and what they light "
                   "(radiosity.formFactors: CPU ray casting or GPU hemicubes)."), this);
    status_->setWordWrap(true);
    layout->addWidget(status_);

    auto* body = new QHBoxLayout();
    chart_ = new QChart();
    chart_->setAnimationOptions(QChart::NoAnimation);
    chart_->legend()->hide();
    chart_->setMargins(QMargins(4, 4, 4, 4));
    series_ = new QLineSeries(chart_);
    chart_->addSeries(series_);
    axisX_ = new QValueAxis(chart_);
    axisX_->setTitleText(tr("seconds"));
    axisX_->setRange(0.0, 1.0);
    axisY_ = new QLogValueAxis(chart_);
    axisY_->setTitleText(tr("residual"));
    axisY_->setBase(10.0);
    axisY_->setRange(1e-3, 1.0);
    axisY_->setLabelFormat("%g");
    chart_->addAxis(axisX_, Qt::AlignBottom);
    chart_->addAxis(axisY_, Qt::AlignLeft);
    series_->attachAxis(axisX_);
    series_->attachAxis(axisY_);
    auto* view = new QChartView(chart_, this);
    view->setMinimumHeight(160);
    body->addWidget(view, 1);
    preview_ = new QLabel(this);
    preview_->setFixedSize(kPreviewWidth, kPreviewHeight);
    preview_->setAlignment(Qt::AlignCenter);
    preview_->setText(tr("no solution yet"));
    body->addWidget(preview_);
    layout->addLayout(body, 1);

    connect(run_, &QPushButton::clicked, this, [this] { running() ? pause() : start(); });
}

RadiosityPanel::~RadiosityPanel() {
    if (worker_) {
        *cancel_ = true;
        worker_->wait();
        delete worker_;
    }
}

void RadiosityPanel::updateButton() {
    run_->setText(running() ? tr("Pause") : tr("Run"));
}

void RadiosityPanel::start() {
    if (running())
        return;
    // A snapshot: edits made while it runs apply to the next run.
    const scene::Project project = document_->project();
    const std::filesystem::path projectFile = document_->path().toStdString();
    const std::filesystem::path projectDir = document_->projectDir().toStdString();
    const scene::ParameterSet& params = project.parameters;
    target_ = params.getFloat("radiosity.convergenceThreshold");
    axisY_->setRange(std::min(1e-3, target_ / 2.0), 1.0);
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    auto cancel = cancel_;
    auto memory = memory_;
    worker_ = QThread::create([this, project, projectFile, projectDir, cancel, memory] {
        QString message;
        QImage image;
        auto context = renderer::HeadlessContext::create();
        if (!context) {
            QMetaObject::invokeMethod(this, "onStopped", Qt::QueuedConnection,
                                      Q_ARG(QString, QString::fromStdString(context.error().describe())),
                                      Q_ARG(QImage, QImage()));
            return;
        }
        const scene::ParameterSet& p = project.parameters;
        const auto textures = importers::loadSceneTextures(project.scene, projectDir);
        std::optional<radiosity::StoredSolution> saved = radiosity::loadSavedSolution(project.scene, projectFile);
        if (!saved && memory->has_value())
            saved = **memory;
        auto created =
            radiosity::RadiositySession::create(project.scene, p, textures.images, std::move(saved), cancel.get());
        if (!created) { // nothing emits, or too many patches: say so, save nothing
            QMetaObject::invokeMethod(this, "onStopped", Qt::QueuedConnection,
                                      Q_ARG(QString, QString::fromStdString(created.error().describe())),
                                      Q_ARG(QImage, QImage()));
            return;
        }
        radiosity::RadiositySession& session = *created;
        auto formFactors = renderer::makeFormFactorSource(p.getEnum("radiosity.formFactors"), session.mesh(),
                                                          project.scene, textures.images, p);
        if (!formFactors) {
            QMetaObject::invokeMethod(this, "onStopped", Qt::QueuedConnection,
                                      Q_ARG(QString, QString::fromStdString(formFactors.error().describe())),
                                      Q_ARG(QImage, QImage()));
            return;
        }
        radiosity::SolveOptions options;
        options.residualTarget = p.getFloat("radiosity.convergenceThreshold");
        options.shootersPerBatch = (*formFactors)->preferredBatch();
        options.progressInterval = 0.25;
        options.cancel = cancel.get();
        options.progress = [this](const radiosity::SolveProgress& s) {
            QMetaObject::invokeMethod(this, "onProgress", Qt::QueuedConnection, Q_ARG(double, s.residual),
                                      Q_ARG(qulonglong, s.shots), Q_ARG(double, s.seconds),
                                      Q_ARG(double, s.shootersPerSecond), Q_ARG(qulonglong, s.patches));
        };
        const auto reason = radiosity::solve(session.solver(), **formFactors, options);
        if (!reason) {
            message = QString::fromStdString(reason.error().describe());
        } else {
            message = QString::fromLatin1(radiosity::toString(*reason));
            *memory = session.stored();
            if (!projectFile.empty()) {
                if (auto ok = radiosity::saveSolution(**memory, radiosity::solutionPath(projectFile)); !ok)
                    message += "; " + QString::fromStdString(ok.error().describe());
                else
                    message += tr("; saved into the project's assets");
            }
            auto view = renderer::RadiosityView::create();
            if (view) {
                const scene::Camera camera = project.scene.cameras.empty()
                                                 ? scene::framingCamera(project.scene)
                                                 : project.scene.cameras.front();
                view->setPatches(session.mesh(), session.solver().state().radiosity,
                                 p.getBool("radiosity.smoothing"));
                view->render(camera, kPreviewWidth, kPreviewHeight, p.getFloat("output.exposure"), false);
                const auto pixels = view->readDisplay();
                image = QImage(pixels.data(), kPreviewWidth, kPreviewHeight, QImage::Format_RGBA8888).copy();
            }
        }
        QMetaObject::invokeMethod(this, "onStopped", Qt::QueuedConnection, Q_ARG(QString, message),
                                  Q_ARG(QImage, image));
    });
    status_->setText(tr("meshing and starting..."));
    worker_->start();
    updateButton();
}

void RadiosityPanel::pause() {
    if (cancel_)
        *cancel_ = true;
}

void RadiosityPanel::onProgress(double residual, qulonglong shots, double seconds, double perSecond,
                                qulonglong patches) {
    series_->append(seconds, std::max(residual, 1e-9));
    axisX_->setRange(0.0, std::max(1.0, seconds));
    // Progress on a log scale: residual 1 is 0, the target is full.
    const double done = std::log(std::max(residual, 1e-12)) / std::log(std::min(target_, 0.999));
    progress_->setValue(int(1000.0 * std::clamp(done, 0.0, 1.0)));
    progress_->setFormat(QString::asprintf("residual %.4f", residual));
    status_->setText(tr("%1 patches, %2 shots, %3 patches/s, %4 s")
                         .arg(patches)
                         .arg(shots)
                         .arg(perSecond, 0, 'f', 0)
                         .arg(seconds, 0, 'f', 1));
}

void RadiosityPanel::onStopped(const QString& message, const QImage& preview) {
    if (worker_) {
        worker_->wait();
        delete worker_;
        worker_ = nullptr;
    }
    if (!preview.isNull()) {
        previewImage_ = preview;
        preview_->setPixmap(QPixmap::fromImage(preview));
    }
    status_->setText(status_->text() + " - " + message);
    updateButton();
    emit stopped(message);
}

} // namespace lpv::editor
