#include "EventLog.h"

#include <QMetaObject>

namespace lpv::editor {

EventLog::EventLog(QObject* parent) : QObject(parent) {}

void EventLog::add(Severity severity, const QString& source, const QString& text) {
    if (entries_.size() >= kMaxEntries)
        entries_.erase(entries_.begin(), entries_.begin() + std::ptrdiff_t(kMaxEntries / 10));
    entries_.push_back({QDateTime::currentDateTime(), severity, source, text});
    emit added(entries_.back());
    if (severity == Severity::Warning)
        ++unseenWarnings_;
    if (severity == Severity::Error)
        ++unseenErrors_;
    if (severity != Severity::Info)
        emit unseenChanged();
}

void EventLog::post(Severity severity, const QString& source, const QString& text) {
    QMetaObject::invokeMethod(
        this, [this, severity, source, text] { add(severity, source, text); }, Qt::QueuedConnection);
}

void EventLog::markSeen() {
    if (unseenWarnings_ == 0 && unseenErrors_ == 0)
        return;
    unseenWarnings_ = unseenErrors_ = 0;
    emit unseenChanged();
}

void EventLog::clear() {
    entries_.clear();
    emit cleared();
    markSeen();
}

QString EventLog::toString(Severity severity) {
    switch (severity) {
    case Severity::Info:
        return tr("info");
    case Severity::Warning:
        return tr("warning");
    case Severity::Error:
        return tr("error");
    }
    return {};
}

} // namespace lpv::editor
