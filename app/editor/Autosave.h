#pragma once
// Autosave to a side folder and crash recovery. Every `interval` the
// modified project is written (atomically, the project library's save) to
// <AppData>/autosave/<key>/ on a worker thread, beside a file naming the
// project it belongs to. Saving the project or closing without saving
// removes it, so an autosave still there at the next start means the editor
// did not close normally: the main window offers to recover it.
#include "Document.h"

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <vector>

class QThread;

namespace lpv::editor {

struct RecoverableAutosave {
    QString autosaveFile;  // the .lpvproj in the autosave folder
    QString originalPath;  // the project it belongs to; empty for a never-saved one
    QDateTime savedAt;
};

class Autosave : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalSeconds = 120;

    explicit Autosave(Document* document, QObject* parent = nullptr);
    ~Autosave() override;

    void setIntervalSeconds(int seconds);
    // Writes now if the document is modified (returns after starting the worker).
    void saveNow();
    // Blocks until a running save finished (tests, quitting).
    void waitForSave();
    // Deletes the current document's autosave (after a save or a discard).
    void discard();

    // The root folder; tests point it elsewhere.
    static QString root();
    static void setRootForTests(const QString& folder);
    // Autosaves left behind, newest first.
    static std::vector<RecoverableAutosave> leftBehind();
    static void remove(const RecoverableAutosave& autosave);

signals:
    void saved(const QString& file);
    void failed(const QString& message);

private:
    static QString folderFor(const QString& projectPath);
    Document* document_;
    QTimer timer_;
    QThread* worker_ = nullptr;
};

} // namespace lpv::editor
