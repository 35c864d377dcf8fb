#include "Autosave.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMetaObject>
#include <QStandardPaths>
#include <QThread>

#include <algorithm>

namespace lpv::editor {
namespace {

QString& rootOverride() {
    static QString folder;
    return folder;
}

constexpr const char* kOriginFile = "origin.txt";
constexpr const char* kProjectName = "autosave.lpvproj";

} // namespace

Autosave::Autosave(Document* document, QObject* parent) : QObject(parent), document_(document) {
    connect(&timer_, &QTimer::timeout, this, &Autosave::saveNow);
    setIntervalSeconds(kDefaultIntervalSeconds);
}

Autosave::~Autosave() { waitForSave(); }

void Autosave::setIntervalSeconds(int seconds) {
    timer_.stop();
    if (seconds > 0)
        timer_.start(seconds * 1000);
}

QString Autosave::root() {
    if (!rootOverride().isEmpty())
        return rootOverride();
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/autosave";
}

void Autosave::setRootForTests(const QString& folder) { rootOverride() = folder; }

QString Autosave::folderFor(const QString& projectPath) {
    // One folder per project file, named by a hash of its absolute path.
    const QString key = projectPath.isEmpty()
                            ? QString("untitled")
                            : QString(QCryptographicHash::hash(QFileInfo(projectPath).absoluteFilePath().toUtf8(),
                                                               QCryptographicHash::Sha1)
                                          .toHex()
                                          .left(16));
    return root() + "/" + key;
}

void Autosave::saveNow() {
    if (!document_->isModified() || (worker_ && worker_->isRunning()))
        return;
    waitForSave();
    const QString folder = folderFor(document_->path());
    const QString origin = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absoluteFilePath();
    // A copy: the user keeps editing while the worker writes.
    auto project = std::make_shared<scene::Project>(document_->project());
    worker_ = QThread::create([this, folder, origin, project] {
        QDir().mkpath(folder);
        const QString file = folder + "/" + kProjectName;
        auto ok = scene::saveProject(*project, file.toStdString());
        if (ok)
            ok = scene::writeFileAtomically((folder + "/" + kOriginFile).toStdString(), origin.toStdString());
        QMetaObject::invokeMethod(
            this,
            [this, file, ok] {
                if (ok)
                    emit saved(file);
                else
                    emit failed(QString::fromStdString(ok.error().describe()));
            },
            Qt::QueuedConnection);
    });
    worker_->start();
}

void Autosave::waitForSave() {
    if (worker_) {
        worker_->wait();
        delete worker_;
        worker_ = nullptr;
    }
}

void Autosave::discard() {
    waitForSave();
    QDir(folderFor(document_->path())).removeRecursively();
}

std::vector<RecoverableAutosave> Autosave::leftBehind() {
    std::vector<RecoverableAutosave> found;
    const QDir dir(root());
    for (const QString& name : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QString folder = dir.filePath(name);
        const QFileInfo project(folder + "/" + kProjectName);
        QFile origin(folder + "/" + kOriginFile);
        if (!project.exists() || !origin.open(QIODevice::ReadOnly))
            continue;
        found.push_back({project.absoluteFilePath(), QString::fromUtf8(origin.readAll()), project.lastModified()});
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.savedAt > b.savedAt; });
    return found;
}

void Autosave::remove(const RecoverableAutosave& autosave) {
    QDir(QFileInfo(autosave.autosaveFile).absolutePath()).removeRecursively();
}

} // namespace lpv::editor
