#include "MainWindow.h"

#include "AboutDialog.h"
#include "AccuracyPanel.h"
#include "Autosave.h"
#include "CameraPathPanel.h"
#include "EventLog.h"
#include "SweepPanel.h"
#include "LogPanel.h"
#include "EffectsPanel.h"
#include "ImportJob.h"
#include "OutlinerPanel.h"
#include "ParameterInspector.h"
#include "PresetBar.h"
#include "ProfilerPanel.h"
#include "RadiosityPanel.h"
#include "StatusMessageLabel.h"
#include "VisualizerPanel.h"
#include "PropertyPanel.h"
#include "Viewport.h"

#include "lpv/renderer/GlContext.h"
#include "lpv/scene/SceneMerge.h"

#include <QAbstractSpinBox>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QCheckBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QUndoView>
#include <QVBoxLayout>

namespace lpv::editor {
namespace {

// File > New: an empty project named "untitled".
scene::Project untitledProject() {
    scene::Project p;
    p.name = "untitled";
    return p;
}

// A panel in a scroll area: its controls scroll when its dock is short,
// instead of their minimum height setting the dock area's (the Sweeps
// dock's 371 px made the bottom strip a third of a 900 px window).
QScrollArea* scrollable(QWidget* panel, QWidget* parent) {
    auto* scroll = new QScrollArea(parent);
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    return scroll;
}

// The bottom strip's default height (the Profiler's table and chart side by
// side), so that the viewport above dominates the window.
constexpr int kBottomDocksHeight = 200;

constexpr int kMaxRecentFiles = 10;
const char* kRecentKey = "recentFiles";

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), document_(new Document(this)) {
    setObjectName("mainWindow");
    log_ = new EventLog(this);
    // GL messages come on the render thread; the log takes them on this one.
    renderer::setGlDebugSink([log = log_](bool error, const std::string& message) {
        log->post(error ? EventLog::Severity::Error : EventLog::Severity::Warning, "OpenGL",
                  QString::fromStdString(message));
    });
    viewport_ = new Viewport(document_, this);
    setCentralWidget(viewport_);
    autosave_ = new Autosave(document_, this);

    // First, so it holds the room left of the fields below and long messages cannot run into them.
    statusMessage_ = new StatusMessageLabel(statusBar());
    frameLabel_ = new QLabel(this);
    memoryLabel_ = new QLabel(this);
    statusBar()->addPermanentWidget(frameLabel_);
    statusBar()->addPermanentWidget(memoryLabel_);
    connect(viewport_, &Viewport::frameRendered, this, [this](const std::vector<renderer::PassTiming>& table) {
        double total = 0.0;
        for (const renderer::PassTiming& t : table)
            total += t.lastMs;
        showFrameStats(total);
    });
    connect(viewport_, &Viewport::radiosityNoteChanged, this, [this](const QString& note, bool failed) {
        if (failed)
            statusBar()->showMessage(tr("Radiosity: ") + note, 10000);
        log_->add(failed ? EventLog::Severity::Warning : EventLog::Severity::Info, tr("Radiosity"),
                  failed ? note : tr("showing %1").arg(note));
    });
    connect(document_, &Document::projectSaved, viewport_, &Viewport::reloadBakedRadiosity);
    connect(document_, &Document::editRefused, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Not applied: ") + message, 10000);
        log_->add(EventLog::Severity::Warning, tr("Edit"), message);
    });
    connect(viewport_, &Viewport::renderFailed, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Render error: ") + message);
        log_->add(EventLog::Severity::Error, tr("Render"), message);
    });
    connect(document_, &Document::titleChanged, this, &MainWindow::updateTitle);
    // Texture decoding runs in the background: its state has its own corner of the status bar.
    texturesLabel_ = new QLabel(this);
    statusBar()->addPermanentWidget(texturesLabel_);
    connect(viewport_, &Viewport::texturesLoading, this, [this](int materials) {
        texturesLabel_->setText(tr("Loading textures of %1 materials...").arg(materials));
    });
    connect(viewport_, &Viewport::texturesLoaded, this, [this](const QStringList& warnings) {
        texturesLabel_->setText(warnings.isEmpty() ? QString() : tr("%1 textures missing").arg(warnings.size()));
        texturesLabel_->setToolTip(tr("Drawn as a placeholder:\n") + warnings.join("\n"));
        for (const QString& w : warnings)
            log_->add(EventLog::Severity::Warning, tr("Textures"), w);
    });
    referenceLabel_ = new QLabel(this);
    referenceLabel_->setObjectName("referenceLabel");
    statusBar()->addPermanentWidget(referenceLabel_);
    connect(viewport_, &Viewport::referenceProgress, this, [this](int spp, double noise, double seconds) {
        referenceLabel_->setText(spp == 0 ? QString()
                                          : tr("Reference: %1 spp, noise %2%, %3 s")
                                                .arg(spp)
                                                .arg(100.0 * noise, 0, 'f', 1)
                                                .arg(seconds, 0, 'f', 1));
        referenceLabel_->setToolTip(tr("gi.method = reference: the CPU path tracer's image of this view, at half "
                                       "its size; samples add up while nothing changes. Noise = the MARE its "
                                       "own variance implies."));
    });
    // Warnings and errors not yet looked at; a click opens the Log dock.
    logButton_ = new QToolButton(this);
    logButton_->setObjectName("logButton");
    logButton_->setAutoRaise(true);
    statusBar()->addPermanentWidget(logButton_);
    connect(logButton_, &QToolButton::clicked, this, &MainWindow::showLog);
    connect(log_, &EventLog::unseenChanged, this, &MainWindow::updateLogButton);
    updateLogButton();
    connect(document_, &Document::changed, this, [this](Changes c) {
        if (c & Change::Cameras)
            rebuildCamerasMenu();
    });
    connect(autosave_, &Autosave::failed, this, [this](const QString& m) {
        statusBar()->showMessage(tr("Autosave failed: ") + m);
        log_->add(EventLog::Severity::Error, tr("Autosave"), m);
    });

    createActions();
    createDocks();
    qApp->installEventFilter(this); // see eventFilter: undo while a field has the focus
    resize(1400, 900);
    defaultState_ = saveState();
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoringLayout_ = true;
    restoreState(settings.value("window/state").toByteArray());
    restoringLayout_ = false;
    showProject(untitledProject(), {});
    log_->add(EventLog::Severity::Info, "OpenGL",
              renderer::glDebugOutputRequested()
                  ? tr("GL debug messages are shown here")
                  : tr("GL debug messages are off (set LPV_GL_DEBUG=1 to show them here; they slow the GPU down)"));
}

// Before the children go (the viewport ends its render thread): no GL message may reach a deleted log.
MainWindow::~MainWindow() { renderer::setGlDebugSink({}); }

void MainWindow::updateLogButton() {
    const int errors = log_->unseenErrors(), warnings = log_->unseenWarnings();
    logButton_->setVisible(errors + warnings > 0);
    logButton_->setText(errors > 0 ? tr("%n error(s)", "", errors) + ", " + tr("%n warning(s)", "", warnings)
                                   : tr("%n warning(s)", "", warnings));
    logButton_->setToolTip(tr("Show them in the Log"));
}

void MainWindow::showLog() {
    QDockWidget* d = dock("log");
    d->show();
    d->raise();
    log_->markSeen();
}

QDockWidget* MainWindow::addDock(QWidget* widget, const QString& name, const QString& title, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name); // saveState/restoreState key
    dock->setWidget(widget);
    addDockWidget(area, dock);
    viewMenu_->addAction(dock->toggleViewAction());
    return dock;
}

QDockWidget* MainWindow::dock(const QString& name) const { return findChild<QDockWidget*>(name); }

void MainWindow::createDocks() {
    outliner_ = new OutlinerPanel(document_, this);
    QDockWidget* outlinerDock = addDock(outliner_, "outliner", tr("Outliner"), Qt::LeftDockWidgetArea);

    undoView_ = new QUndoView(document_->undoStack(), this);
    undoView_->setEmptyLabel(tr("<opened>"));
    addDock(undoView_, "history", tr("History"), Qt::LeftDockWidgetArea);

    // The inspector: presets on top, every registry parameter below.
    auto* inspectorPage = new QWidget(this);
    auto* inspectorLayout = new QVBoxLayout(inspectorPage);
    inspectorLayout->setContentsMargins(0, 0, 0, 0);
    presetBar_ = new PresetBar(inspectorPage);
    inspector_ = new ParameterInspector(inspectorPage);
    inspectorLayout->addWidget(presetBar_);
    inspectorLayout->addWidget(inspector_);
    connect(inspector_, &ParameterInspector::parameterEdited, this,
            [this](const QString& key, const scene::ParameterValue& value) {
                document_->setParameter(key.toStdString(), value);
            });
    connect(inspector_, &ParameterInspector::parameterResetRequested, this,
            [this](const QString& key) { document_->setParameter(key.toStdString(), std::nullopt); });
    connect(presetBar_, &PresetBar::presetSaveRequested, this,
            [this](const QString& name) { document_->savePreset(name.toStdString()); });
    connect(presetBar_, &PresetBar::presetApplyRequested, document_, &Document::applyPreset);
    connect(presetBar_, &PresetBar::presetDeleteRequested, document_, &Document::deletePreset);
    connect(document_, &Document::changed, this, [this](Changes c) {
        if (c & Change::Parameters)
            inspector_->setParameters(document_->parameters());
        if (c & Change::Presets)
            presetBar_->setPresets(document_->project().presets);
        if (c & (Change::Parameters | Change::Presets))
            updateSplit();
    });
    inspector_->setParameters(document_->parameters());
    presetBar_->setPresets(document_->project().presets);
    QDockWidget* inspectorDock = addDock(inspectorPage, "inspector", tr("Inspector"), Qt::RightDockWidgetArea);

    properties_ = new PropertyPanel(document_, this);
    addDock(properties_, "properties", tr("Properties"), Qt::RightDockWidgetArea);

    profiler_ = new ProfilerPanel(this);
    connect(viewport_, &Viewport::frameRendered, profiler_, &ProfilerPanel::addFrame);
    connect(document_, &Document::changed, profiler_, [this](Changes c) {
        if (c == Changes(Change::Everything))
            profiler_->clear();
    });
    QDockWidget* profilerDock = addDock(profiler_, "profiler", tr("Profiler"), Qt::BottomDockWidgetArea);

    cameraPaths_ = new CameraPathPanel(document_, viewport_, this);
    connect(cameraPaths_, &CameraPathPanel::currentPathChanged, viewport_, &Viewport::setShownPath);
    QDockWidget* pathsDock =
        addDock(scrollable(cameraPaths_, this), "cameraPaths", tr("Camera paths"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(profilerDock, pathsDock);
    radiosity_ = new RadiosityPanel(document_, this);
    QDockWidget* radiosityDock =
        addDock(scrollable(radiosity_, this), "radiosity", tr("Radiosity"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(profilerDock, radiosityDock);
    connect(radiosity_, &RadiosityPanel::stopped, this,
            [this](const QString& message) { log_->add(EventLog::Severity::Info, tr("Radiosity"), message); });
    // gi.method = radiosity: a stop saved the solution the viewport shows.
    connect(radiosity_, &RadiosityPanel::stopped, viewport_, &Viewport::reloadBakedRadiosity);
    connect(cameraPaths_, &CameraPathPanel::videoExportFinished, this, [this](const QString& output, const QString& error) {
        if (error.isEmpty())
            log_->add(EventLog::Severity::Info, tr("Video export"), tr("wrote %1").arg(output));
        else if (error == "cancelled")
            log_->add(EventLog::Severity::Info, tr("Video export"), tr("cancelled: %1").arg(output));
        else
            log_->add(EventLog::Severity::Error, tr("Video export"), output + ": " + error);
    });
    sweeps_ = new SweepPanel(document_, [this] { return viewport_->viewCamera(); }, this);
    QDockWidget* sweepsDock =
        addDock(scrollable(sweeps_, this), "sweeps", tr("Sweeps"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(profilerDock, sweepsDock);
    // Timings on llvmpipe are only the settings' own when nothing else renders.
    connect(sweeps_, &SweepPanel::timingChanged, this, [this](bool timing) {
        viewport_->setFramesPaused(timing, tr("a sweep is timing (Sweeps dock)"));
        if (accuracy_ && timing && accuracy_->traceBox()->isChecked()) {
            accuracy_->traceBox()->setChecked(false);
            resumeAccuracyTrace_ = true;
        } else if (accuracy_ && !timing && resumeAccuracyTrace_) {
            accuracy_->traceBox()->setChecked(true);
            resumeAccuracyTrace_ = false;
        }
        if (accuracy_)
            accuracy_->traceBox()->setEnabled(!timing);
    });
    connect(sweeps_, &SweepPanel::logMessage, this, [this](const QString& message, bool warning) {
        log_->add(warning ? EventLog::Severity::Warning : EventLog::Severity::Info, tr("Sweep"), message);
    });
    // The frame's error against a reference of the same view, next to its GPU time (issue #26 item 3).
    accuracy_ = new AccuracyPanel(document_, viewport_, this);
    tabifyDockWidget(profilerDock, addDock(scrollable(accuracy_, this), "accuracy", tr("Accuracy"),
                                           Qt::BottomDockWidgetArea));
    logPanel_ = new LogPanel(log_, this);
    QDockWidget* logDock = addDock(logPanel_, "log", tr("Log"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(profilerDock, logDock);
    // Shown is seen: the count in the status bar starts again.
    connect(logDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            log_->markSeen();
    });
    profilerDock->raise();

    effects_ = new EffectsPanel(document_, viewport_, this);
    connect(viewport_, &Viewport::lpvNoteChanged, effects_, &EffectsPanel::setRendererNote);
    QDockWidget* effectsDock = addDock(effects_, "effects", tr("Effects"), Qt::RightDockWidgetArea);

    // Default layout: the right-hand panels share one area as tabs, the
    // profiler stays a strip under the viewport.
    tabifyDockWidget(inspectorDock, dock("properties"));
    tabifyDockWidget(inspectorDock, effectsDock);
    inspectorDock->raise();
    // Hidden until asked for: while hidden it reads nothing back from the renderer.
    visualizers_ = new VisualizerPanel(document_, viewport_, this);
    // In a scroll area: its controls' minimum height, stacked under the
    // inspector's, grew the window past a 1024 px screen (to 1091 px), and
    // it stayed so after the dock was closed.
    QDockWidget* vizDock =
        addDock(scrollable(visualizers_, this), "visualizers", tr("Visualizers"), Qt::RightDockWidgetArea);
    // A tab beside the Inspector, raised whenever it is shown (eventFilter):
    // stacked under it, the dock opened about 60 px tall with two of its
    // controls visible.
    tabifyDockWidget(inspectorDock, vizDock);
    vizDock_ = vizDock;
    connect(vizDock, &QDockWidget::visibilityChanged, visualizers_, &VisualizerPanel::setActive);
    vizDock->hide();
    inspectorDock->raise();
    resizeDocks({profilerDock}, {kBottomDocksHeight}, Qt::Vertical);
    resizeDocks({inspectorDock}, {400}, Qt::Horizontal);
    // Given no width, the left area shrank to its minimum (about 65 px) and
    // cut every name in the outliner to its first letters.
    resizeDocks({outlinerDock}, {220}, Qt::Horizontal);
}

void MainWindow::createActions() {
    QUndoStack* undo = document_->undoStack();
    QToolBar* toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName("mainToolbar");

    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* newAction = file->addAction(tr("&New"), this, &MainWindow::newProject);
    newAction->setShortcut(QKeySequence::New);
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openDialog);
    open->setShortcut(QKeySequence::Open);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* saveAction = file->addAction(tr("&Save"), this, [this] { save(); });
    saveAction->setShortcut(QKeySequence::Save);
    QAction* saveAsAction = file->addAction(tr("Save &As..."), this, [this] { saveAs(); });
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* import = file->addAction(tr("&Import..."), this, &MainWindow::importDialog);
    import->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undoAction = undo->createUndoAction(this, tr("&Undo"));
    undoAction->setShortcut(QKeySequence::Undo);
    QAction* redoAction = undo->createRedoAction(this, tr("&Redo"));
    redoAction->setShortcut(QKeySequence::Redo);
    edit->addAction(undoAction);
    edit->addAction(redoAction);
    edit->addSeparator();
    QAction* rename = edit->addAction(tr("Re&name"), this, [this] { outliner_->renameSelected(); });
    rename->setShortcut(QKeySequence(Qt::Key_F2));
    QAction* duplicate = edit->addAction(tr("&Duplicate"), this, [this] { outliner_->duplicateSelected(); });
    duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    QAction* remove = edit->addAction(tr("De&lete"), this, [this] { outliner_->deleteSelected(); });
    remove->setShortcut(QKeySequence::Delete);
    // Delete, F2 and Ctrl+D act on the selection wherever the focus is, except while typing in a field.
    for (QAction* a : {rename, duplicate, remove})
        a->setShortcutContext(Qt::WindowShortcut);

    QMenu* create = menuBar()->addMenu(tr("&Create"));
    create->addAction(tr("&Sun (directional light)"), this, [this] { createLight(scene::LightType::Directional); });
    create->addAction(tr("&Point light"), this, [this] { createLight(scene::LightType::Point); });
    create->addAction(tr("S&pot light"), this, [this] { createLight(scene::LightType::Spot); });
    create->addAction(tr("&Area light"), this, [this] { createLight(scene::LightType::Area); });
    create->addSeparator();
    create->addAction(tr("&Camera from view"), this, &MainWindow::createCameraFromView);
    create->addSeparator();
    create->addAction(tr("P&lane"), this, [this] { createPrimitive("plane"); });
    create->addAction(tr("&Box"), this, [this] { createPrimitive("box"); });
    create->addAction(tr("Sp&here"), this, [this] { createPrimitive("sphere"); });
    create->addSeparator();
    create->addAction(import);

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    QAction* frame = viewMenu_->addAction(tr("&Frame selection"), viewport_, &Viewport::frameSelection);
    frame->setShortcut(QKeySequence(Qt::Key_F));
    frame->setShortcutContext(Qt::WidgetWithChildrenShortcut); // F is also a letter in text fields
    QAction* home = viewMenu_->addAction(tr("&Home view"), viewport_, &Viewport::homeView);
    home->setObjectName("homeView");
    home->setShortcut(QKeySequence(Qt::Key_Home));
    home->setShortcutContext(Qt::WidgetWithChildrenShortcut); // Home moves the cursor in text fields
    home->setToolTip(
        tr("Back to the scene's opening view: its first camera, else one framing the whole scene"));
    camerasMenu_ = viewMenu_->addMenu(tr("&Cameras"));
    auto* gizmoModes = new QActionGroup(this);
    const std::pair<QString, GizmoMode> modes[] = {
        {tr("&Move (W)"), GizmoMode::Move}, {tr("&Rotate (E)"), GizmoMode::Rotate}, {tr("&Scale (R)"), GizmoMode::Scale}};
    QMenu* gizmo = viewMenu_->addMenu(tr("&Gizmo"));
    for (const auto& [label, mode] : modes) {
        QAction* a = gizmo->addAction(label, this, [this, mode] { viewport_->setGizmoMode(mode); });
        a->setCheckable(true);
        a->setChecked(mode == GizmoMode::Move);
        gizmoModes->addAction(a);
        toolbar->addAction(a);
    }
    // Pivot point, as Blender's: where the gizmo sits and what rotate and scale turn about.
    gizmo->addSeparator();
    auto* pivots = new QActionGroup(this);
    const std::pair<QString, GizmoPivot> pivotChoices[] = {
        {tr("Pivot: &bounds centre"), GizmoPivot::BoundsCentre}, {tr("Pivot: &origin"), GizmoPivot::Origin}};
    for (const auto& [label, pivot] : pivotChoices) {
        QAction* a = gizmo->addAction(label, this, [this, pivot] { viewport_->setGizmoPivot(pivot); });
        a->setObjectName(pivot == GizmoPivot::BoundsCentre ? "pivotBoundsCentre" : "pivotOrigin");
        a->setCheckable(true);
        a->setChecked(pivot == viewport_->gizmoPivotMode());
        pivots->addAction(a);
    }
    gizmo->addSeparator();
    QAction* snap = gizmo->addAction(tr("S&nap (0.25 m, 15°, 0.1×; Ctrl inverts while dragging)"));
    snap->setCheckable(true);
    connect(snap, &QAction::toggled, this, [this](bool on) { viewport_->snap().enabled = on; });
    toolbar->addAction(snap);
    splitAction_ = viewMenu_->addAction(tr("&A/B split view..."), this, [this](bool on) {
        if (on && !chooseSplit())
            splitAction_->setChecked(false);
        if (!on)
            splitChoice_ = {-2, -2};
        updateSplit();
    });
    splitAction_->setCheckable(true);
    splitAction_->setToolTip(tr("Render two presets side by side: A on the left half, B on the right"));
    toolbar->addAction(splitAction_);
    // GI on/off is one control: gi.method off skips every indirect pass (undoable like any parameter edit).
    giAction_ = viewMenu_->addAction(tr("&Global illumination"));
    giAction_->setObjectName("giToggle");
    giAction_->setCheckable(true);
    giAction_->setToolTip(tr("Indirect light on (gi.method = lpv) or off (direct light only, no indirect pass runs)"));
    giAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    connect(giAction_, &QAction::triggered, this, [this](bool on) {
        document_->setParameter("gi.method", scene::ParameterValue(std::string(on ? "lpv" : "off")));
    });
    connect(document_, &Document::changed, giAction_, [this](Changes c) {
        if (c.testFlag(Change::Parameters))
            giAction_->setChecked(document_->parameters().getEnum("gi.method") != "off");
    });
    giAction_->setChecked(document_->parameters().getEnum("gi.method") != "off");
    toolbar->addSeparator();
    toolbar->addAction(giAction_);
    // Viewport resolution: an editor preference (QSettings), not a project parameter.
    QMenu* resolution = viewMenu_->addMenu(tr("Viewport &resolution"));
    auto* resolutions = new QActionGroup(this);
    const double savedScale = QSettings().value("viewport/resolutionScale", 1.0).toDouble();
    for (const double scale : {1.0, 0.5, 0.25}) {
        QAction* a = resolution->addAction(tr("%1%").arg(int(scale * 100)), this, [this, scale] {
            viewport_->setResolutionScale(scale);
            QSettings().setValue("viewport/resolutionScale", scale);
        });
        a->setCheckable(true);
        a->setChecked(std::abs(scale - savedScale) < 1e-6);
        resolutions->addAction(a);
    }
    viewport_->setResolutionScale(savedScale);
    QAction* resetLayout = viewMenu_->addAction(tr("Reset &layout"), this, [this] {
        restoringLayout_ = true;
        restoreState(defaultState_);
        restoringLayout_ = false;
    });
    resetLayout->setObjectName("resetLayout");
    viewMenu_->addSeparator();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About LPV Studio"), this, [this] { AboutDialog(viewport_->renderGlInfo(), this).exec(); });

    QAction* firstGizmoAction = toolbar->actions().value(0);
    for (QAction* a : {newAction, open, saveAction, import, undoAction, redoAction})
        toolbar->insertAction(firstGizmoAction, a);
    toolbar->insertSeparator(firstGizmoAction);
}

void MainWindow::updateTitle() {
    const QString name =
        document_->path().isEmpty() ? document_->displayName() : QFileInfo(document_->path()).fileName();
    setWindowTitle(QString("%1[*] - LPV Studio").arg(name));
    setWindowModified(document_->isModified());
}

void MainWindow::showFrameStats(double gpuMs) {
    frameLabel_->setText(tr("GPU %1 ms").arg(gpuMs, 0, 'f', 2));
    frameLabel_->setToolTip(viewport_->glRenderer());
    // Queried by the render thread with each frame (its context is the one that renders).
    const auto& memory = viewport_->gpuMemory();
    if (!memory)
        memoryLabel_->setText(tr("GPU memory: not reported by this driver"));
    else if (memory->totalMiB > 0.0)
        memoryLabel_->setText(tr("GPU memory: %1 of %2 MiB used")
                                  .arg(memory->totalMiB - memory->freeMiB, 0, 'f', 0)
                                  .arg(memory->totalMiB, 0, 'f', 0));
    else
        memoryLabel_->setText(tr("GPU memory: %1 MiB free").arg(memory->freeMiB, 0, 'f', 0));
}

// ---- A/B split ----

bool MainWindow::chooseSplit() {
    QStringList names{tr("Current parameters")};
    for (const scene::ParameterPreset& p : document_->project().presets)
        names << QString::fromStdString(p.name);
    if (names.size() < 2) {
        QMessageBox::information(this, tr("A/B split view"),
                                 tr("Save at least one preset (Inspector > Save as...) to compare it with the "
                                    "current parameters."));
        return false;
    }
    bool ok = false;
    const QString a = QInputDialog::getItem(this, tr("A/B split view"), tr("Left half (A):"), names, 0, false, &ok);
    if (!ok)
        return false;
    const QString b = QInputDialog::getItem(this, tr("A/B split view"), tr("Right half (B):"), names, 1, false, &ok);
    if (!ok)
        return false;
    setSplit(int(names.indexOf(a)) - 1, int(names.indexOf(b)) - 1);
    return true;
}

void MainWindow::setSplit(int presetA, int presetB) {
    splitChoice_ = {presetA, presetB};
    splitAction_->setChecked(presetA >= -1 && presetB >= -1);
    updateSplit();
}

void MainWindow::updateSplit() {
    const auto& presets = document_->project().presets;
    auto side = [&](int index) -> std::optional<std::pair<scene::ParameterSet, QString>> {
        if (index == -1)
            return std::pair{document_->parameters(), tr("current parameters")};
        if (index >= 0 && std::size_t(index) < presets.size())
            return std::pair{presets[std::size_t(index)].parameters,
                             QString::fromStdString(presets[std::size_t(index)].name)};
        return std::nullopt;
    };
    const auto a = side(splitChoice_.first), b = side(splitChoice_.second);
    if (!a || !b) {
        splitAction_->setChecked(false);
        viewport_->setSplit(std::nullopt);
        return;
    }
    viewport_->setSplit(std::pair{a->first, b->first}, a->second, b->second);
}

// ---- Projects ----

void MainWindow::showProject(scene::Project project, const QString& path) {
    const std::size_t triangles = project.scene.triangleCount(), lights = project.scene.lights.size();
    document_->reset(std::move(project), QFileInfo::exists(path) ? path : QString());
    updateTitle();
    rebuildCamerasMenu();
    if (!path.isEmpty())
        statusBar()->showMessage(tr("%1: %2 triangles, %3 lights").arg(path).arg(triangles).arg(lights));
}

bool MainWindow::openProject(const QString& path, bool interactive) {
    auto loaded = scene::loadProject(path.toStdString());
    if (!loaded) {
        const QString message = QString::fromStdString(loaded.error().describe());
        lastOpenError_ = message;
        statusBar()->showMessage(message);
        log_->add(EventLog::Severity::Error, tr("Open"), message);
        if (interactive)
            QMessageBox::critical(this, tr("Cannot open project"), message);
        return false;
    }
    autosave_->discard(); // the project being replaced was saved or discarded by the caller
    const std::vector<std::string> warnings = loaded->loadWarnings;
    showProject(std::move(*loaded), path);
    addRecentFile(path);
    log_->add(EventLog::Severity::Info, tr("Open"), tr("opened %1").arg(path));
    for (const std::string& w : warnings)
        log_->add(EventLog::Severity::Warning, tr("Open"), QString::fromStdString(w));
    if (!warnings.empty()) {
        // Texture references led out of the project's folder: say so where
        // the user looks, and in the dialog when a person opened it.
        QStringList lines;
        for (const std::string& w : warnings)
            lines << QString::fromStdString(w);
        statusBar()->showMessage(tr("%1: %n texture reference(s) outside the project not read", "", int(lines.size()))
                                     .arg(path));
        if (interactive)
            QMessageBox::warning(this, tr("Textures not read"), lines.join("\n"));
    }
    return true;
}

bool MainWindow::openFromCommandLine(const QString& path) {
    if (openProject(path, false))
        return true;
    // Not exec(): main() has not shown the window yet, and the box belongs over it.
    auto* box = new QMessageBox(QMessageBox::Critical, tr("Cannot open project"), lastOpenError_, QMessageBox::Ok, this);
    box->setObjectName("openError");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    QTimer::singleShot(0, box, [box] { box->open(); });
    return false;
}

bool MainWindow::confirmDiscardChanges() {
    if (!document_->isModified())
        return true;
    int answer = unsavedAnswerForTests_;
    if (answer == 0)
        // The project's name, not the window's title ("untitled - LPV Studio has unsaved changes").
        answer = QMessageBox::warning(this, tr("Unsaved changes"),
                                      tr("%1 has unsaved changes. Save them?").arg(document_->displayName()),
                                      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                      QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    if (answer == QMessageBox::Discard) {
        autosave_->discard();
        return true;
    }
    return false;
}

void MainWindow::newProject() {
    if (!confirmDiscardChanges())
        return;
    showProject(untitledProject(), {});
}

void MainWindow::openDialog() {
    if (!confirmDiscardChanges())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), document_->projectDir(),
                                                      tr("LPV Studio projects (*.lpvproj)"));
    if (!path.isEmpty())
        openProject(path);
}

bool MainWindow::save() {
    if (document_->path().isEmpty())
        return saveAs();
    return saveTo(document_->path());
}

bool MainWindow::saveAs() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save project as"), document_->projectDir(),
                                                tr("LPV Studio projects (*.lpvproj)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(".lpvproj"))
        path += ".lpvproj";
    return saveTo(path);
}

bool MainWindow::saveTo(const QString& path, bool interactive) {
    autosave_->discard(); // the autosave of the old path (or of "untitled")
    document_->setEditorView(viewport_->viewCamera());
    auto saved = document_->saveAs(path);
    if (!saved) {
        const QString message = QString::fromStdString(saved.error().describe());
        statusBar()->showMessage(tr("Not saved: ") + message);
        log_->add(EventLog::Severity::Error, tr("Save"), message);
        if (interactive)
            QMessageBox::critical(this, tr("Cannot save project"), message + tr("\nThe previous file is unchanged."));
        return false;
    }
    addRecentFile(path);
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    log_->add(EventLog::Severity::Info, tr("Save"), tr("saved %1").arg(path));
    return true;
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value(kRecentKey).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(kRecentKey, files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = QSettings().value(kRecentKey).toStringList();
    for (const QString& f : files)
        recentMenu_->addAction(f, this, [this, f] {
            if (confirmDiscardChanges())
                openProject(f);
        });
    recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::rebuildCamerasMenu() {
    camerasMenu_->clear();
    const auto& cameras = document_->scene().cameras;
    for (std::size_t i = 0; i < cameras.size(); ++i)
        camerasMenu_->addAction(QString::fromStdString(cameras[i].name.empty() ? "camera " + std::to_string(i)
                                                                              : cameras[i].name),
                                this, [this, i] {
                                    if (i < document_->scene().cameras.size())
                                        viewport_->setViewCamera(document_->scene().cameras[i]);
                                });
    camerasMenu_->setEnabled(!cameras.empty());
}

void MainWindow::offerRecovery() {
    for (const RecoverableAutosave& a : Autosave::leftBehind()) {
        const QString what = a.originalPath.isEmpty() ? tr("an unsaved project") : a.originalPath;
        const auto answer = QMessageBox::question(
            this, tr("Recover unsaved changes?"),
            tr("LPV Studio did not close normally. An autosave of %1 from %2 is left.\nRecover it?")
                .arg(what, a.savedAt.toString()),
            QMessageBox::Yes | QMessageBox::No);
        if (answer != QMessageBox::Yes) {
            Autosave::remove(a);
            continue;
        }
        auto loaded = scene::loadProject(a.autosaveFile.toStdString());
        if (!loaded) {
            QMessageBox::critical(this, tr("Cannot recover"), QString::fromStdString(loaded.error().describe()));
            continue;
        }
        // The recovered project belongs to its original file but is unsaved until the user saves.
        document_->reset(std::move(*loaded), a.originalPath, true);
        Autosave::remove(a);
        return;
    }
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    // Shown (View menu, a test, --visualizer) is seen: as a tab it would
    // otherwise open behind the Inspector. Not while a saved layout is
    // restored, which keeps its own current tabs.
    if (event->type() == QEvent::Show && watched == vizDock_ && !restoringLayout_)
        QTimer::singleShot(0, vizDock_, [dock = vizDock_] { dock->raise(); });
    if (event->type() != QEvent::ShortcutOverride)
        return QMainWindow::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    const bool undo = key->matches(QKeySequence::Undo), redo = key->matches(QKeySequence::Redo);
    auto* widget = qobject_cast<QWidget*>(watched);
    if ((!undo && !redo) || !widget)
        return QMainWindow::eventFilter(watched, event);
    // Only fields of this window and its docks (floating ones too), not of a dialog.
    bool ours = false;
    for (QObject* o = widget; o && !ours; o = o->parent()) {
        if (o != widget && qobject_cast<QDialog*>(o))
            return QMainWindow::eventFilter(watched, event);
        ours = o == this;
    }
    if (!ours)
        return QMainWindow::eventFilter(watched, event);
    // A spin box commits what it shows as an edit, so its own undo (the text
    // typed) would only fight the project's history: the history wins. A text
    // field undoes its own typing first, then hands Ctrl+Z on.
    auto* spin = qobject_cast<QAbstractSpinBox*>(widget);
    if (!spin)
        spin = qobject_cast<QAbstractSpinBox*>(widget->parentWidget());
    auto* line = qobject_cast<QLineEdit*>(widget);
    const bool yield = spin || (line && !(undo ? line->isUndoAvailable() : line->isRedoAvailable()));
    if (!yield)
        return QMainWindow::eventFilter(watched, event);
    event->ignore();
    return true; // not accepted by the field: Edit > Undo / Redo take the key
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!confirmDiscardChanges()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    event->accept();
}

// ---- Import ----

void MainWindow::importDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import scene"), document_->projectDir(),
        tr("Scenes (*.4ds *.obj *.gltf *.glb *.fbx *.dae *.3ds *.ply);;All files (*)"));
    if (!path.isEmpty())
        importFile(path);
}

void MainWindow::importFile(const QString& path, bool interactive) {
    if (importRunning_)
        return;
    importRunning_ = true;
    auto* job = new ImportJob(path, this);
    auto* progress = new QProgressDialog(tr("Importing %1...").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 0, this);
    progress->setWindowModality(Qt::WindowModal);
    // Shown after 300 ms by a timer of our own: with a busy range (0, 0) and
    // no setValue() the dialog's minimumDuration never starts, and its
    // built-in 4 s timer is what used to show it.
    progress->setMinimumDuration(importProgressDelayMs_);
    auto* shower = new QTimer(progress);
    shower->setSingleShot(true);
    connect(shower, &QTimer::timeout, progress, &QWidget::show);
    shower->start(importProgressDelayMs_);
    auto* ticker = new QTimer(progress);
    QElapsedTimer clock;
    clock.start();
    connect(ticker, &QTimer::timeout, progress, [progress, path, clock] {
        progress->setLabelText(
            tr("Importing %1... %2 s").arg(QFileInfo(path).fileName()).arg(clock.elapsed() / 1000.0, 0, 'f', 1));
    });
    ticker->start(200);
    auto finish = [this, job, progress, ticker, shower] {
        importRunning_ = false;
        // Hidden before an error box opens: deleteLater waits for this event
        // loop, not the box's, and meanwhile the dialog stayed up (or its
        // timers showed it), modal, over the box and blocking its OK.
        shower->stop();
        ticker->stop();
        progress->disconnect(this);
        progress->reset(); // stops that timer
        progress->hide();
        progress->deleteLater();
        job->deleteLater();
    };
    connect(progress, &QProgressDialog::canceled, this, [this, job, finish, path] {
        job->cancel();
        statusBar()->showMessage(tr("Import of %1 cancelled; the project is unchanged").arg(path), 8000);
        log_->add(EventLog::Severity::Info, tr("Import"), tr("%1: cancelled; the project is unchanged").arg(path));
        finish();
    });
    connect(job, &ImportJob::failed, this, [this, finish, interactive](const QString& message) {
        finish();
        statusBar()->showMessage(tr("Import failed: ") + message);
        log_->add(EventLog::Severity::Error, tr("Import"), message);
        if (interactive)
            QMessageBox::critical(this, tr("Import failed"), message);
    });
    connect(job, &ImportJob::imported, this,
            [this, finish, path](std::shared_ptr<ImportedScene> imported) {
                finish();
                importers::ImportResult* result = &imported->result;
                const auto& st = result->stats;
                const bool addSun = document_->scene().lights.empty() && result->scene.lights.empty();
                document_->editScene(tr("Import %1").arg(QFileInfo(path).fileName()), Change::Structure | Change::Materials |
                                         Change::Lights | Change::Cameras | Change::CameraPaths,
                                     [&](scene::Scene& s) {
                                         scene::appendScene(s, std::move(result->scene));
                                         // Like `lpv import`: an unlit scene would render black, so
                                         // it gets the sun that lights the most of its first view.
                                         if (addSun && imported->sun)
                                             s.lights.push_back(imported->sun->light);
                                     });
                // Seen as `lpv import` and `lpv render` see it: its own camera, or from
                // inside an enclosed scene (Sponza), not framed from outside.
                viewport_->setViewCamera(imported->view);
                statusBar()->showMessage(tr("Imported %1: %2 objects, %3 triangles, %4 materials, textures %5 found / "
                                            "%6 missing, %7 warnings, %8 s")
                                             .arg(path)
                                             .arg(st.objects)
                                             .arg(st.triangles)
                                             .arg(st.materials)
                                             .arg(st.texturesFound)
                                             .arg(st.texturesMissing)
                                             .arg(result->warnings.size())
                                             .arg(st.seconds, 0, 'f', 2));
                log_->add(EventLog::Severity::Info, tr("Import"), statusBar()->currentMessage());
                for (const std::string& w : result->warnings)
                    log_->add(EventLog::Severity::Warning, tr("Import"), QString::fromStdString(w));
            });
    job->start();
}

} // namespace lpv::editor
