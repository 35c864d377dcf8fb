#include "ParameterEditor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lpv::editor {

template <class SpinBox>
void ParameterEditor::placeNumberBox(SpinBox* spin, const QString& unit, bool afterSlider) {
    if (!unit.isEmpty())
        spin->setSuffix(" " + unit);
    // Typed numbers take effect on Enter: "2048" must not rebuild the shadow
    // maps at 2, 20 and 204 on the way. Arrows, wheel and slider act at once.
    spin->setKeyboardTracking(false);
    spin->setAlignment(Qt::AlignRight);
    guardWheel(spin);
    if (!afterSlider)
        row()->addStretch(1);
    row()->addWidget(spin);
}

namespace {

using scene::ParameterInfo;
using scene::ParameterType;
using scene::ParameterValue;

double toDouble(const ParameterValue& v) {
    if (const auto* d = std::get_if<double>(&v))
        return *d;
    if (const auto* i = std::get_if<int>(&v))
        return *i;
    assert(false && "a numeric parameter got a non-numeric value");
    return 0.0;
}

// The fewest decimals (at most 6) that show `v` exactly.
int decimalsOf(double v) {
    for (int d = 0; d < 6; ++d) {
        const double scale = std::pow(10.0, d);
        if (std::abs(std::round(v * scale) / scale - v) <= 1e-9 * std::max(1.0, std::abs(v)))
            return d;
    }
    return 6;
}

// Ranges spanning three decades or more get a logarithmic slider and a step
// that follows the value: lpv.cellSize runs from 1 mm to 100 m.
bool isLogScale(const ParameterInfo& info) {
    return info.minValue > 0.0 && info.maxValue / info.minValue >= 1000.0;
}

// A 1-2-5 step near a hundredth of the range.
double linearStep(const ParameterInfo& info) {
    const double raw = (info.maxValue - info.minValue) / 100.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / power;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * power;
}

// Integer ranges up to this many values get a slider (lpv.propagationSteps 0..64);
// beyond it (reference.samplesPerPixel up to 65536) a slider step is too coarse.
constexpr int kMaxIntSliderRange = 256;
// Positions of a float slider.
constexpr int kFloatSliderSteps = 1000;

class BoolEditor final : public ParameterEditor {
  public:
    BoolEditor(const ParameterInfo& info, QWidget* parent) : ParameterEditor(info, parent) {
        check_ = new QCheckBox(this);
        row()->addWidget(check_);
        row()->addStretch(1);
        finishLayout();
        connect(check_, &QCheckBox::toggled, this, [this] { userEdited(); });
    }
    ParameterValue value() const override { return check_->isChecked(); }
    QWidget* input() const override { return check_; }

  protected:
    void display(const ParameterValue& v) override {
        assert(std::holds_alternative<bool>(v));
        check_->setChecked(std::get<bool>(v));
    }

  private:
    QCheckBox* check_ = nullptr;
};

class IntEditor final : public ParameterEditor {
  public:
    IntEditor(const ParameterInfo& info, QWidget* parent) : ParameterEditor(info, parent) {
        const int lo = static_cast<int>(info.minValue);
        const int hi = static_cast<int>(info.maxValue);
        if (hi - lo <= kMaxIntSliderRange) {
            slider_ = new QSlider(Qt::Horizontal, this);
            slider_->setRange(lo, hi);
            slider_->setPageStep(std::max(1, (hi - lo) / 8));
            guardWheel(slider_);
            row()->addWidget(slider_, 1);
        }
        spin_ = new QSpinBox(this);
        spin_->setRange(lo, hi);
        placeNumberBox(spin_, parameterUnit(info), slider_ != nullptr);
        finishLayout();

        connect(spin_, &QSpinBox::valueChanged, this, [this](int v) {
            if (slider_) {
                const QSignalBlocker block(slider_);
                slider_->setValue(v);
            }
            userEdited();
        });
        if (slider_)
            connect(slider_, &QSlider::valueChanged, this, [this](int v) {
                const QSignalBlocker block(spin_);
                spin_->setValue(v);
                userEdited();
            });
    }
    ParameterValue value() const override { return spin_->value(); }
    QWidget* input() const override { return spin_; }
    QAbstractSlider* slider() const override { return slider_; }

  protected:
    void display(const ParameterValue& v) override {
        const int i = static_cast<int>(std::lround(toDouble(v)));
        spin_->setValue(i);
        if (slider_ && !slider_->isSliderDown())
            slider_->setValue(i);
    }

  private:
    QSpinBox* spin_ = nullptr;
    QSlider* slider_ = nullptr;
};

class FloatEditor final : public ParameterEditor {
  public:
    FloatEditor(const ParameterInfo& info, QWidget* parent)
        : ParameterEditor(info, parent), log_(isLogScale(info)) {
        if (std::isfinite(info.minValue) && std::isfinite(info.maxValue)) {
            slider_ = new QSlider(Qt::Horizontal, this);
            slider_->setRange(0, kFloatSliderSteps);
            slider_->setPageStep(kFloatSliderSteps / 10);
            guardWheel(slider_);
            row()->addWidget(slider_, 1);
        }
        spin_ = new QDoubleSpinBox(this);
        spin_->setDecimals(parameterDecimals(info));
        spin_->setRange(info.minValue, info.maxValue);
        if (log_)
            spin_->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        else
            spin_->setSingleStep(linearStep(info));
        placeNumberBox(spin_, parameterUnit(info), slider_ != nullptr);
        // A word besides numbers (lpv.cellSize's "auto": the renderer fits
        // it): a check box; while it is on the number is not used.
        if (!info.enumValues.empty()) {
            word_ = new QCheckBox(QString::fromStdString(info.enumValues.front()), this);
            word_->setToolTip(tr("%1: chosen by the renderer; off: the number beside it")
                                  .arg(QString::fromStdString(info.enumValues.front())));
            row()->addWidget(word_);
            connect(word_, &QCheckBox::toggled, this, [this](bool on) {
                showWord(on);
                userEdited();
            });
        }
        // The number a word gives way to: the middle of the range (log or linear).
        number_ = log_ ? std::sqrt(info.minValue * info.maxValue) : 0.5 * (info.minValue + info.maxValue);
        finishLayout();

        connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
            if (slider_) {
                const QSignalBlocker block(slider_);
                slider_->setValue(toSlider(v));
            }
            number_ = v;
            userEdited();
        });
        if (slider_)
            connect(slider_, &QSlider::valueChanged, this, [this](int position) {
                // The spin box rounds to its decimals; what it shows is what is emitted.
                const QSignalBlocker block(spin_);
                spin_->setValue(fromSlider(position));
                number_ = spin_->value();
                userEdited();
            });
    }
    // Exactly as set: a project value with more digits than the spin box
    // shows is not rounded until the user edits it.
    ParameterValue value() const override {
        if (word_ && word_->isChecked())
            return info().enumValues.front();
        return number_;
    }
    QWidget* input() const override { return spin_; }
    QAbstractSlider* slider() const override { return slider_; }

  protected:
    void display(const ParameterValue& v) override {
        if (std::holds_alternative<std::string>(v)) {
            if (word_) {
                const QSignalBlocker block(word_);
                word_->setChecked(true);
                showWord(true);
            }
            return;
        }
        if (word_) {
            const QSignalBlocker block(word_);
            word_->setChecked(false);
            showWord(false);
        }
        const double d = toDouble(v);
        number_ = d;
        const QSignalBlocker block(spin_);
        spin_->setValue(d);
        if (slider_ && !slider_->isSliderDown())
            slider_->setValue(toSlider(d));
    }

  private:
    double fromSlider(int position) const {
        const double t = static_cast<double>(position) / kFloatSliderSteps;
        const ParameterInfo& p = info();
        return log_ ? p.minValue * std::pow(p.maxValue / p.minValue, t)
                    : p.minValue + (p.maxValue - p.minValue) * t;
    }
    int toSlider(double v) const {
        const ParameterInfo& p = info();
        const double t = log_ ? std::log(v / p.minValue) / std::log(p.maxValue / p.minValue)
                              : (v - p.minValue) / (p.maxValue - p.minValue);
        return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kFloatSliderSteps));
    }

    void showWord(bool on) {
        spin_->setEnabled(!on);
        if (slider_)
            slider_->setEnabled(!on);
        // While the word is on, the greyed box shows it: Qt shows the special
        // text at the minimum, which would otherwise read "0.000001 m" (issue #46).
        spin_->setSpecialValueText(on ? word_->text() : QString());
        if (on) {
            const QSignalBlocker block(spin_);
            spin_->setValue(spin_->minimum());
        } else {
            const QSignalBlocker block(spin_);
            spin_->setValue(number_);
            if (slider_) {
                const QSignalBlocker blockSlider(slider_);
                slider_->setValue(toSlider(number_));
            }
        }
    }

    bool log_ = false;
    double number_ = 0.0; // the number, kept while a word is checked
    QDoubleSpinBox* spin_ = nullptr;
    QSlider* slider_ = nullptr;
    QCheckBox* word_ = nullptr;
};

class EnumEditor final : public ParameterEditor {
  public:
    EnumEditor(const ParameterInfo& info, QWidget* parent) : ParameterEditor(info, parent) {
        combo_ = new QComboBox(this);
        // The names as `lpv --set` and the project file spell them.
        for (const std::string& name : info.enumValues)
            combo_->addItem(QString::fromStdString(name));
        guardWheel(combo_);
        row()->addWidget(combo_, 1);
        finishLayout();
        connect(combo_, &QComboBox::currentIndexChanged, this, [this] { userEdited(); });
    }
    ParameterValue value() const override {
        const int i = combo_->currentIndex();
        return i >= 0 ? info().enumValues[static_cast<std::size_t>(i)] : std::string();
    }
    QWidget* input() const override { return combo_; }

  protected:
    void display(const ParameterValue& v) override {
        assert(std::holds_alternative<std::string>(v));
        const auto& names = info().enumValues;
        const auto it = std::find(names.begin(), names.end(), std::get<std::string>(v));
        combo_->setCurrentIndex(it == names.end() ? -1 : static_cast<int>(it - names.begin()));
    }

  private:
    QComboBox* combo_ = nullptr;
};

// See ParameterEditor::guardWheel.
class WheelGuard final : public QObject {
  public:
    using QObject::QObject;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Wheel) {
            const auto* w = qobject_cast<QWidget*>(watched);
            if (w && !w->hasFocus()) {
                // Filtered but not accepted: QApplication passes it on to the
                // parents, so the scroll area scrolls.
                event->ignore();
                return true;
            }
        }
        return false;
    }
};

QString words(const QString& camelCase) {
    QStringList out;
    QString word;
    for (const QChar c : camelCase) {
        if (c.isUpper() && !word.isEmpty()) {
            out << word;
            word.clear();
        }
        word += c.toLower();
    }
    if (!word.isEmpty())
        out << word;
    static const QStringList kAcronyms{"gv", "lpv", "rsm", "sh", "vpl"};
    for (QString& w : out)
        if (kAcronyms.contains(w))
            w = w.toUpper();
    QString text = out.join(' ');
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}

} // namespace

ParameterEditor* ParameterEditor::create(const ParameterInfo& info, QWidget* parent) {
    ParameterEditor* editor = nullptr;
    switch (info.type) {
    case ParameterType::Bool:
        editor = new BoolEditor(info, parent);
        break;
    case ParameterType::Int:
        editor = new IntEditor(info, parent);
        break;
    case ParameterType::Float:
        editor = new FloatEditor(info, parent);
        break;
    case ParameterType::Enum:
        editor = new EnumEditor(info, parent);
        break;
    }
    assert(editor);
    editor->setValue(info.defaultValue);
    return editor;
}

ParameterEditor::ParameterEditor(const ParameterInfo& info, QWidget* parent) : QWidget(parent), info_(info) {
    row_ = new QHBoxLayout(this);
    row_->setContentsMargins(0, 0, 0, 0);
    setObjectName(key());
}

void ParameterEditor::finishLayout() {
    reset_ = new QToolButton(this);
    reset_->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    reset_->setAutoRaise(true);
    reset_->setFocusPolicy(Qt::TabFocus);
    reset_->setToolTip(tr("Reset to the default, %1").arg(formatParameterValue(info_, info_.defaultValue)));
    reset_->setAccessibleName(tr("Reset %1").arg(parameterLabel(info_)));
    row_->addWidget(reset_);
    connect(reset_, &QToolButton::clicked, this, &ParameterEditor::resetClicked);

    const QString tip = parameterToolTip(info_);
    input()->setToolTip(tip);
    input()->setAccessibleName(parameterLabel(info_));
    if (slider())
        slider()->setToolTip(tip);
}

void ParameterEditor::guardWheel(QWidget* w) {
    w->setFocusPolicy(Qt::StrongFocus);
    w->installEventFilter(new WheelGuard(w));
}

void ParameterEditor::setValue(const ParameterValue& v) {
    {
        const QSignalBlocker blockInput(input());
        const QSignalBlocker blockSlider(slider());
        display(v);
    }
    updateResetButton();
    emit valueShown();
}

void ParameterEditor::userEdited() {
    updateResetButton();
    emit valueShown();
    emit edited(value());
}

void ParameterEditor::resetClicked() {
    setValue(info_.defaultValue);
    emit resetRequested();
}

void ParameterEditor::updateResetButton() {
    reset_->setEnabled(!isDefault());
}

QString parameterLabel(const ParameterInfo& info) {
    const QString key = QString::fromStdString(info.key);
    const qsizetype dot = key.indexOf('.');
    return words(dot >= 0 ? key.mid(dot + 1) : key);
}

QString parameterUnit(const ParameterInfo& info) {
    QString unit = QString::fromStdString(info.unit);
    unit.replace("^2", QString::fromUtf8("\u00b2")).replace("^3", QString::fromUtf8("\u00b3"));
    return unit;
}

QString formatParameterValue(const ParameterInfo& info, const ParameterValue& v) {
    QString text;
    switch (info.type) {
    case ParameterType::Bool:
        return std::get<bool>(v) ? QStringLiteral("on") : QStringLiteral("off");
    case ParameterType::Enum:
        return QString::fromStdString(std::get<std::string>(v));
    case ParameterType::Int:
        text = QString::number(std::lround(toDouble(v)));
        break;
    case ParameterType::Float:
        if (const auto* word = std::get_if<std::string>(&v))
            return QString::fromStdString(*word); // "auto"
        text = QString::number(toDouble(v), 'g', 6);
        break;
    }
    const QString unit = parameterUnit(info);
    return unit.isEmpty() ? text : text + " " + unit;
}

QString parameterToolTip(const ParameterInfo& info) {
    const auto esc = [](const QString& s) { return s.toHtmlEscaped(); };
    QString tip = QString("<p><b>%1</b> &nbsp;<code>%2</code></p><p>%3</p>")
                      .arg(esc(parameterLabel(info)), esc(QString::fromStdString(info.key)),
                           esc(QString::fromStdString(info.description)));
    tip += "<p>" + QObject::tr("Default: %1").arg(esc(formatParameterValue(info, info.defaultValue)));
    if (info.type == ParameterType::Int || info.type == ParameterType::Float) {
        tip += "<br>" +
               QObject::tr("Range: %1 to %2")
                   .arg(esc(formatParameterValue(info, info.type == ParameterType::Int
                                                           ? ParameterValue(static_cast<int>(info.minValue))
                                                           : ParameterValue(info.minValue))),
                        esc(formatParameterValue(info, info.type == ParameterType::Int
                                                           ? ParameterValue(static_cast<int>(info.maxValue))
                                                           : ParameterValue(info.maxValue))));
    } else if (info.type == ParameterType::Enum) {
        QStringList names;
        for (const std::string& n : info.enumValues)
            names << QString::fromStdString(n);
        tip += "<br>" + QObject::tr("Choices: %1").arg(esc(names.join(", ")));
    }
    QStringList passes;
    for (const std::string& p : scene::passNames(info.invalidates))
        passes << QString::fromStdString(p);
    if (!passes.isEmpty())
        tip += "<br>" + QObject::tr("Re-runs: %1").arg(esc(passes.join(", ")));
    return tip + "</p>";
}

int parameterDecimals(const ParameterInfo& info) {
    const bool numericDefault = !std::holds_alternative<std::string>(info.defaultValue); // not "auto"
    int d = std::max({2, decimalsOf(info.minValue), decimalsOf(info.maxValue),
                      numericDefault ? decimalsOf(toDouble(info.defaultValue)) : 0});
    if (!isLogScale(info))
        d = std::max(d, decimalsOf(linearStep(info)));
    return std::min(d, 6);
}

} // namespace lpv::editor
