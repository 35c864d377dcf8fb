#include "VideoExportDialog.h"

#include "lpv/video/VideoExport.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QMetaObject>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QThread>

#include <memory>

namespace lpv::editor {
namespace {

std::vector<std::pair<std::string, std::string>> asOverrides(const scene::ParameterSet& params) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [key, value] : params.overrides())
        out.emplace_back(key, scene::formatValue(value));
    return out;
}

QString timeText(double seconds) {
    return seconds < 60.0 ? QObject::tr("%1 s").arg(seconds, 0, 'f', 0)
                          : QObject::tr("%1 min %2 s").arg(int(seconds) / 60).arg(int(seconds) % 60);
}

} // namespace

VideoExportDialog::VideoExportDialog(Document* document, int pathIndex, QWidget* parent)
    : QDialog(parent), document_(document), pathIndex_(pathIndex), output_(new QLineEdit(this)),
      width_(new QSpinBox(this)), height_(new QSpinBox(this)), fps_(new QDoubleSpinBox(this)),
      compare_(new QComboBox(this)) {
    setWindowTitle(tr("Export video"));
    const scene::CameraPath& path = document_->scene().cameraPaths.at(std::size_t(pathIndex_));
    auto* form = new QFormLayout(this);
    auto* outputRow = new QHBoxLayout;
    output_->setText(document_->projectDir() + "/" + QString::fromStdString(path.name).replace(' ', '-') + ".mp4");
    auto* browse = new QPushButton(tr("Browse..."), this);
    outputRow->addWidget(output_, 1);
    outputRow->addWidget(browse);
    form->addRow(tr("Output (.mp4, or a folder for PNGs):"), outputRow);
    width_->setRange(16, 7680);
    width_->setSingleStep(2);
    width_->setValue(1280);
    height_->setRange(16, 4320);
    height_->setSingleStep(2);
    height_->setValue(720);
    fps_->setRange(1.0, 240.0);
    fps_->setValue(30.0);
    form->addRow(tr("Width:"), width_);
    form->addRow(tr("Height:"), height_);
    form->addRow(tr("Frames per second:"), fps_);
    compare_->addItem(tr("No (the current parameters)"));
    for (const scene::ParameterPreset& p : document_->project().presets)
        compare_->addItem(tr("Current | %1").arg(QString::fromStdString(p.name)));
    form->addRow(tr("Side by side:"), compare_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* exportButton = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    form->addRow(buttons);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Video file"), output_->text(),
                                                       tr("MP4 video (*.mp4);;PNG sequence folder (*)"));
        if (!f.isEmpty())
            output_->setText(f);
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(exportButton, &QPushButton::clicked, this, [this] {
        const QString error = run();
        if (error.isEmpty())
            accept();
        else if (error != "cancelled")
            QMessageBox::critical(this, tr("Export failed"), error);
    });
}

QString VideoExportDialog::run() {
    video::VideoOptions options;
    const scene::Project& project = document_->project();
    options.pathName = project.scene.cameraPaths.at(std::size_t(pathIndex_)).name;
    options.output = output_->text().toStdString();
    options.width = width_->value();
    options.height = height_->value();
    options.fps = fps_->value();
    options.projectFile = document_->path().toStdString(); // gi.method = radiosity: its saved solution
    // The project's own parameters go in as overrides, so side B can start from the defaults like its preset.
    auto project2 = std::make_shared<scene::Project>(project);
    project2->parameters = {};
    options.setA = asOverrides(project.parameters);
    if (int b = compare_->currentIndex() - 1; b >= 0) {
        options.setB = asOverrides(project.presets.at(std::size_t(b)).parameters);
        options.labelA = "current";
        options.labelB = project.presets.at(std::size_t(b)).name;
    }

    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto result = std::make_shared<QString>();
    QProgressDialog progress(tr("Rendering..."), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    QPointer<QProgressDialog> progressPtr(&progress);
    connect(&progress, &QProgressDialog::canceled, this, [cancel] { *cancel = true; });
    const int cancelAfter = cancelAfterFrames_;
    const std::string dir = document_->projectDir().toStdString();
    QEventLoop loop;
    QThread* worker = QThread::create([=, &loop] {
        auto ok = video::renderVideo(*project2, dir, options, [=, &loop](const video::VideoProgress& p) {
            QMetaObject::invokeMethod(&loop, [=] {
                if (!progressPtr)
                    return;
                progressPtr->setMaximum(p.frames);
                progressPtr->setValue(p.frame);
                progressPtr->setLabelText(QObject::tr("Frame %1 of %2, %3 elapsed, about %4 left")
                                              .arg(p.frame)
                                              .arg(p.frames)
                                              .arg(timeText(p.elapsedSeconds), timeText(p.etaSeconds)));
            });
            if (cancelAfter > 0 && p.frame >= cancelAfter)
                *cancel = true;
            return !*cancel;
        });
        if (!ok)
            *result = *cancel ? QString("cancelled") : QString::fromStdString(ok.error().describe());
        else if (*cancel)
            *result = "cancelled";
    });
    connect(worker, &QThread::finished, &loop, &QEventLoop::quit);
    worker->start();
    loop.exec();
    worker->wait();
    delete worker;
    emit exportFinished(output_->text(), *result);
    return *result;
}

} // namespace lpv::editor
