#pragma once
// The input for one registry parameter, chosen from its type and range:
// a check box (bool), a spin box (int, with a slider for short ranges), a
// double spin box with a linear or logarithmic slider (float), a combo box
// (enum); plus a reset-to-default button. The ParameterInspector lays these
// out; they hold a copy of the value they show, never the project's.
#include "lpv/scene/ParameterRegistry.h"

#include <QMetaType>
#include <QString>
#include <QWidget>

class QAbstractSlider;
class QHBoxLayout;
class QToolButton;

// So a ParameterValue travels in signals, QVariant and QSignalSpy.
Q_DECLARE_METATYPE(lpv::scene::ParameterValue)

namespace lpv::editor {

class ParameterEditor : public QWidget {
    Q_OBJECT
  public:
    // The editor for `info`'s type; `info` must outlive it (registry entries do).
    static ParameterEditor* create(const scene::ParameterInfo& info, QWidget* parent = nullptr);

    const scene::ParameterInfo& info() const { return info_; }
    QString key() const { return QString::fromStdString(info_.key); }

    // The value shown, in the registry's type. A float the user entered is
    // what its spin box shows (rounded to its decimals); one set by setValue()
    // is kept exactly.
    virtual scene::ParameterValue value() const = 0;
    // Shows `value` without emitting edited(). While the user drags this
    // editor's slider the slider stays under the mouse; the rest updates.
    void setValue(const scene::ParameterValue& value);
    bool isDefault() const { return value() == info_.defaultValue; }

    // The widget a user types into or clicks: QCheckBox, QSpinBox,
    // QDoubleSpinBox or QComboBox.
    virtual QWidget* input() const = 0;
    // The slider beside the spin box, or nullptr where there is none.
    virtual QAbstractSlider* slider() const { return nullptr; }
    QToolButton* resetButton() const { return reset_; }

  signals:
    // The user changed the value: once per click, arrow step, typed value
    // (on Enter or leaving the field) or slider position while dragging.
    void edited(const lpv::scene::ParameterValue& value);
    // The reset button was clicked; the editor already shows the default.
    void resetRequested();
    // After any change of the value shown, by the user or by setValue().
    void valueShown();

  protected:
    ParameterEditor(const scene::ParameterInfo& info, QWidget* parent);

    // Shows a value of this editor's type; the caller has blocked the widgets' signals.
    virtual void display(const scene::ParameterValue& value) = 0;
    // Subclasses call this from their widgets' change signals.
    void userEdited();
    // The row the subclass fills; the reset button is appended by finishLayout().
    QHBoxLayout* row() const { return row_; }
    void finishLayout();
    // Wheel events reach `w` only once it has focus, so scrolling the
    // inspector does not change values under the mouse.
    void guardWheel(QWidget* w);
    // A number box (QSpinBox or QDoubleSpinBox) as every numeric editor shows
    // it: its unit, right-aligned, after its slider or pushed to the right.
    template <class SpinBox>
    void placeNumberBox(SpinBox* spin, const QString& unit, bool afterSlider);

  private:
    void resetClicked();
    void updateResetButton();

    const scene::ParameterInfo& info_;
    QHBoxLayout* row_ = nullptr;
    QToolButton* reset_ = nullptr;
};

// "lpv.propagationSteps" -> "Propagation steps".
QString parameterLabel(const scene::ParameterInfo& info);
// The unit as shown ("m^2" -> "m²"); empty for none.
QString parameterUnit(const scene::ParameterInfo& info);
// "8 steps", "0.25 m", "true", "computeGather".
QString formatParameterValue(const scene::ParameterInfo& info, const scene::ParameterValue& value);
// Rich-text tooltip: label, key, description, default, range or choices, and the passes a change re-runs.
QString parameterToolTip(const scene::ParameterInfo& info);
// Decimals a float's spin box shows: enough for its step, bounds and default.
int parameterDecimals(const scene::ParameterInfo& info);

} // namespace lpv::editor
