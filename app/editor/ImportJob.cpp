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
        std::shared_ptr<ImportedScene> done;
        if (result && !cancelled_) {
            done = std::make_shared<ImportedScene>();
            done->view = app::firstView(result->scene);
            if (result->scene.lights.empty())
                done->sun = app::chooseDefaultSun(result->scene);
            done->result = std::move(*result);
        }
        // Deliver on the GUI thread; the job may have been cancelled meanwhile.
        QMetaObject::invokeMethod(
            this,
            [this, self, done, error = result ? std::string() : result.error().describe()]() mutable {
                if (!self || cancelled_)
                    return;
                if (done)
                    emit imported(done);
                else
                    emit failed(QString::fromStdString(error));
            },
            Qt::QueuedConnection);
    });
    thread_->start();
}

void ImportJob::cancel() { cancelled_ = true; }

} // namespace lpv::editor
