#pragma once
// Camera paths in the editor: choose or create a path, its keys in a table
// (time, position, rotation, field of view), add a key from the current view,
// a timeline that scrubs and plays the path in real time through the
// viewport's camera, import/export as JSON or CSV, and video export. Every
// edit is an undo command through the Document.
#include "Document.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;

namespace lpv::editor {

class Viewport;

class CameraPathPanel : public QWidget {
    Q_OBJECT
public:
    CameraPathPanel(Document* document, Viewport* viewport, QWidget* parent = nullptr);

    // The path shown (-1 = none); the viewport draws it.
    int currentPath() const { return current_; }
    void setCurrentPath(int index);
    double time() const { return time_; }
    bool playing() const { return playTimer_.isActive(); }
    QTableWidget* keyTable() const { return table_; }

public slots:
    void newPath();
    void deletePath();
    // Adds a key at the current time from the viewport's camera (replacing a key at that same time).
    void addKeyFromView();
    void deleteSelectedKey();
    void setKeyToView();
    // Moves the timeline; the viewport's camera follows the path.
    void setTime(double seconds);
    void play();
    void pause();
    void exportPath();
    void importPath();
    void exportVideo();

signals:
    void currentPathChanged(int index);
    // A video export ended: its output and the error ("" done, "cancelled").
    void videoExportFinished(const QString& output, const QString& error);

private:
    void refresh();
    void onCellChanged(int row, int column);
    void editPath(const QString& text, const std::function<void(scene::CameraPath&)>& edit);
    double duration() const;
    const scene::CameraPath* path() const;

    Document* document_;
    Viewport* viewport_;
    int current_ = -1;
    double time_ = 0.0;
    QComboBox* pathCombo_;
    QCheckBox* closed_;
    QCheckBox* constantSpeed_;
    QTableWidget* table_;
    QSlider* timeline_;
    QDoubleSpinBox* timeBox_;
    QLabel* durationLabel_;
    QPushButton* playButton_;
    QTimer playTimer_;
    QElapsedTimer playClock_;
    double playStartTime_ = 0.0;
    bool updating_ = false;
};

} // namespace lpv::editor
