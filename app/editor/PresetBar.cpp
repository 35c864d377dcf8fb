#include "PresetBar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QSignalBlocker>
#include <QToolButton>

namespace lpv::editor {
namespace {

// The preset's values, one per line, for the combo's item tooltip.
QString describe(const scene::ParameterPreset& preset) {
    const auto& overrides = preset.parameters.overrides();
    if (overrides.empty())
        return QObject::tr("All parameters at their defaults");
    QStringList lines;
    for (const auto& [key, value] : overrides)
        lines << QString::fromStdString(key + " = " + scene::formatValue(value));
    return lines.join('\n');
}

} // namespace

PresetBar::PresetBar(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    combo_ = new QComboBox(this);
    combo_->setObjectName("presetCombo");
    combo_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    combo_->setPlaceholderText(tr("No presets"));
    combo_->setToolTip(tr("Named parameter presets saved in the project"));
    layout->addWidget(combo_, 1);

    const auto button = [&](const QString& text, const QString& tip) {
        auto* b = new QToolButton(this);
        b->setText(text);
        b->setToolTip(tip);
        layout->addWidget(b);
        return b;
    };
    save_ = button(tr("Save as..."),
                   tr("Save the current parameters as a preset (a new one, or replace one by name)"));
    apply_ = button(tr("Apply"), tr("Make the selected preset's values the current parameters"));
    delete_ = button(tr("Delete"), tr("Delete the selected preset"));

    connect(save_, &QToolButton::clicked, this, &PresetBar::openSaveDialog);
    connect(apply_, &QToolButton::clicked, this, [this] {
        if (currentIndex() >= 0)
            emit presetApplyRequested(currentIndex());
    });
    connect(delete_, &QToolButton::clicked, this, [this] {
        if (currentIndex() >= 0)
            emit presetDeleteRequested(currentIndex());
    });
    connect(combo_, &QComboBox::currentIndexChanged, this, &PresetBar::updateButtons);
    updateButtons();
}

void PresetBar::setPresets(const std::vector<scene::ParameterPreset>& presets) {
    const QString selected = !justSaved_.isEmpty() ? justSaved_ : combo_->currentText();
    justSaved_.clear();
    names_.clear();
    {
        const QSignalBlocker block(combo_);
        combo_->clear();
        for (const scene::ParameterPreset& p : presets) {
            const QString name = QString::fromStdString(p.name);
            names_ << name;
            combo_->addItem(name);
            combo_->setItemData(combo_->count() - 1, describe(p), Qt::ToolTipRole);
        }
        const qsizetype keep = names_.indexOf(selected);
        combo_->setCurrentIndex(keep >= 0 ? static_cast<int>(keep) : (names_.isEmpty() ? -1 : 0));
    }
    updateButtons();
}

int PresetBar::currentIndex() const {
    return combo_->currentIndex();
}

void PresetBar::setCurrentIndex(int index) {
    combo_->setCurrentIndex(index);
}

void PresetBar::openSaveDialog() {
    if (dialog_)
        return;
    auto* dialog = new QInputDialog(this);
    dialog_ = dialog;
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Save Preset"));
    dialog->setLabelText(tr("Save the current parameters as the preset named:"));
    if (!names_.isEmpty()) {
        // Picking an existing name replaces that preset.
        dialog->setComboBoxItems(names_);
        dialog->setComboBoxEditable(true);
    }
    dialog->setTextValue(unusedName());
    connect(dialog, &QInputDialog::textValueSelected, this, [this](const QString& text) {
        const QString name = text.trimmed();
        if (name.isEmpty())
            return;
        justSaved_ = name;
        emit presetSaveRequested(name);
    });
    // Window-modal and non-blocking: the editor keeps drawing behind it.
    dialog->open();
}

void PresetBar::updateButtons() {
    const bool selected = currentIndex() >= 0;
    apply_->setEnabled(selected);
    delete_->setEnabled(selected);
    combo_->setEnabled(!names_.isEmpty());
}

QString PresetBar::unusedName() const {
    for (qsizetype i = names_.size() + 1;; ++i) {
        const QString name = tr("Preset %1").arg(i);
        if (!names_.contains(name))
            return name;
    }
}

} // namespace lpv::editor
