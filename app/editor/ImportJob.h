#pragma once
// Runs importers::importScene on a worker thread, so the window keeps
// drawing during a long import. The importer cannot be interrupted midway:
// cancelling discards its result when it arrives (the project is untouched)
// and the window is free at once.
#include "lpv/importers/Importer.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

class QThread;

namespace lpv::editor {

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
    void imported(std::shared_ptr<lpv::importers::ImportResult> result);
    void failed(const QString& message);

private:
    QString file_;
    QThread* thread_ = nullptr;
    std::atomic<bool> cancelled_{false};
};

} // namespace lpv::editor
