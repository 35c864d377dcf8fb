#include "CameraPathPanel.h"

#include "VideoExportDialog.h"
#include "Viewport.h"

#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Project.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::editor {
namespace {

enum Column { kTime, kX, kY, kZ, kRotX, kRotY, kRotZ, kFov, kColumns };
constexpr int kTimelineSteps = 1000;

void sortKeys(scene::CameraPath& p) {
    std::stable_sort(p.keyframes.begin(), p.keyframes.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
}

} // namespace

CameraPathPanel::CameraPathPanel(Document* document, Viewport* viewport, QWidget* parent)
    : QWidget(parent), document_(document), viewport_(viewport), pathCombo_(new QComboBox(this)),
      closed_(new QCheckBox(tr("Closed loop"), this)), constantSpeed_(new QCheckBox(tr("Constant speed"), this)),
      table_(new QTableWidget(this)), timeline_(new QSlider(Qt::Horizontal, this)), timeBox_(new QDoubleSpinBox(this)),
      durationLabel_(new QLabel(this)), playButton_(new QPushButton(tr("Play"), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);

    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(new QLabel(tr("Path:"), this));
    pathRow->addWidget(pathCombo_, 1);
    auto* newButton = new QPushButton(tr("New"), this);
    auto* deleteButton = new QPushButton(tr("Delete"), this);
    pathRow->addWidget(newButton);
    pathRow->addWidget(deleteButton);
    layout->addLayout(pathRow);

    auto* optionsRow = new QHBoxLayout;
    optionsRow->addWidget(closed_);
    optionsRow->addWidget(constantSpeed_);
    optionsRow->addStretch();
    layout->addLayout(optionsRow);

    table_->setColumnCount(kColumns);
    table_->setHorizontalHeaderLabels(
        {tr("Time s"), tr("X"), tr("Y"), tr("Z"), tr("Rot X°"), tr("Rot Y°"), tr("Rot Z°"), tr("FOV°")});
    table_->verticalHeader()->hide();
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    layout->addWidget(table_, 1);

    auto* keyRow = new QHBoxLayout;
    auto* addKey = new QPushButton(tr("Add key from view"), this);
    auto* setKey = new QPushButton(tr("Set key to view"), this);
    auto* deleteKey = new QPushButton(tr("Delete key"), this);
    keyRow->addWidget(addKey);
    keyRow->addWidget(setKey);
    keyRow->addWidget(deleteKey);
    layout->addLayout(keyRow);

    auto* timeRow = new QHBoxLayout;
    timeRow->addWidget(playButton_);
    timeline_->setRange(0, kTimelineSteps);
    timeRow->addWidget(timeline_, 1);
    timeBox_->setDecimals(2);
    timeBox_->setSuffix(" s");
    timeBox_->setSingleStep(0.1);
    timeRow->addWidget(timeBox_);
    timeRow->addWidget(durationLabel_);
    layout->addLayout(timeRow);

    auto* fileRow = new QHBoxLayout;
    auto* importButton = new QPushButton(tr("Import JSON..."), this);
    auto* exportButton = new QPushButton(tr("Export JSON/CSV..."), this);
    auto* videoButton = new QPushButton(tr("Export video..."), this);
    fileRow->addWidget(importButton);
    fileRow->addWidget(exportButton);
    fileRow->addWidget(videoButton);
    layout->addLayout(fileRow);

    connect(newButton, &QPushButton::clicked, this, &CameraPathPanel::newPath);
    connect(deleteButton, &QPushButton::clicked, this, &CameraPathPanel::deletePath);
    connect(addKey, &QPushButton::clicked, this, &CameraPathPanel::addKeyFromView);
    connect(setKey, &QPushButton::clicked, this, &CameraPathPanel::setKeyToView);
    connect(deleteKey, &QPushButton::clicked, this, &CameraPathPanel::deleteSelectedKey);
    connect(importButton, &QPushButton::clicked, this, &CameraPathPanel::importPath);
    connect(exportButton, &QPushButton::clicked, this, &CameraPathPanel::exportPath);
    connect(videoButton, &QPushButton::clicked, this, &CameraPathPanel::exportVideo);
    connect(pathCombo_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!updating_)
            setCurrentPath(i);
    });
    connect(closed_, &QCheckBox::toggled, this, [this](bool on) {
        if (!updating_)
            editPath(on ? tr("Close camera path") : tr("Open camera path"), [on](auto& p) { p.closed = on; });
    });
    connect(constantSpeed_, &QCheckBox::toggled, this, [this](bool on) {
        if (!updating_)
            editPath(tr("Camera path speed"), [on](auto& p) { p.constantSpeed = on; });
    });
    connect(table_, &QTableWidget::cellChanged, this, &CameraPathPanel::onCellChanged);
    connect(timeline_, &QSlider::valueChanged, this, [this](int v) {
        if (!updating_)
            setTime(duration() * v / kTimelineSteps);
    });
    connect(timeBox_, &QDoubleSpinBox::valueChanged, this, [this](double t) {
        if (!updating_)
            setTime(t);
    });
    connect(playButton_, &QPushButton::clicked, this, [this] { playing() ? pause() : play(); });
    playTimer_.setInterval(16);
    connect(&playTimer_, &QTimer::timeout, this, [this] {
        const double d = duration();
        double t = playStartTime_ + playClock_.elapsed() / 1000.0;
        if (t > d) {
            const scene::CameraPath* p = path();
            if (p && p->closed && d > 0.0) {
                t = std::fmod(t, d);
            } else {
                t = d;
                pause();
            }
        }
        setTime(t);
    });
    connect(document_, &Document::changed, this, [this](Changes c) {
        if (c & Change::CameraPaths) {
            if (c == Changes(Change::Everything))
                current_ = document_->scene().cameraPaths.empty() ? -1 : 0;
            refresh();
        }
    });
    current_ = document_->scene().cameraPaths.empty() ? -1 : 0;
    refresh();
}

const scene::CameraPath* CameraPathPanel::path() const {
    const auto& paths = document_->scene().cameraPaths;
    return current_ >= 0 && std::size_t(current_) < paths.size() ? &paths[std::size_t(current_)] : nullptr;
}

double CameraPathPanel::duration() const {
    const scene::CameraPath* p = path();
    return p ? double(scene::CameraSpline(*p).duration()) : 0.0;
}

void CameraPathPanel::setCurrentPath(int index) {
    current_ = index;
    refresh();
    emit currentPathChanged(current_);
}

void CameraPathPanel::refresh() {
    const auto& paths = document_->scene().cameraPaths;
    if (current_ >= int(paths.size()))
        current_ = int(paths.size()) - 1;
    updating_ = true;
    pathCombo_->clear();
    for (const scene::CameraPath& p : paths)
        pathCombo_->addItem(QString::fromStdString(p.name));
    pathCombo_->setCurrentIndex(current_);
    const scene::CameraPath* p = path();
    closed_->setChecked(p && p->closed);
    constantSpeed_->setChecked(p && p->constantSpeed);
    const int selectedRow = table_->currentRow();
    table_->setRowCount(p ? int(p->keyframes.size()) : 0);
    for (int row = 0; p && row < int(p->keyframes.size()); ++row) {
        const scene::CameraKeyframe& k = p->keyframes[std::size_t(row)];
        const glm::vec3 euler = glm::degrees(glm::eulerAngles(k.orientation));
        const double values[kColumns] = {k.time,  k.position.x, k.position.y, k.position.z,
                                         euler.x, euler.y,      euler.z,      glm::degrees(k.fovY)};
        for (int c = 0; c < kColumns; ++c)
            table_->setItem(row, c, new QTableWidgetItem(QString::number(values[c], 'f', c == kTime ? 2 : 3)));
    }
    if (selectedRow >= 0 && selectedRow < table_->rowCount())
        table_->selectRow(selectedRow);
    const double d = duration();
    timeBox_->setRange(0.0, d);
    timeBox_->setValue(std::min(time_, d));
    timeline_->setValue(d > 0.0 ? int(std::lround(time_ / d * kTimelineSteps)) : 0);
    durationLabel_->setText(tr("/ %1 s").arg(d, 0, 'f', 2));
    updating_ = false;
    setEnabled(true);
    emit currentPathChanged(current_);
}

void CameraPathPanel::editPath(const QString& text, const std::function<void(scene::CameraPath&)>& edit) {
    const scene::CameraPath* p = path();
    if (!p)
        return;
    scene::CameraPath changed = *p;
    edit(changed);
    sortKeys(changed);
    document_->setCameraPath(current_, changed, text);
}

void CameraPathPanel::newPath() {
    int created = -1;
    document_->editScene(tr("New camera path"), Change::CameraPaths, [&](scene::Scene& s) {
        scene::CameraPath p;
        p.name = "path " + std::to_string(s.cameraPaths.size() + 1);
        p.keyframes.push_back(scene::keyframeFromCamera(viewport_->viewCamera(), 0.0f));
        s.cameraPaths.push_back(p);
        created = int(s.cameraPaths.size()) - 1;
    });
    setCurrentPath(created);
}

void CameraPathPanel::deletePath() {
    if (!path())
        return;
    const int index = current_;
    document_->editScene(tr("Delete camera path"), Change::CameraPaths,
                         [index](scene::Scene& s) { s.cameraPaths.erase(s.cameraPaths.begin() + index); });
}

void CameraPathPanel::addKeyFromView() {
    if (!path()) {
        newPath(); // its first key is the view, at 0 s
        return;
    }
    const scene::CameraPath* p = path();
    // At the timeline's time, or one second after the last key when the timeline sits at the end.
    double t = time_;
    if (!p->keyframes.empty() && t >= p->keyframes.back().time - 1e-6)
        t = p->keyframes.back().time + 1.0;
    const scene::CameraKeyframe key = scene::keyframeFromCamera(viewport_->viewCamera(), float(t));
    editPath(tr("Add camera key"), [&](scene::CameraPath& path) {
        auto same = std::find_if(path.keyframes.begin(), path.keyframes.end(),
                                 [&](const auto& k) { return std::abs(k.time - key.time) < 1e-4f; });
        if (same != path.keyframes.end())
            *same = key;
        else
            path.keyframes.push_back(key);
    });
    time_ = t;
    refresh();
}

void CameraPathPanel::setKeyToView() {
    const int row = table_->currentRow();
    const scene::CameraPath* p = path();
    if (!p || row < 0 || row >= int(p->keyframes.size()))
        return;
    const float t = p->keyframes[std::size_t(row)].time;
    editPath(tr("Set camera key to view"), [&](scene::CameraPath& path) {
        const float fov = path.keyframes[std::size_t(row)].fovY;
        path.keyframes[std::size_t(row)] = scene::keyframeFromCamera(viewport_->viewCamera(), t);
        path.keyframes[std::size_t(row)].fovY = fov;
    });
}

void CameraPathPanel::deleteSelectedKey() {
    const int row = table_->currentRow();
    const scene::CameraPath* p = path();
    if (!p || row < 0 || row >= int(p->keyframes.size()))
        return;
    editPath(tr("Delete camera key"), [row](scene::CameraPath& path) { path.keyframes.erase(path.keyframes.begin() + row); });
}

void CameraPathPanel::onCellChanged(int row, int column) {
    if (updating_)
        return;
    const scene::CameraPath* p = path();
    if (!p || row >= int(p->keyframes.size()))
        return;
    bool ok = false;
    const double value = table_->item(row, column)->text().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        refresh(); // puts the old value back
        return;
    }
    editPath(tr("Edit camera key"), [&](scene::CameraPath& path) {
        scene::CameraKeyframe& k = path.keyframes[std::size_t(row)];
        switch (column) {
        case kTime: k.time = float(std::max(0.0, value)); break;
        case kX:
        case kY:
        case kZ: k.position[column - kX] = float(value); break;
        case kRotX:
        case kRotY:
        case kRotZ: {
            glm::vec3 euler = glm::degrees(glm::eulerAngles(k.orientation));
            euler[column - kRotX] = float(value);
            k.orientation = glm::quat(glm::radians(euler));
            break;
        }
        case kFov: k.fovY = glm::radians(float(std::clamp(value, 1.0, 170.0))); break;
        default: break;
        }
    });
}

void CameraPathPanel::setTime(double seconds) {
    const scene::CameraPath* p = path();
    time_ = std::clamp(seconds, 0.0, std::max(duration(), 0.0));
    updating_ = true;
    timeBox_->setValue(time_);
    const double d = duration();
    timeline_->setValue(d > 0.0 ? int(std::lround(time_ / d * kTimelineSteps)) : 0);
    updating_ = false;
    if (p && !p->keyframes.empty())
        viewport_->setViewCamera(scene::CameraSpline(*p).cameraAt(float(time_), viewport_->viewCamera()));
}

void CameraPathPanel::play() {
    if (!path() || duration() <= 0.0)
        return;
    if (time_ >= duration() - 1e-6)
        time_ = 0.0;
    playStartTime_ = time_;
    playClock_.start();
    playTimer_.start();
    playButton_->setText(tr("Pause"));
}

void CameraPathPanel::pause() {
    playTimer_.stop();
    playButton_->setText(tr("Play"));
}

void CameraPathPanel::exportPath() {
    const scene::CameraPath* p = path();
    if (!p)
        return;
    QString selectedFilter;
    const QString file = QFileDialog::getSaveFileName(this, tr("Export camera path"),
                                                      QString::fromStdString(p->name) + ".json",
                                                      tr("Camera path JSON (*.json);;CSV per frame (*.csv)"),
                                                      &selectedFilter);
    if (file.isEmpty())
        return;
    std::string text;
    if (file.endsWith(".csv", Qt::CaseInsensitive)) {
        bool ok = false;
        const double fps = QInputDialog::getDouble(this, tr("CSV frame rate"), tr("Frames per second:"), 30.0, 1.0,
                                                   240.0, 2, &ok);
        if (!ok)
            return;
        text = scene::cameraPathToCsv(scene::CameraSpline(*p), fps);
    } else {
        auto json = scene::cameraPathToJson(*p);
        if (!json) {
            QMessageBox::critical(this, tr("Cannot export"), QString::fromStdString(json.error().describe()));
            return;
        }
        text = *json;
    }
    if (auto written = scene::writeFileAtomically(file.toStdString(), text); !written)
        QMessageBox::critical(this, tr("Cannot export"), QString::fromStdString(written.error().describe()));
}

void CameraPathPanel::importPath() {
    const QString file = QFileDialog::getOpenFileName(this, tr("Import camera path"), {}, tr("Camera path JSON (*.json)"));
    if (file.isEmpty())
        return;
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) {
        QMessageBox::critical(this, tr("Cannot import"), tr("%1: %2").arg(file, f.errorString()));
        return;
    }
    auto loaded = scene::cameraPathFromJson(f.readAll().toStdString(), file.toStdString());
    if (!loaded) {
        QMessageBox::critical(this, tr("Cannot import"), QString::fromStdString(loaded.error().describe()));
        return;
    }
    int created = -1;
    document_->editScene(tr("Import camera path"), Change::CameraPaths, [&](scene::Scene& s) {
        s.cameraPaths.push_back(*loaded);
        created = int(s.cameraPaths.size()) - 1;
    });
    setCurrentPath(created);
}

void CameraPathPanel::exportVideo() {
    const scene::CameraPath* p = path();
    if (!p || p->keyframes.size() < 2) {
        QMessageBox::information(this, tr("Export video"), tr("The path needs at least two keys."));
        return;
    }
    VideoExportDialog dialog(document_, current_, this);
    connect(&dialog, &VideoExportDialog::exportFinished, this, &CameraPathPanel::videoExportFinished);
    dialog.exec();
}

} // namespace lpv::editor
