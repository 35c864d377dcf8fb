#pragma once
// The editor's main window: the viewport in the centre, dockable panels
// around it (layout remembered with QSettings), menus and a toolbar with the
// standard shortcuts, and a status bar with frame time and GPU memory.
#include "Document.h"

#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QToolButton;
class QUndoView;

namespace lpv::editor {

class AccuracyPanel;
class Autosave;
class CameraPathPanel;
class EffectsPanel;
class EventLog;
class SweepPanel;
class LogPanel;
class RadiosityPanel;
class StatusMessageLabel;
class OutlinerPanel;
class ParameterInspector;
class PresetBar;
class ProfilerPanel;
class PropertyPanel;
class Viewport;
class VisualizerPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Loads a project; on failure shows the loader's error (a dialog when
    // `interactive`) and keeps the current one.
    bool openProject(const QString& path, bool interactive = true);
    // The loader's error of the last openProject that failed (names file and field).
    const QString& lastOpenError() const { return lastOpenError_; }
    // The project named on the command line. If it cannot be read the editor
    // still opens, and a box over the window (once it is shown) gives the
    // loader's error; returns false then.
    bool openFromCommandLine(const QString& path);
    // Shows a project that is not on disk (the built-in Cornell box when its file is missing).
    void showProject(scene::Project project, const QString& path);
    // Opens a template as a new, untitled project (Save asks for a path;
    // nothing is written beside the template). False, with lastOpenError, if it cannot be read.
    bool openTemplate(const QString& path, bool interactive = true);
    // `lpvstudio` with no project: the built-in Cornell box template, untitled.
    // Returns the template file it read (empty: none was found, the box was made in code).
    QString openBuiltInTemplate();
    // Saves to the document's path, or asks for one; false if cancelled or failed.
    bool save();
    bool saveAs();
    bool saveTo(const QString& path, bool interactive = true);
    // Imports a scene file into the current project on a worker thread with a
    // progress dialog; the import is one undo step.
    void importFile(const QString& path, bool interactive = true);
    // Offers to recover autosaves left by a session that did not close normally.
    void offerRecovery();

    Document* document() const { return document_; }
    Viewport* viewport() const { return viewport_; }
    OutlinerPanel* outliner() const { return outliner_; }
    EffectsPanel* effects() const { return effects_; }
    RadiosityPanel* radiosity() const { return radiosity_; }
    SweepPanel* sweeps() const { return sweeps_; }
    AccuracyPanel* accuracy() const { return accuracy_; }
    PropertyPanel* properties() const { return properties_; }
    ParameterInspector* inspector() const { return inspector_; }
    PresetBar* presetBar() const { return presetBar_; }
    // A/B split: preset indices for the left and right halves (-1 = the current parameters).
    void setSplit(int presetA, int presetB);
    ProfilerPanel* profiler() const { return profiler_; }
    CameraPathPanel* cameraPaths() const { return cameraPaths_; }
    VisualizerPanel* visualizers() const { return visualizers_; }
    // The session's log (open, save, import, textures, GL messages, solves,
    // exports) and its dock; the status bar's "N warnings" opens the dock.
    EventLog* eventLog() const { return log_; }
    LogPanel* logPanel() const { return logPanel_; }
    QToolButton* logButton() const { return logButton_; }
    // "Reference: 12 spp, noise 8.1%, 3.2 s" while gi.method = reference, else empty.
    QLabel* referenceLabel() const { return referenceLabel_; }
    // The status bar's message, elided, with the whole text as its tooltip.
    StatusMessageLabel* statusMessage() const { return statusMessage_; }
    Autosave* autosave() const { return autosave_; }
    // Import running (tests wait on it).
    bool importRunning() const { return importRunning_; }
    // How long an import runs before its progress dialog shows (300 ms; tests
    // set 0 so that a fast machine's import still meets the dialog).
    void setImportProgressDelay(int ms) { importProgressDelayMs_ = ms; }
    // Docks by object name ("outliner", "inspector", ...).
    QDockWidget* dock(const QString& name) const;
    // When a dialog would ask (unsaved changes on close), what the answer is: tests set it.
    void setUnsavedChangesAnswerForTests(int standardButton) { unsavedAnswerForTests_ = standardButton; }

    // Same as the Create menu's actions.
    void createLight(scene::LightType type);
    void createPrimitive(const QString& kind);
    void createCameraFromView();

protected:
    void closeEvent(QCloseEvent* event) override;
    // Ctrl+Z / Ctrl+Shift+Z in a spin box (or a text field with nothing of
    // its own to undo) go to the project's history, not the field's.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void createActions();
    void createDocks();
    QDockWidget* addDock(QWidget* widget, const QString& name, const QString& title, Qt::DockWidgetArea area);
    void newProject();
    void openDialog();
    void importDialog();
    bool confirmDiscardChanges();
    void updateTitle();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void rebuildCamerasMenu();
    void showFrameStats(double gpuMs);
    void updateLogButton();
    void showLog();
    bool chooseSplit();
    void updateSplit();

    Document* document_ = nullptr;
    Viewport* viewport_ = nullptr;
    VisualizerPanel* visualizers_ = nullptr;
    OutlinerPanel* outliner_ = nullptr;
    EffectsPanel* effects_ = nullptr;
    RadiosityPanel* radiosity_ = nullptr;
    SweepPanel* sweeps_ = nullptr;
    bool resumeAccuracyTrace_ = false; // the Accuracy trace was on when a sweep started
    AccuracyPanel* accuracy_ = nullptr;
    PropertyPanel* properties_ = nullptr;
    ParameterInspector* inspector_ = nullptr;
    PresetBar* presetBar_ = nullptr;
    QAction* splitAction_ = nullptr;
    QAction* giAction_ = nullptr; // gi.method on (lpv) / off, in the toolbar and the View menu
    std::pair<int, int> splitChoice_{-2, -2}; // preset indices; -1 = current parameters, -2 = off
    ProfilerPanel* profiler_ = nullptr;
    CameraPathPanel* cameraPaths_ = nullptr;
    Autosave* autosave_ = nullptr;
    EventLog* log_ = nullptr;
    LogPanel* logPanel_ = nullptr;
    QToolButton* logButton_ = nullptr;
    QUndoView* undoView_ = nullptr;
    StatusMessageLabel* statusMessage_ = nullptr;
    QLabel* frameLabel_ = nullptr;
    QLabel* memoryLabel_ = nullptr;
    QLabel* texturesLabel_ = nullptr;
    QLabel* referenceLabel_ = nullptr; // gi.method = reference: samples and noise of the live view
    QLabel* lpvNoteLabel_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* camerasMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QByteArray defaultState_;
    QDockWidget* vizDock_ = nullptr; // raised whenever shown (eventFilter)
    bool restoringLayout_ = false;   // restoreState shows docks: no raising then
    bool importRunning_ = false;
    int importProgressDelayMs_ = 300;
    QString lastOpenError_;
    int unsavedAnswerForTests_ = 0;
};

} // namespace lpv::editor
