#include "ImportJob.h"

#include <QMetaObject>
#include <QPointer>
#include <QThread>

namespace lpv::editor {

ImportJob::ImportJob(QString file, QObject* parent) : QObject(parent), file_(std::move(file)) {}

ImportJob::~ImportJob() {
    if (thread_) {
        thread_->wait();
        delete thread_;
    }
}

void ImportJob::start() {
    const std::string path = file_.toStdString();
    QPointer<ImportJob> self(this);
    thread_ = QThread::create([this, self, path] {
        auto result = importers::importScene(path);
        // Deliver on the GUI thread; the job may have been cancelled meanwhile.
        QMetaObject::invokeMethod(
            this,
            [this, self, result = std::move(result)]() mutable {
                if (!self || cancelled_)
                    return;
                if (result)
                    emit imported(std::make_shared<importers::ImportResult>(std::move(*result)));
                else
                    emit failed(QString::fromStdString(result.error().describe()));
            },
            Qt::QueuedConnection);
    });
    thread_->start();
}

void ImportJob::cancel() { cancelled_ = true; }

} // namespace lpv::editor
