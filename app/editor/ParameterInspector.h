#pragma once
// The parameter inspector (issue #7, item 5): one editor per registry
// parameter, generated from scene::ParameterRegistry, in collapsible groups
// (LPV, RSM, Shadows, Effects, Output, Radiosity, Reference), with a search
// field. It shows values and reports edits; it does not own the values:
// whoever holds the project applies parameterEdited / parameterResetRequested
// (as undoable commands) and calls setParameters() or setParameter() with
// the result, also after undo and redo.
#include "ParameterEditor.h"

#include "lpv/scene/ParameterRegistry.h"

#include <QHash>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

class QFormLayout;
class QLabel;
class QLineEdit;
class QToolButton;

namespace lpv::editor {

class ParameterInspector : public QWidget {
    Q_OBJECT
  public:
    // Builds editors for every parameter of `registry`, showing the defaults.
    explicit ParameterInspector(QWidget* parent = nullptr, const scene::ParameterRegistry& registry =
                                                               scene::ParameterRegistry::instance());

    // Shows every value of `values` (defaults for the keys it does not set).
    // Emits no parameterEdited; a slider the user is dragging stays where it is.
    void setParameters(const scene::ParameterSet& values);
    // The same for one key (after an undo or redo of one edit). Unknown keys are ignored.
    void setParameter(const QString& key, const scene::ParameterValue& value);

    // The widget a user edits `key` with (QCheckBox, QSpinBox, QDoubleSpinBox
    // or QComboBox), or nullptr for a key the registry does not declare.
    QWidget* editorFor(const QString& key) const;
    // The whole editor of `key`: value(), slider(), resetButton(); nullptr if unknown.
    ParameterEditor* parameterEditor(const QString& key) const;
    // The label in front of the editor.
    QLabel* labelFor(const QString& key) const;

    // The search field. Matching is case-insensitive; every word typed must
    // occur in the key, the label, the description or the group.
    QLineEdit* searchField() const { return search_; }
    void setFilter(const QString& text);
    // Whether `key` passes the current filter (its group may still be collapsed).
    bool matchesFilter(const QString& key) const;

    // Group names in display order.
    QStringList groups() const;
    QToolButton* groupHeader(const QString& group) const;
    void setGroupExpanded(const QString& group, bool expanded);
    bool isGroupExpanded(const QString& group) const;

  signals:
    // The user changed `key` to `value` (already in range and of the
    // registry's type). A slider drag emits on every step; consecutive edits
    // of one key are meant to merge into one undo step.
    void parameterEdited(const QString& key, const lpv::scene::ParameterValue& value);
    // The user clicked `key`'s reset button: drop its override so it reads
    // as the default again. The editor already shows the default; no
    // parameterEdited is emitted for a reset.
    void parameterResetRequested(const QString& key);

  private:
    struct Section {
        QString name;
        QToolButton* header = nullptr;
        QWidget* body = nullptr;
        QFormLayout* form = nullptr;
        bool expanded = true;
        int total = 0;
        int matching = 0;
    };
    struct Entry {
        const scene::ParameterInfo* info = nullptr;
        ParameterEditor* editor = nullptr;
        QLabel* label = nullptr;
        std::size_t section = 0;
        int row = 0;
        QString haystack; // lower-case key, label, description and group, for the filter
        bool matches = true;
    };

    std::size_t sectionFor(const QString& group, QWidget* container);
    void addEntry(const scene::ParameterInfo& info);
    void alignColumns();
    void applyFilter();
    void updateSection(Section& section);
    void updateLabel(const Entry& entry);
    const Entry* find(const QString& key) const;
    Section* findSection(const QString& group);
    const Section* findSection(const QString& group) const;

    QLineEdit* search_ = nullptr;
    QLabel* noMatches_ = nullptr;
    QWidget* sectionsContainer_ = nullptr;
    std::vector<Section> sections_;
    std::vector<Entry> entries_;
    QHash<QString, std::size_t> byKey_;
    QStringList filterWords_;
};

} // namespace lpv::editor
