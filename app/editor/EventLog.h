#pragma once
// The editor's log (issue #26 item 5): what happened, when and where from,
// kept for the session: open and save results, import summaries and their
// warnings, missing textures, GL debug messages, radiosity solves and video
// exports. The Log dock (LogPanel) shows it; the status bar counts the
// warnings and errors not yet looked at and leads there.
#include <QDateTime>
#include <QObject>
#include <QString>

#include <vector>

namespace lpv::editor {

class EventLog : public QObject {
    Q_OBJECT
  public:
    enum class Severity { Info, Warning, Error };
    struct Entry {
        QDateTime time;
        Severity severity = Severity::Info;
        QString source; // "Open", "Import", "Textures", "OpenGL", ...
        QString text;
    };
    // The oldest entries go beyond this many: a GL message every frame must not grow without end.
    static constexpr std::size_t kMaxEntries = 10000;

    explicit EventLog(QObject* parent = nullptr);

    // On the UI thread.
    void add(Severity severity, const QString& source, const QString& text);
    // From any thread (GL messages arrive on the render thread): queued to the UI thread.
    void post(Severity severity, const QString& source, const QString& text);

    const std::vector<Entry>& entries() const { return entries_; }
    // Warnings and errors added since markSeen().
    int unseenWarnings() const { return unseenWarnings_; }
    int unseenErrors() const { return unseenErrors_; }
    void markSeen();
    void clear();

    static QString toString(Severity severity);

  signals:
    void added(const Entry& entry);
    void cleared();
    void unseenChanged();

  private:
    std::vector<Entry> entries_;
    int unseenWarnings_ = 0;
    int unseenErrors_ = 0;
};

} // namespace lpv::editor
