#pragma once
// Named parameter presets of the project (scene::Project::presets): a combo
// box of them with Save current as..., Apply and Delete. Like the inspector
// it shows what it is given and reports requests; whoever holds the project
// turns them into undoable commands and calls setPresets() with the result.
#include "lpv/scene/Project.h"

#include <QInputDialog>
#include <QPointer>
#include <QWidget>

#include <vector>

class QComboBox;
class QToolButton;

namespace lpv::editor {

class PresetBar : public QWidget {
    Q_OBJECT
  public:
    explicit PresetBar(QWidget* parent = nullptr);

    // Lists `presets` in their order. The selection stays on the preset of
    // the same name, or moves to the one just saved under a new name.
    void setPresets(const std::vector<scene::ParameterPreset>& presets);
    // The selected preset's index in the list given to setPresets(), -1 if there is none.
    int currentIndex() const;
    void setCurrentIndex(int index);

    QComboBox* presetCombo() const { return combo_; }
    QToolButton* saveButton() const { return save_; }
    QToolButton* applyButton() const { return apply_; }
    QToolButton* deleteButton() const { return delete_; }
    // The name dialog while it is open (the Save button opens it), else nullptr.
    QInputDialog* saveDialog() const { return dialog_; }

  signals:
    // "Save current as preset...": store the current parameters under `name`
    // (trimmed, never empty). If a preset of that name exists the receiver
    // replaces its parameters; otherwise it appends a new preset.
    void presetSaveRequested(const QString& name);
    // Make preset `index`'s values the current parameters.
    void presetApplyRequested(int index);
    // Remove preset `index` (undoable, so no confirmation is asked).
    void presetDeleteRequested(int index);

  private:
    void openSaveDialog();
    void updateButtons();
    QString unusedName() const;

    QComboBox* combo_ = nullptr;
    QToolButton* save_ = nullptr;
    QToolButton* apply_ = nullptr;
    QToolButton* delete_ = nullptr;
    QPointer<QInputDialog> dialog_;
    QStringList names_;
    QString justSaved_;
};

} // namespace lpv::editor
