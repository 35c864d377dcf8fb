#pragma once
// Runs importers::importScene on a worker thread, so the window keeps
// drawing during a long import. The importer cannot be interrupted midway:
// cancelling discards its result when it arrives (the project is untouched)
// and the window is free at once.
#include "lpv/app/ImportDefaults.h"
#include "lpv/importers/Importer.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>

class QThread;

namespace lpv::editor {

// An import's result with what the worker also worked out for it, as `lpv
// import` does: the view to show it from, and a sun in case it has no lights
// (ray traced: Sponza takes about a second, so not on the GUI thread).
struct ImportedScene {
    importers::ImportResult result;
    scene::Camera view;
    std::optional<app::DefaultSun> sun; // set when the imported scene has no lights
};

class ImportJob : public QObject {
    Q_OBJECT
public:
    explicit ImportJob(QString file, QObject* parent = nullptr);
    ~ImportJob() override; // waits for the worker: the importer holds no cancellation point

    void start();
    void cancel();
    bool cancelled() const { return cancelled_; }
    const QString& file() const { return file_; }

signals:
    // Exactly one of these, on the GUI thread, unless cancelled.
    void imported(std::shared_ptr<lpv::editor::ImportedScene> imported);
    void failed(const QString& message);

private:
    QString file_;
    QThread* thread_ = nullptr;
    std::atomic<bool> cancelled_{false};
};

} // namespace lpv::editor
